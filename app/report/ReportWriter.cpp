#include "ReportWriter.h"

#include "ImageFile.h"
#include "MessageText.h"
#include "OutputFile.h"

#include <QDir>
#include <QRegularExpression>

namespace shadowlab {

void writeReport(const QString& directory, const std::vector<ReportRow>& rows, const ReportFacts& facts)
{
    if (!QDir().mkpath(directory))
        throw OutputError(OutputError::Kind::WriteFailed, QStringLiteral("cannot create the report folder '%1'").arg(displayText(directory)));
    const QDir dir(directory);
    // report.json after the error images it names, so that a report.json always has them.
    writeOutputFile(dir.filePath(QStringLiteral("report.csv")), reportCsv(rows));
    if (!dir.mkpath(QStringLiteral("errors")))
        throw OutputError(OutputError::Kind::WriteFailed, QStringLiteral("cannot create the folder '%1'").arg(displayText(dir.filePath(QStringLiteral("errors")))));
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!rows[i].accuracy.hardErrors.isNull())
            writeOutputFile(dir.filePath(errorImageName(i)), encodePng(rows[i].accuracy.hardErrors));
    }
    // A report written before into the same folder may have had more rows: its images past
    // these would be taken for this report's.
    static const QRegularExpression imageName(QStringLiteral("^(\\d{3,})\\.png$"));
    QDir errors(dir.filePath(QStringLiteral("errors")));
    for (const QString& name : errors.entryList(QDir::Files)) {
        if (const QRegularExpressionMatch m = imageName.match(name); m.hasMatch() && m.captured(1).toULongLong() >= rows.size())
            errors.remove(name);
    }
    writeOutputFile(dir.filePath(QStringLiteral("report.json")), reportJson(rows, facts));
    writeOutputFile(dir.filePath(QStringLiteral("report.html")), reportHtml(rows, facts));
}

} // namespace shadowlab
