// One input, read three ways, as the command line reads what users give it: a settings file
// (then validated), a report sweep file (every entry applied to the defaults), and lines of
// --set key=value. Refusals (SettingsError, UsageError) are the expected outcome for most
// inputs; a crash, a sanitizer report, an uncaught exception or a hang is a bug.
#include "SettingsOptions.h"
#include "ReportSweep.h"
#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstddef>
#include <cstdint>

namespace {

using namespace shadowlab;

void asSettingsFile(const QByteArray& bytes, const Settings& base)
{
    try {
        const QJsonDocument doc = QJsonDocument::fromJson(bytes);
        if (!doc.isObject())
            return;
        const Settings settings = settingsFromFileObject(QStringLiteral("fuzz.json"), doc.object(), base);
        validate(settings);
        settingsToJson(settings);
    } catch (const SettingsError& e) {
        (void)e.what();
    }
}

void asSweepFile(const QByteArray& bytes, const Settings& base)
{
    try {
        for (const SweepEntry& entry : parseSweepFile(bytes, QStringLiteral("sweep.json")))
            applySweepEntry(base, entry);
    } catch (const SettingsError& e) {
        (void)e.what();
    } catch (const UsageError& e) {
        (void)e.what();
    }
}

void asAssignments(const QByteArray& bytes, const Settings& base)
{
    Settings settings = base;
    for (const QByteArray& line : bytes.split('\n')) {
        try {
            applyAssignment(settings, QString::fromUtf8(line));
        } catch (const SettingsError& e) {
            (void)e.what();
        }
    }
    validate(settings);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const Settings base = presetSettings(QStringLiteral("seed"));
    const QByteArray bytes(reinterpret_cast<const char*>(data), qsizetype(size));
    asSettingsFile(bytes, base);
    asSweepFile(bytes, base);
    asAssignments(bytes, base);
    return 0;
}
