#pragma once

// The kinds of settings key (a number, a whole number, a toggle, a point, a choice of names), each
// built from a KeySpec in designated initialisers and an accessor to its field. For the key
// table (SettingsTable.cpp) only.

#include "MessageText.h"
#include "SettingsEntries.h"
#include "SettingsError.h"

#include <QStringList>

namespace shadowlab::settings {

// What a key says about itself. `range` and `oddOnly` are for numbers and whole numbers.
struct KeySpec {
    const char* key = "";
    Range range{};
    bool oddOnly = false;
    const char* help = "";
    SettingPresentation look{};
};

inline SettingKey describe(const KeySpec& spec, const char* type, const QString& rangeText, double lo, double hi, const QStringList& choices = {})
{
    return SettingKey{.key = QString::fromLatin1(spec.key), .type = QString::fromLatin1(type), .range = rangeText,
                      .help = QString::fromUtf8(spec.help), .choices = choices, .minimum = lo, .maximum = hi,
                      .presentation = spec.look};
}

inline const auto noCheck = [](const Settings&) { return std::optional<QString>(); };

// Field accessors are generic lambdas `[](auto& s) -> auto& { return s.x.y; }` so that one
// accessor serves reading, writing and checking.
template <typename Field>
Entry number(const KeySpec& spec, Field field)
{
    const QString k = QString::fromLatin1(spec.key);
    const Range range = spec.range;
    return {describe(spec, "number", range.text(), range.lo, range.hi),
            [field](const Settings& s) { return formatNumber(field(s)); },
            [field, range, k](Settings& s, const QString& v) { field(s) = parseNumber(k, v, range); },
            [field, range](const Settings& s) { return checkNumber(field(s), range); }};
}

// A whole number in spec.range, and odd where spec.oddOnly says so.
template <typename Field>
Entry whole(const KeySpec& spec, Field field)
{
    const QString k = QString::fromLatin1(spec.key);
    const int lo = int(spec.range.lo), hi = int(spec.range.hi);
    const bool oddOnly = spec.oddOnly;
    const QString rangeText = QStringLiteral("[%1, %2]%3").arg(lo).arg(hi).arg(oddOnly ? QStringLiteral(", odd") : QString());
    auto check = [lo, hi, oddOnly, rangeText](int v) -> std::optional<QString> {
        if (v < lo || v > hi)
            return QStringLiteral("%1 is out of range; allowed: %2").arg(v).arg(rangeText);
        if (oddOnly && v % 2 == 0)
            return QStringLiteral("%1 is even; it must be odd (a kernel has a centre texel), e.g. %2 or %3; allowed: %4")
                .arg(v)
                .arg(std::max(v - 1, lo))
                .arg(std::min(v + 1, hi))
                .arg(rangeText);
        return std::nullopt;
    };
    return {describe(spec, "integer", rangeText, lo, hi),
            [field](const Settings& s) { return QString::number(field(s)); },
            [field, check, k, rangeText](Settings& s, const QString& v) {
                const int value = parseWholeNumber(k, v, rangeText);
                if (auto problem = check(value))
                    throw SettingsError(k, *problem);
                field(s) = value;
            },
            [field, check](const Settings& s) { return check(field(s)); }};
}

template <typename Field>
Entry toggle(const KeySpec& spec, Field field)
{
    const QString k = QString::fromLatin1(spec.key);
    return {describe(spec, "bool", QStringLiteral("true | false"), 0, 1),
            [field](const Settings& s) { return field(s) ? QStringLiteral("true") : QStringLiteral("false"); },
            [field, k](Settings& s, const QString& v) { field(s) = parseBool(k, v); },
            noCheck};
}

template <typename Field>
Entry point(const KeySpec& spec, Field field)
{
    const QString k = QString::fromLatin1(spec.key);
    return {describe(spec, "vec3", QStringLiteral("x,y,z, each finite with |x| <= 1e7"), -kMaxCoordinate, kMaxCoordinate),
            [field](const Settings& s) { return formatVec3(field(s)); },
            [field, k](Settings& s, const QString& v) { field(s) = parseVec3(k, v); },
            [field](const Settings& s) { return checkVec3(field(s)); }};
}

// An enum spelled by a fixed list of names, in the enum's order. `then` runs after a value is
// set, for keys that keep another in step (light.type and light.projection).
template <typename Enum, typename Field>
Entry choice(const KeySpec& spec, const QStringList& names, Field field, std::function<void(Settings&)> then = {})
{
    const QString k = QString::fromLatin1(spec.key);
    const QString rangeText = names.join(QStringLiteral(" | "));
    return {describe(spec, "choice", rangeText, 0, double(names.size() - 1), names),
            [field, names](const Settings& s) { return names.value(int(field(s))); },
            [field, names, k, rangeText, then](Settings& s, const QString& v) {
                const int index = names.indexOf(v.trimmed().toLower());
                if (index < 0)
                    throw SettingsError(k, QStringLiteral("'%1' is not allowed%2; choose one of %3").arg(displayText(v), didYouMean(v, names), rangeText));
                field(s) = Enum(index);
                if (then)
                    then(s);
            },
            noCheck};
}

} // namespace shadowlab::settings
