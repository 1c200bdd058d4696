#pragma once

#include <QString>

#include <stdexcept>

namespace shadowlab {

// A bad setting: which key, and a message that says what is allowed.
class SettingsError : public std::runtime_error {
public:
    SettingsError(QString key, const QString& message)
        : std::runtime_error((key.isEmpty() ? message : key + QStringLiteral(": ") + message).toStdString()),
          m_key(std::move(key)) {}

    const QString& key() const { return m_key; }

private:
    QString m_key;
};

} // namespace shadowlab
