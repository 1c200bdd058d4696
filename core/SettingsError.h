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

    // The same error found within `context` (a file, a sweep entry): the context, then the key
    // and the message, the key said once.
    SettingsError within(const QString& context) const
    {
        return SettingsError(Whole{}, m_key, escapeControlCharacters(context).toStdString() + ": " + what());
    }

private:
    struct Whole {};    // the text as it stands: the key already in it
    SettingsError(Whole, QString key, const std::string& text) : std::runtime_error(text), m_key(std::move(key)) {}

    QString m_key;
};

} // namespace shadowlab
