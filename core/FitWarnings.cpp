// The user's words for the cuts fitLight() measures (LightFitting.h).
#include "LightFitting.h"

#include <QStringList>

#include <algorithm>

namespace shadowlab {

namespace {

// Two significant digits below 10 %, whole percent above ("0.38", "7.2", "100").
QString percent(double share)
{
    const double p = share * 100.0;
    return QString::number(p, 'f', p < 1.0 ? 2 : p < 10.0 ? 1 : 0);
}

constexpr double kPartWorthSaying = 1e-3;

SettingsIssue warningOf(const FitCut& cut)
{
    if (cut.by == FitCut::By::WidestCone)
        return {SettingsIssue::Severity::Warning, QStringLiteral("light.position"),
                QStringLiteral("%1 % of the visible receivers lie behind the light or outside the widest cone one map can cover (%2°): "
                               "they are lit without a shadow test; move the light away from them, or use an ortho light")
                    .arg(percent(cut.share))
                    .arg(kMaxFittedFov)};
    // Every plane that cuts, the sides together, most first; the warning sits at the first.
    struct Part {
        double share;
        const char* key;
        const char* where;
    };
    const auto& b = cut.byPlane;
    std::vector<Part> parts{{b[0] + b[1] + b[2] + b[3], cut.perspective ? "light.fov" : "light.extent", "outside the sides"},
                            {b[4], "light.near", "before light.near"},
                            {b[5], "light.far", "beyond light.far"}};
    std::stable_sort(parts.begin(), parts.end(), [](const Part& x, const Part& y) { return x.share > y.share; });
    QStringList where;
    for (const Part& part : parts) {
        if (part.share > kPartWorthSaying)
            where << QStringLiteral("%1 % %2").arg(percent(std::min(part.share, cut.share)), QString::fromLatin1(part.where));
    }
    return {SettingsIssue::Severity::Warning, QString::fromLatin1(parts.front().key),
            QStringLiteral("%1 % of the visible receivers lie outside the light volume (%2): they are lit without a shadow test; "
                           "widen the volume (light.extent or light.fov, light.near, light.far), or set light.fit=scene")
                .arg(percent(cut.share), where.join(QStringLiteral(", ")))};
}

} // namespace

std::vector<SettingsIssue> fitWarnings(const FittedLight& fit)
{
    std::vector<SettingsIssue> warnings;
    for (const FitCut& cut : fit.cuts) {
        SettingsIssue warning = warningOf(cut);
        if (std::none_of(warnings.begin(), warnings.end(), [&](const SettingsIssue& w) { return w.key == warning.key; }))
            warnings.push_back(std::move(warning));
    }
    return warnings;
}

} // namespace shadowlab
