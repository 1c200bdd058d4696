#pragma once

#include "ReportAnalysis.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace shadowlab {

// A report folder that cannot be read back, or reports that do not make one report together.
// The message names the folder and what to do.
class ReportMergeError : public std::runtime_error {
public:
    explicit ReportMergeError(const QString& message) : std::runtime_error(message.toStdString()) {}
};

// Share K of N as `report --shard` takes it and report.json says it ("2/4"): {K, N} with
// 1 <= K <= N, or nothing when `text` is not that.
std::optional<std::pair<int, int>> parseShare(const QString& text);

// One report read back from its folder: report.json and the error images beside it.
struct ReportPart {
    QString directory;
    std::vector<ReportRow> rows;
    ReportFacts facts;
};

// Reads `directory`/report.json as writeReport() wrote it (report, or report --shard) and its
// rows' error images. Throws ReportMergeError naming the file and what is wrong with it.
ReportPart readReportPart(const QString& directory);

// Reports put together (report --merge): the shares of one sweep (--shard K/N, measured on one
// machine or on several), and whole reports or shares of that sweep from other machines, which
// then stand side by side as a comparison. Every part must come from the same sweep (the same
// scene, size, sweep and settings, frames and samples); every configuration must be measured by
// some part, and none twice on one machine. The rows come in sweep order, each carrying the
// renderer and machine that measured it; fronts are marked again, each among the rows of its
// light and machine. Throws ReportMergeError saying which part is missing, doubled or foreign.
struct MergedReport {
    std::vector<ReportRow> rows;
    ReportFacts facts;
    QStringList notes;          // what a reader should know: several machines, who measured what
};
MergedReport mergeReportParts(const std::vector<ReportPart>& parts);

} // namespace shadowlab
