#include "SettingsEntries.h"

#include "MessageText.h"
#include "SettingsError.h"

#include <QStringList>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace shadowlab::settings {

namespace {

// Why `text`, which Qt would not read as a double, is refused: a number too small or too
// large for a double is called that, not "not a number".
QString numberProblem(const QString& text)
{
    const QByteArray latin = text.trimmed().toLatin1();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(latin.constData(), &end);
    if (!latin.isEmpty() && end == latin.constData() + latin.size() && errno == ERANGE) {
        if (std::abs(v) < 1.0)
            return QStringLiteral("'%1' is too small: it underflows to 0 in double precision (the smallest normal magnitude is %2); write 0 or a larger value")
                .arg(displayText(text))
                .arg(std::numeric_limits<double>::min());
        return QStringLiteral("'%1' is too large: it overflows double precision").arg(displayText(text));
    }
    return QStringLiteral("'%1' is not a number").arg(displayText(text));
}

} // namespace

QString Range::text() const
{
    return QStringLiteral("%1%2, %3%4")
        .arg(loOpen ? QLatin1Char('(') : QLatin1Char('['))
        .arg(lo)
        .arg(hi)
        .arg(hiOpen ? QLatin1Char(')') : QLatin1Char(']'));
}

QString formatNumber(double v)
{
    return QString::number(v, 'g', 15);
}

QString formatVec3(const glm::dvec3& v)
{
    return QStringLiteral("%1,%2,%3").arg(formatNumber(v.x), formatNumber(v.y), formatNumber(v.z));
}

std::optional<QString> checkNumber(double v, const Range& range)
{
    if (!std::isfinite(v))
        return QStringLiteral("must be a finite number in %1, not %2").arg(range.text(), formatNumber(v));
    if (!range.contains(v))
        return QStringLiteral("%1 is out of range; allowed: %2").arg(formatNumber(v), range.text());
    return std::nullopt;
}

std::optional<QString> checkVec3(const glm::dvec3& v)
{
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(v[i]) || std::abs(v[i]) > kMaxCoordinate)
            return QStringLiteral("each coordinate must be finite with |x| <= %1, got %2")
                .arg(formatNumber(kMaxCoordinate), formatVec3(v));
    }
    return std::nullopt;
}

double parseNumber(const QString& key, const QString& text, const Range& range)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok)
        throw SettingsError(key, QStringLiteral("%1; allowed: %2").arg(numberProblem(text), range.text()));
    if (auto problem = checkNumber(v, range))
        throw SettingsError(key, *problem);
    return v;
}

int parseWholeNumber(const QString& key, const QString& text, const QString& allowed)
{
    bool ok = false;
    const int value = text.trimmed().toInt(&ok);
    if (!ok)
        throw SettingsError(key, QStringLiteral("'%1' is not a whole number; allowed: %2").arg(displayText(text), allowed));
    return value;
}

bool parseBool(const QString& key, const QString& text)
{
    const QString t = text.trimmed().toLower();
    if (t == u"true" || t == u"1" || t == u"on" || t == u"yes")
        return true;
    if (t == u"false" || t == u"0" || t == u"off" || t == u"no")
        return false;
    throw SettingsError(key, QStringLiteral("'%1' is not a boolean; allowed: true | false").arg(displayText(text)));
}

glm::dvec3 parseVec3(const QString& key, const QString& text)
{
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() != 3)
        throw SettingsError(key, QStringLiteral("'%1' is not a vector; write three numbers x,y,z").arg(displayText(text)));
    glm::dvec3 result;
    for (int i = 0; i < 3; ++i) {
        bool ok = false;
        result[i] = parts[i].trimmed().toDouble(&ok);
        if (!ok)
            throw SettingsError(key, QStringLiteral("'%1' is not a vector of three numbers x,y,z: %2").arg(displayText(text), numberProblem(parts[i])));
    }
    if (auto problem = checkVec3(result))
        throw SettingsError(key, *problem);
    return result;
}

} // namespace shadowlab::settings
