#include "CliSupport.h"
#include "Commands.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace shadowlab::cli {

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
        out() << QStringLiteral("%1 %2 %3\n").arg(QStringLiteral("key"), -21).arg(QStringLiteral("default"), -16).arg(QStringLiteral("range"));
        for (const SettingKey& k : settingKeys()) {
            out() << QStringLiteral("%1 %2 %3\n").arg(k.key, -21).arg(settingValue(defaults, k.key), -16).arg(k.range);
            out() << QStringLiteral("%1 %2\n").arg(QString(), -21).arg(k.help);
        }
        out().flush();
        return kExitOk;
    });
}

} // namespace shadowlab::cli
