#pragma once

#include "ReportAnalysis.h"

#include <QByteArray>
#include <QString>

#include <vector>

namespace shadowlab {

// Each format over the same rows and facts (ReportAnalysis.h).
QByteArray reportCsv(const std::vector<ReportRow>& rows);
QByteArray reportJson(const std::vector<ReportRow>& rows, const ReportFacts& facts);
QByteArray reportHtml(const std::vector<ReportRow>& rows, const ReportFacts& facts);

// Where report.json says the error image of the row at `position` is, relative to its folder.
QString errorImageName(std::size_t position);

// Writes report.csv, report.json, each row's error image (errorImageName(), which
// report --merge reads back) and a self-contained report.html (inline SVG charts of each
// error against time with its Pareto front and the noise of both axes, the table without its
// columns of zeros, and the error images of the best and worst rows). Each file is written
// whole or not at all; throws OutputError when one cannot be.
void writeReport(const QString& directory, const std::vector<ReportRow>& rows, const ReportFacts& facts);

} // namespace shadowlab
