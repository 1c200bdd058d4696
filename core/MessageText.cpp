#include "MessageText.h"

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

} // namespace shadowlab
