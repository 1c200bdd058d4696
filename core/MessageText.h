#pragma once

#include <QString>

namespace shadowlab {

// Text from input (a value, a key, a path) made safe to quote in a message: control
// characters (NUL included) written as \n, \t, \x01, ..., and anything longer than
// `maxLength` characters cut, saying how much was left out.
QString displayText(const QString& text, int maxLength = 80);

// Only the escaping: for whole messages, which may quote input that was not shortened.
QString escapeControlCharacters(const QString& text);

} // namespace shadowlab
