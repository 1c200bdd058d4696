#include "CliSupport.h"
#include "Commands.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace shadowlab::cli {

namespace {

// `text` in lines of at most `width` characters, broken between words (a longer word alone).
QStringList wrapWords(const QString& text, qsizetype width)
{
    QStringList lines;
    QString line;
    for (const QString& word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        if (!line.isEmpty() && line.size() + 1 + word.size() > width) {
            lines << line;
            line.clear();
        }
        line += (line.isEmpty() ? QString() : QStringLiteral(" ")) + word;
    }
    if (!line.isEmpty())
        lines << line;
    return lines;
}

} // namespace

int runSettings(const QStringList& arguments)
{
    return guarded(QStringLiteral("settings"), [&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(QStringLiteral("List every setting key with its default and range."));
        parser.addHelpOption();
        parser.addOption({QStringLiteral("scene"), QStringLiteral("Show the defaults of this scene preset, or of a model or scene file (which is read)."),
                          QStringLiteral("name|file"), QStringLiteral("seed")});
        parser.addOption({QStringLiteral("json"), QStringLiteral("Print JSON for machines.")});
        addImportOptions(parser);
        if (!parseArguments(parser, QStringLiteral("settings"), arguments))
            return kExitOk;
        applyImportOptions(parser);
        Settings probe;
        applySetting(probe, QStringLiteral("scene"), parser.value(QStringLiteral("scene")));
        const Settings defaults = presetSettings(probe.scene);

        if (parser.isSet(QStringLiteral("json"))) {
            QJsonArray keys;
            for (const SettingKey& k : settingKeys()) {
                QJsonObject o{{QStringLiteral("key"), k.key},
                              {QStringLiteral("type"), k.type},
                              {QStringLiteral("default"), settingValue(defaults, k.key)},
                              {QStringLiteral("range"), k.range},
                              {QStringLiteral("help"), k.help}};
                if (!k.choices.isEmpty())
                    o.insert(QStringLiteral("choices"), QJsonArray::fromStringList(k.choices));
                keys.append(o);
            }
            out() << QJsonDocument(keys).toJson(QJsonDocument::Indented);
            return kExitOk;
        }
        // Columns as wide as their widest entry; the help wrapped under the key's column. An
        // empty default (no objects switched off) reads "none", so the columns stay columns.
        const auto shownDefault = [&](const QString& key) {
            const QString value = settingValue(defaults, key);
            return value.isEmpty() ? QStringLiteral("none") : value;
        };
        qsizetype keyWidth = 3, defaultWidth = 7;
        for (const SettingKey& k : settingKeys()) {
            keyWidth = std::max(keyWidth, k.key.size());
            defaultWidth = std::max(defaultWidth, shownDefault(k.key).size());
        }
        const int keyColumn = -int(keyWidth), defaultColumn = -int(defaultWidth);
        out() << QStringLiteral("%1  %2  %3\n").arg(QStringLiteral("key"), keyColumn).arg(QStringLiteral("default"), defaultColumn).arg(QStringLiteral("range"));
        const QString indent(keyWidth + 2, QLatin1Char(' '));
        for (const SettingKey& k : settingKeys()) {
            out() << QStringLiteral("%1  %2  %3\n").arg(k.key, keyColumn).arg(shownDefault(k.key), defaultColumn).arg(k.range);
            for (const QString& line : wrapWords(k.help, std::max<qsizetype>(100 - indent.size(), 40)))
                out() << indent << line << '\n';
        }
        out().flush();
        return kExitOk;
    });
}

} // namespace shadowlab::cli
