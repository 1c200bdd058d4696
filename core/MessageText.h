#pragma once

#include <QString>
#include <QStringList>

namespace shadowlab {

// Text from input (a value, a key, a path) made safe to quote in a message: control
// characters (NUL included) written as \n, \t, \x01, ..., and anything longer than
// `maxLength` characters cut, saying how much was left out.
QString displayText(const QString& text, int maxLength = 80);

// Only the escaping: for whole messages, which may quote input that was not shortened.
QString escapeControlCharacters(const QString& text);

// The candidate a mistyped `text` most likely meant (fewest single-character edits, case
// ignored, a swap of two neighbours counting as one), or empty when none is close enough to
// be worth suggesting. A candidate whose last dotted part is `text` ("slope" for
// "bias.slope") also counts.
QString closestMatch(const QString& text, const QStringList& candidates);

// " (did you mean 'x'?)" for closestMatch(), empty when there is none.
QString didYouMean(const QString& text, const QStringList& candidates);

} // namespace shadowlab
