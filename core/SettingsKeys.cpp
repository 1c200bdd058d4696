#include "SettingsEntries.h"

#include "MessageText.h"
#include "SettingsError.h"

// The settings' interface: every key, and reading and writing one by name. The keys themselves
// are in SettingsTable.cpp, their parsing in SettingsParsing.cpp, JSON files in SettingsJson.cpp
// and the rules between keys in SettingsValidation.cpp.
namespace shadowlab {

using settings::entries;
using settings::entryFor;
using settings::Entry;

const std::vector<SettingKey>& settingKeys()
{
    static const std::vector<SettingKey> keys = [] {
        std::vector<SettingKey> k;
        for (const Entry& e : entries())
            k.push_back(e.info);
        return k;
    }();
    return keys;
}

const SettingKey* findSettingKey(const QString& key)
{
    for (const SettingKey& k : settingKeys()) {
        if (k.key == key)
            return &k;
    }
    return nullptr;
}

QString settingValue(const Settings& settings, const QString& key)
{
    return entryFor(key).get(settings);
}

void applySetting(Settings& settings, const QString& key, const QString& value)
{
    entryFor(key.trimmed()).set(settings, value);
}

void applyAssignment(Settings& settings, const QString& assignment)
{
    const qsizetype eq = assignment.indexOf(QLatin1Char('='));
    if (eq <= 0)
        throw SettingsError(QString(), QStringLiteral("'%1' is not key=value, e.g. --set bias.slope=0.01").arg(displayText(assignment)));
    applySetting(settings, assignment.left(eq), assignment.mid(eq + 1));
}

} // namespace shadowlab
