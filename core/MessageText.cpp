#include "MessageText.h"

#include <algorithm>
#include <vector>

namespace shadowlab {

QString escapeControlCharacters(const QString& text)
{
    QString result;
    result.reserve(text.size());
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if (u == u'\n')
            result += QStringLiteral("\\n");
        else if (u == u'\t')
            result += QStringLiteral("\\t");
        else if (u == u'\r')
            result += QStringLiteral("\\r");
        else if (u < 0x20 || (u >= 0x7f && u < 0xa0))
            result += QStringLiteral("\\x%1").arg(int(u), 2, 16, QLatin1Char('0'));
        else
            result += c;
    }
    return result;
}

QString displayText(const QString& text, int maxLength)
{
    if (text.size() <= maxLength)
        return escapeControlCharacters(text);
    return escapeControlCharacters(text.left(maxLength)) + QStringLiteral("… (%1 more characters)").arg(text.size() - maxLength);
}

namespace {

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of
// neighbours each cost one.
int editDistance(const QString& a, const QString& b)
{
    const qsizetype n = a.size(), m = b.size();
    std::vector<std::vector<int>> d(std::size_t(n + 1), std::vector<int>(std::size_t(m + 1)));
    for (qsizetype i = 0; i <= n; ++i)
        d[std::size_t(i)][0] = int(i);
    for (qsizetype j = 0; j <= m; ++j)
        d[0][std::size_t(j)] = int(j);
    for (qsizetype i = 1; i <= n; ++i) {
        for (qsizetype j = 1; j <= m; ++j) {
            const auto I = std::size_t(i), J = std::size_t(j);
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[I][J] = std::min({d[I - 1][J] + 1, d[I][J - 1] + 1, d[I - 1][J - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[I][J] = std::min(d[I][J], d[I - 2][J - 2] + 1);
        }
    }
    return d[std::size_t(n)][std::size_t(m)];
}

} // namespace

QString closestMatch(const QString& text, const QStringList& candidates)
{
    const QString typed = text.trimmed().toLower();
    if (typed.isEmpty() || typed.size() > 200)
        return QString();
    // A third of the word may be wrong, at least one character, at most three.
    const int allowed = std::clamp(int(typed.size()) / 3, 1, 3);
    QString best;
    int bestDistance = allowed + 1;
    for (const QString& candidate : candidates) {
        const QString c = candidate.toLower();
        if (c == typed)
            return QString();   // not mistyped
        int distance = editDistance(typed, c);
        if (c.section(QLatin1Char('.'), -1) == typed)
            distance = std::min(distance, 1);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = candidate;
        }
    }
    return best;
}

QString didYouMean(const QString& text, const QStringList& candidates)
{
    const QString match = closestMatch(text, candidates);
    return match.isEmpty() ? QString() : QStringLiteral(" (did you mean '%1'?)").arg(match);
}

} // namespace shadowlab
