#include "SettingsEntries.h"

#include "InputFile.h"
#include "MessageText.h"
#include "OutputFile.h"
#include "SettingsError.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>

#include <utility>

// Settings as JSON: a file's nested objects name the keys' dotted parts, and every key writes
// the type its table entry has.
namespace shadowlab {

using settings::entries;
using settings::Entry;
using settings::formatNumber;

namespace {

void flattenJson(const QJsonObject& object, const QString& prefix, std::vector<std::pair<QString, QJsonValue>>& out)
{
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QString key = prefix.isEmpty() ? it.key() : prefix + QLatin1Char('.') + it.key();
        if (it.value().isObject())
            flattenJson(it.value().toObject(), key, out);
        else
            out.emplace_back(key, it.value());
    }
}

QString jsonValueText(const QString& key, const QJsonValue& value)
{
    switch (value.type()) {
    case QJsonValue::Bool:
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return formatNumber(value.toDouble());
    case QJsonValue::String:
        return value.toString();
    case QJsonValue::Array: {
        QStringList parts;
        for (const QJsonValue& v : value.toArray()) {
            if (!v.isDouble())
                throw SettingsError(key, QStringLiteral("arrays must hold numbers, e.g. [1, 2, 3]"));
            parts << formatNumber(v.toDouble());
        }
        return parts.join(QLatin1Char(','));
    }
    default:
        throw SettingsError(key, QStringLiteral("null or undefined is not a value; give a number, string, boolean or [x, y, z]"));
    }
}

} // namespace

QJsonObject settingsToJson(const Settings& settings)
{
    QJsonObject object;
    for (const Entry& e : entries()) {
        const QString text = e.get(settings);
        if (e.info.type == u"number" || e.info.type == u"integer")
            object.insert(e.info.key, text.toDouble());
        else if (e.info.type == u"bool")
            object.insert(e.info.key, text == u"true");
        else if (e.info.type == u"vec3") {
            QJsonArray array;
            for (const QString& part : text.split(QLatin1Char(',')))
                array.append(part.toDouble());
            object.insert(e.info.key, array);
        } else
            object.insert(e.info.key, text);
    }
    return object;
}

QStringList assignmentsFromJson(const QJsonObject& object)
{
    std::vector<std::pair<QString, QJsonValue>> flat;
    flattenJson(object, QString(), flat);
    QStringList assignments;
    for (const auto& [key, value] : flat)
        assignments << key + QLatin1Char('=') + jsonValueText(key, value);
    return assignments;
}

Settings settingsFromJson(const QJsonObject& object, const Settings& base)
{
    std::vector<std::pair<QString, QJsonValue>> flat;
    flattenJson(object, QString(), flat);
    Settings result = base;
    for (const auto& [key, value] : flat)
        applySetting(result, key, jsonValueText(key, value));
    return result;
}

QJsonObject readSettingsObject(const QString& path)
{
    const QByteArray bytes = readInputFile(path, QStringLiteral("settings file"));
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        throw SettingsError(QString(), QStringLiteral("settings file '%1' is not valid JSON at offset %2: %3")
                                           .arg(displayText(path))
                                           .arg(error.offset)
                                           .arg(error.errorString()));
    if (!doc.isObject())
        throw SettingsError(QString(), QStringLiteral("settings file '%1' must hold a JSON object of key: value pairs").arg(displayText(path)));
    return doc.object();
}

Settings settingsFromFileObject(const QString& path, const QJsonObject& object, const Settings& base)
{
    try {
        return settingsFromJson(object, base);
    } catch (const SettingsError& e) {
        throw e.within(QStringLiteral("in '%1'").arg(displayText(path)));
    }
}

Settings loadSettingsFile(const QString& path, const Settings& base)
{
    return settingsFromFileObject(path, readSettingsObject(path), base);
}

void saveSettingsFile(const QString& path, const Settings& settings)
{
    checkOutputFile(path, QStringLiteral("settings file"));
    writeOutputFile(path, QJsonDocument(settingsToJson(settings)).toJson(QJsonDocument::Indented));
}

} // namespace shadowlab
