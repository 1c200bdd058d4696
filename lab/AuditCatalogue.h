#pragma once

#include "HeadlessRenderer.h"

#include <QString>

#include <functional>
#include <optional>
#include <vector>

namespace shadowlab {

// What one audit case saw.
struct AuditOutcome {
    bool pass = false;
    bool finite = true;                 // every matrix and every visibility value was finite
    std::optional<double> error;        // share of light-facing pixels misclassified against ray casting
    QString happened;                   // in a few words, with the numbers that decided
};

// One extreme or degenerate case: its name, what should happen, and how to find out. Shared by
// `shadowlab audit` and tests/tst_Audit.cpp, so each case is also a test row.
struct AuditCase {
    QString name;
    QString expected;
    std::function<AuditOutcome(HeadlessRenderer&)> run;
};

const std::vector<AuditCase>& auditCatalogue();

// Runs `c` on `headless`, turning any exception into a failed outcome and restoring the preset
// scene afterwards, so one case cannot spoil the next.
AuditOutcome runAuditCase(const AuditCase& c, HeadlessRenderer& headless);

} // namespace shadowlab
