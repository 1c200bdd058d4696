#include "AuditCatalogue.h"
#include "CliSupport.h"
#include "Commands.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace shadowlab::cli {

int runAudit(const QStringList& arguments)
{
    return guarded(QStringLiteral("audit"), [&] {
        QCommandLineParser parser;
        parser.setApplicationDescription(QStringLiteral("Run the catalogue of extreme and degenerate cases; exit code 1 if any fails."));
        parser.addHelpOption();
        parser.addOption({QStringLiteral("json"), QStringLiteral("Print JSON for machines.")});
        if (!parseArguments(parser, QStringLiteral("audit"), arguments))
            return kExitOk;

        HeadlessRenderer headless;
        const bool json = parser.isSet(QStringLiteral("json"));
        QJsonArray rows;
        int failed = 0;
        // The case column as wide as the longest name, so every row's result lines up.
        int nameWidth = 4;
        for (const AuditCase& c : auditCatalogue())
            nameWidth = std::max(nameWidth, int(c.name.size()));
        if (!json)
            out() << "renderer: " << headless.renderer().rendererString() << "\n\n"
                  << QStringLiteral("%1 %2 %3 %4\n").arg(QStringLiteral("case"), -nameWidth).arg(QStringLiteral("result"), -6)
                         .arg(QStringLiteral("error"), -8).arg(QStringLiteral("expected / what happened"));
        for (const AuditCase& c : auditCatalogue()) {
            const AuditOutcome o = runAuditCase(c, headless);
            failed += !o.pass;
            const QString error = o.error ? QStringLiteral("%1 %").arg(100.0 * *o.error, 0, 'f', 2) : QStringLiteral("-");
            if (json) {
                QJsonObject row{{QStringLiteral("case"), c.name},
                                {QStringLiteral("expected"), c.expected},
                                {QStringLiteral("happened"), o.happened},
                                {QStringLiteral("finite"), o.finite},
                                {QStringLiteral("pass"), o.pass}};
                if (o.error)
                    row.insert(QStringLiteral("error"), *o.error);
                rows.append(row);
                continue;
            }
            out() << QStringLiteral("%1 %2 %3 %4\n").arg(c.name, -nameWidth).arg(o.pass ? QStringLiteral("pass") : QStringLiteral("FAIL"), -6)
                         .arg(error, -8).arg(c.expected)
                  << QString(nameWidth + 17, QLatin1Char(' ')) << "-> " << o.happened << '\n';
            out().flush();
        }
        if (json)
            out() << QJsonDocument(QJsonObject{{QStringLiteral("renderer"), headless.renderer().rendererString()},
                                               {QStringLiteral("cases"), rows},
                                               {QStringLiteral("failed"), failed}})
                         .toJson(QJsonDocument::Indented);
        else
            out() << '\n' << auditCatalogue().size() - std::size_t(failed) << " of " << auditCatalogue().size() << " cases pass\n";
        out().flush();
        return failed ? kExitFailure : kExitOk;
    });
}

} // namespace shadowlab::cli
