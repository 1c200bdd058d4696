#include "ReportWriter.h"

#include "MessageText.h"
#include "OutputFile.h"

#include <QDir>

namespace shadowlab {

void writeReport(const QString& directory, const std::vector<ReportRow>& rows, const ReportFacts& facts)
{
    if (!QDir().mkpath(directory))
        throw OutputError(OutputError::Kind::WriteFailed, QStringLiteral("cannot create the report folder '%1'").arg(displayText(directory)));
    const QDir dir(directory);
    writeOutputFile(dir.filePath(QStringLiteral("report.csv")), reportCsv(rows));
    writeOutputFile(dir.filePath(QStringLiteral("report.json")), reportJson(rows, facts));
    writeOutputFile(dir.filePath(QStringLiteral("report.html")), reportHtml(rows, facts));
}

} // namespace shadowlab
