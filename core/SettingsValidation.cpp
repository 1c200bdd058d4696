#include "SettingsEntries.h"

#include "MomentMath.h"
#include "SettingsError.h"
#include "ShadowTechnique.h"
#include "ShadowViews.h"
#include "VirtualPages.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <tuple>
#include <utility>

// The rules between keys. Each field's own range is its table entry's; what is checked here
// are the combinations that one field cannot judge alone.
namespace shadowlab {

using settings::entries;
using settings::Entry;
using settings::formatNumber;

namespace {

struct Issues {
    std::vector<SettingsIssue> errors;
    std::vector<SettingsIssue> warnings;

    void error(const char* key, const QString& message)
    {
        errors.push_back({SettingsIssue::Severity::Error, QString::fromLatin1(key), message});
    }
    void warning(const char* key, const QString& message)
    {
        warnings.push_back({SettingsIssue::Severity::Warning, QString::fromLatin1(key), message});
    }
};

// The light and the camera each need somewhere to look, and a light's depth range must be one.
void checkPlacement(const Settings& s, Issues& issues)
{
    const double lightDistance = glm::length(s.light.position - s.light.target);
    if (!(lightDistance > 1e-9 * std::max(1.0, glm::length(s.light.target))))
        issues.error("light.position", QStringLiteral("the light is at its target; move light.position away from light.target"));
    if (glm::length(s.camera.position - s.camera.target) <= 1e-9 * std::max(1.0, glm::length(s.camera.target)))
        issues.error("camera.position", QStringLiteral("the camera is at its target; move camera.position away from camera.target"));
    if (s.light.projection == LightProjection::Perspective && s.light.nearPlane <= 0.0)
        issues.error("light.near", QStringLiteral("a perspective light needs near > 0 (got %1); try 0.1").arg(formatNumber(s.light.nearPlane)));
    if (s.light.nearPlane >= s.light.farPlane)
        issues.error("light.far", QStringLiteral("far (%1) must be greater than near (%2)")
                                      .arg(formatNumber(s.light.farPlane), formatNumber(s.light.nearPlane)));
}

// The light's type, its projection and the views its map is cut into.
void checkLightRig(const Settings& s, Issues& issues)
{
    if ((s.light.type == LightType::Directional) != (s.light.projection == LightProjection::Ortho))
        issues.error("light.projection", QStringLiteral("light.projection=%1 does not fit light.type=%2; a directional light is ortho, spot and point "
                                                        "lights are perspective (setting light.type sets the projection)")
                                             .arg(toString(s.light.projection), toString(s.light.type)));
    if (s.shadow.cascades > 1 && s.light.type != LightType::Directional)
        issues.error("shadow.cascades", QStringLiteral("cascades split a directional light's map; with light.type=%1 set shadow.cascades=1")
                                            .arg(toString(s.light.type)));
    if (const ShadowStorageLimits& storage = shadowStorageLimits(shadowTechnique(s.filter.mode).map);
        usesShadowViews(s) && !storage.refusedWithViews.isEmpty() && settingValue(s, storage.refusedWithViews) == u"true")
        issues.error(storage.refusedWithViews.toUtf8().constData(), storage.reason);
}

// The first setting a virtual map cannot serve, with the key to change.
void checkVirtualMap(const Settings& s, Issues& issues)
{
    if (!s.shadow.virtualMap)
        return;
    const auto refuse = [&](const char* key, const QString& why) {
        issues.error(key, QStringLiteral("%1 (shadow.virtual=true); %2").arg(why, QStringLiteral("set shadow.virtual=false to use it")));
    };
    const ShadowTechnique& technique = shadowTechnique(s.filter.mode);
    const std::optional<double> reach = technique.tapReach(s.filter);
    if (s.light.type != LightType::Directional)
        refuse("light.type", QStringLiteral("virtual shadow maps are clipmaps of a directional light, not of a %1 light").arg(toString(s.light.type)));
    else if (s.shadow.cascades > 1)
        refuse("shadow.cascades", QStringLiteral("a virtual map replaces cascades: its clipmap levels give each pixel its own texel size; set shadow.cascades=1"));
    else if (s.light.warp != LightWarp::None)
        refuse("light.warp", QStringLiteral("a virtual map's pages are plain ortho views; set light.warp=none"));
    else if (s.light.fit == LightFit::Manual)
        refuse("light.fit", QStringLiteral("a virtual map's coarsest level covers the whole scene, not a manual volume; set light.fit=scene"));
    else if (technique.map == ShadowMapKind::Moments)
        refuse("filter.mode", QStringLiteral("%1 filters a moments map, and a virtual map stores depth pages").arg(toString(s.filter.mode)));
    else if (!reach)
        refuse("filter.mode", QStringLiteral("%1 may read anywhere in the map, beyond a page and its border").arg(toString(s.filter.mode)));
    else if (*reach + s.bias.normal > kVirtualPageBorder)
        refuse(s.bias.normal > 0.0 ? "bias.normal" : "filter.mode",
               QStringLiteral("the taps (%1 texels) and the normal offset (%2 texels) reach past a page's border of %3 texels; "
                              "choose a smaller kernel, radius or bias.normal")
                   .arg(formatNumber(*reach), formatNumber(s.bias.normal)).arg(kVirtualPageBorder));
    else if (s.filter.earlyOut && technique.penumbraOnly)
        refuse("filter.early_out", QStringLiteral("penumbra-only filtering reads a min/max mip of one map, not of pages; set filter.early_out=false"));
}

// A cache policy the map cannot keep: a virtual map keeps pages, a map of views keeps views.
void checkCache(const Settings& s, Issues& issues)
{
    const ShadowCachePolicy cache = s.shadow.cache;
    if (cache == ShadowCachePolicy::Pages && !s.shadow.virtualMap)
        issues.error("shadow.cache", QStringLiteral("pages keeps a virtual map's pages, and this map has views, not pages; set shadow.virtual=true, "
                                                    "or shadow.cache=static to keep the views' still casters"));
    else if (s.shadow.virtualMap && cache != ShadowCachePolicy::Off && cache != ShadowCachePolicy::Pages)
        issues.error("shadow.cache", QStringLiteral("a virtual map keeps pages, not views: %1 does not apply to it; set shadow.cache=pages (or off)")
                                         .arg(toString(cache)));
}

// A depth-unit bias above half the depth range pushes every receiver through its casters.
void checkDepthBias(const Settings& s, Issues& issues)
{
    if (s.bias.space != BiasSpace::Depth)
        return;
    for (const auto& [key, value] : {std::pair{"bias.slope", s.bias.slope}, std::pair{"bias.min", s.bias.min}}) {
        if (value > 0.5)
            issues.error(key, QStringLiteral("%1 is more than half the depth range; in depth units (bias.space=depth) it must be in [0, 0.5], "
                                             "or choose bias.space=world")
                                  .arg(formatNumber(value)));
    }
}

// What runs, but not as set: each warning says what is used instead and how to get what was asked.
void warnOfSubstitutes(const Settings& s, Issues& issues)
{
    if (s.light.fit == LightFit::Manual && s.light.projection == LightProjection::Perspective && s.map.format == DepthFormat::Depth24
        && s.light.farPlane / s.light.nearPlane > 1e5)
        issues.warning("light.near", QStringLiteral("far/near = %1 leaves a 24-bit depth map almost no precision far away; raise light.near or use map.format=depth32f")
                                         .arg(formatNumber(s.light.farPlane / s.light.nearPlane)));
    if (s.light.warp == LightWarp::Lispsm && s.light.type != LightType::Directional)
        issues.warning("light.warp", QStringLiteral("light.warp=lispsm warps a directional light's map; a %1 light's map is drawn unwarped (set light.warp=none)")
                                         .arg(toString(s.light.type)));
    if (s.filter.mode == FilterMode::PcfOptimized && optimizedPcfKernel(s.filter) != s.filter.kernel)
        issues.warning("filter.kernel", QStringLiteral("pcf-optimized has kernels of 3, 5 and 7 texels; %1 is used for filter.kernel=%2 (filter.mode=pcf has every odd width)")
                                            .arg(optimizedPcfKernel(s.filter)).arg(s.filter.kernel));
    if (!isMomentTechnique(s.filter.mode))
        return;
    if (s.moments.blurAt == MomentBlurAt::Lookup && (s.moments.mipmaps || s.moments.anisotropy > 1) && s.moments.blur > 1)
        issues.warning("moments.blur_at", QStringLiteral("moments.blur_at=lookup: a map with mipmaps or anisotropic lookups is blurred by its "
                                                         "own pass (the mips must hold the blur, and an anisotropic footprint is not the "
                                                         "lookup's kernel); set moments.mipmaps=false and moments.anisotropy=1 to blur in "
                                                         "the lookup"));
    const double limit = maxExponent(s.filter.mode, s.moments.format);
    for (const auto& [key, value] : {std::pair{"filter.exponent_positive", s.filter.positiveExponent},
                                     std::pair{"filter.exponent_negative", s.filter.negativeExponent}}) {
        if (usesParameter(s.filter, QString::fromLatin1(key)) && value > limit)
            issues.warning(key, QStringLiteral("%1 does not fit moments.format=%2 for %3: %4 is used; choose moments.format=32 for larger exponents")
                                    .arg(formatNumber(value), toString(s.moments.format), toString(s.filter.mode), QString::number(limit, 'f', 2)));
    }
}

} // namespace

std::vector<SettingsIssue> validate(const Settings& s)
{
    Issues issues;
    for (const Entry& e : entries()) {
        if (auto problem = e.check(s))
            issues.errors.push_back({SettingsIssue::Severity::Error, e.info.key, *problem});
    }
    if (!issues.errors.empty())
        return issues.errors; // cross-field rules mean little while a field itself is broken

    checkPlacement(s, issues);
    checkLightRig(s, issues);
    checkVirtualMap(s, issues);
    checkCache(s, issues);
    if (s.shadow.cascades > 1 && s.light.fit == LightFit::Manual)
        issues.error("shadow.cascades", QStringLiteral("cascades are fitted to the camera's view; set light.fit=scene or shadow.cascades=1"));
    checkDepthBias(s, issues);
    if (issues.errors.empty())
        warnOfSubstitutes(s, issues);

    issues.errors.insert(issues.errors.end(), issues.warnings.begin(), issues.warnings.end());
    return issues.errors;
}

void ensureValid(const Settings& settings)
{
    for (const SettingsIssue& issue : validate(settings)) {
        if (issue.severity == SettingsIssue::Severity::Error)
            throw SettingsError(issue.key, issue.message);
    }
}

} // namespace shadowlab
