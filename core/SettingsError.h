#pragma once

#include "MessageText.h"

#include <QString>

#include <stdexcept>

namespace shadowlab {

// A bad setting: which key, and a message that says what is allowed. The key is quoted
// shortened and both are escaped (see displayText()), so a NUL or an escape sequence from
// the input can neither cut the message nor reach the terminal.
class SettingsError : public std::runtime_error {
public:
    SettingsError(QString key, const QString& message)
        : std::runtime_error(escapeControlCharacters(key.isEmpty() ? message : displayText(key) + QStringLiteral(": ") + message).toStdString()),
          m_key(std::move(key)) {}

    const QString& key() const { return m_key; }

private:
    QString m_key;
};

} // namespace shadowlab
