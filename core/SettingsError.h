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

    // A key that is no setting at all: each front end says where the list of keys is (the
    // command line's `shadowlab settings`, the window's dock).
    static SettingsError unknownKey(QString key, const QString& message)
    {
        SettingsError e(std::move(key), message);
        e.m_unknownKey = true;
        return e;
    }

    const QString& key() const { return m_key; }
    bool isUnknownKey() const { return m_unknownKey; }

    // The same error found within `context` (a file, a sweep entry): the context, then the key
    // and the message, the key said once.
    SettingsError within(const QString& context) const
    {
        SettingsError e(Whole{}, m_key, escapeControlCharacters(context).toStdString() + ": " + what());
        e.m_unknownKey = m_unknownKey;
        return e;
    }

private:
    struct Whole {};    // the text as it stands: the key already in it
    SettingsError(Whole, QString key, const std::string& text) : std::runtime_error(text), m_key(std::move(key)) {}

    QString m_key;
    bool m_unknownKey = false;
};

} // namespace shadowlab
