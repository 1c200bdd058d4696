#include "SettingRelevance.h"

#include "SettingsKeys.h"
#include "ShadowReach.h"
#include "ShadowTechnique.h"
#include "ShadowViews.h"

#include <QStringList>

namespace shadowlab {

namespace {

// The techniques (by key) that read the parameter `key`.
QStringList readersOf(const QString& key)
{
    QStringList readers;
    for (const ShadowTechnique& t : shadowTechniques()) {
        if (t.parameters.contains(key))
            readers << t.key;
    }
    return readers;
}

QStringList momentTechniques()
{
    QStringList moments;
    for (const ShadowTechnique& t : shadowTechniques()) {
        if (t.map == ShadowMapKind::Moments)
            moments << t.key;
    }
    return moments;
}

QString techniqueKey(const Settings& s)
{
    return shadowTechnique(s.filter.mode).key;
}

// What a moment technique leaves unread: the depth map's cures for acne, and where its blur runs.
QString ignoredWithMoments(const Settings& s, const QString& key)
{
    if (key == u"moments.blur_at" && s.moments.blur <= 1)
        return QStringLiteral("moments.blur=%1 blurs nothing; a width of 3 or more runs where this says.").arg(s.moments.blur);
    if (key == u"moments.blur_at" && (s.moments.mipmaps || s.moments.anisotropy > 1))
        return QStringLiteral("The blur runs as a pass over the map while moments.mipmaps is on or moments.anisotropy is above 1.");
    if (key == u"bias.skip_floors" && !shadowTechnique(s.filter.mode).coverage && !tapReachTexels(s))
        return QStringLiteral("%1 stores four moments and no coverage beside them, so every receiver must be in its map, and %2: floors "
                              "go into the whole map. vsm, evsm2 and esm leave floors out; evsm4 and msm draw them around the casters.")
            .arg(techniqueKey(s),
                 shadowTechnique(s.filter.mode).farPlaneReadsLit ? QStringLiteral("with moments.mipmaps or moments.anisotropy above 1 a lookup may read anywhere")
                                                                 : QStringLiteral("it reads the far plane's moments near it as shadow"));
    if (key == u"bias.cull_front" || key == u"bias.polygon_factor" || key == u"bias.polygon_units" || key == u"bias.footprint" || key == u"bias.receiver_plane")
        return QStringLiteral("%1 draws every face into a moments map with no offset and compares no depths: filter.moment_bias holds "
                              "its acne off. Depth-compare filters read it.")
            .arg(techniqueKey(s));
    return {};
}

} // namespace

QString ignoredBecause(const Settings& s, const QString& key)
{
    const bool moments = shadowTechnique(s.filter.mode).map == ShadowMapKind::Moments;
    const bool directional = s.light.type == LightType::Directional;
    const bool shadowKey = key.startsWith(u"map.") || key.startsWith(u"bias.") || key.startsWith(u"filter.") || key.startsWith(u"moments.")
                           || key.startsWith(u"contact.") || (key.startsWith(u"shadow.") && key != u"shadow.enabled");
    if (!s.shadow.enabled && (shadowKey || key == u"shading.shadow_only" || key == u"shading.texel_density"))
        return QStringLiteral("Shadows are off: turn on shadow.enabled to use it.");

    // The technique's own parameters, and the moment maps' settings.
    for (const TechniqueParameter& parameter : techniqueParameters()) {
        if (parameter.key == key && !usesParameter(s.filter, key))
            return QStringLiteral("%1 does not read it; %2 %3.")
                .arg(techniqueKey(s), readersOf(key).join(QStringLiteral(", ")), readersOf(key).size() == 1 ? QStringLiteral("does") : QStringLiteral("do"));
    }
    if (key.startsWith(u"moments.") && !moments)
        return QStringLiteral("%1 stores depth, not moments; the moment filters (%2) read it.").arg(techniqueKey(s), momentTechniques().join(QStringLiteral(", ")));
    if (moments) {
        if (const QString why = ignoredWithMoments(s, key); !why.isEmpty())
            return why;
    }
    if (key == u"bias.receiver_plane" && (s.filter.mode == FilterMode::Hard || s.filter.mode == FilterMode::HwBilinear))
        return QStringLiteral("%1 takes one lookup, with no taps to place on the receiver's plane; the wide filters (pcf, poisson, pcss, …) read it.")
            .arg(techniqueKey(s));
    if (key == u"filter.early_out" && !shadowTechnique(s.filter.mode).penumbraOnly) {
        QStringList skipping;
        for (const ShadowTechnique& t : shadowTechniques()) {
            if (t.penumbraOnly)
                skipping << t.key;
        }
        return QStringLiteral("Only %1 skip their taps outside penumbrae; %2 does not.").arg(skipping.join(QStringLiteral(", ")), techniqueKey(s));
    }
    if (key == u"map.slice_coverage" && s.map.slices <= 1)
        return QStringLiteral("Read only where a map is drawn into slices; set map.slices above 1.");
    if ((key == u"map.slices" || key == u"map.slice_coverage") && s.shadow.cache != ShadowCachePolicy::Off)
        return QStringLiteral("A cached map starts each frame from its copy, which writes every texel as a clear does, so there is nothing for "
                              "slices to save; set shadow.cache to off to draw into slices.");
    if ((key == u"map.slices" || key == u"map.slice_coverage") && (moments || !slicesDepth(s) || s.map.format != DepthFormat::Depth24))
        return QStringLiteral("Only one plain ortho depth24 map is drawn into slices; perspective and warped maps, cascades, virtual pages, "
                              "depth32f and moments clear every time.");
    if (key == u"shadow.cache_interval" && s.shadow.cache != ShadowCachePolicy::EveryN)
        return QStringLiteral("Only shadow.cache=every-n redraws moving casters at an interval; set shadow.cache to every-n.");
    if ((key == u"map.slices" || key == u"map.slice_coverage") && s.rasteriser.profile == RasteriserProfile::Hardware)
        return QStringLiteral("Depth slices save a software rasteriser its clears; with rasteriser.profile=hardware every draw clears. "
                              "Set rasteriser.profile to software (or auto, on a software rasteriser).");

    // The light's kinds of map.
    if (key == u"light.warp" && !directional)
        return QStringLiteral("Only a directional light's map is warped; set light.type to directional.");
    if (key == u"light.warp_scale" && (!directional || s.light.warp != LightWarp::Lispsm))
        return QStringLiteral("Only a lispsm warp reads it: set light.warp to lispsm (directional lights).");
    if (key == u"light.stabilize" && s.light.fit == LightFit::Manual)
        return QStringLiteral("A hand-set volume (light.fit manual) is not moved, so there is nothing to snap; set light.fit to scene.");
    if (key == u"shadow.cascades" && !directional)
        return QStringLiteral("Cascades split a directional light's map; a %1 light has %2.")
            .arg(toString(s.light.type), s.light.type == LightType::Point ? QStringLiteral("six cube faces") : QStringLiteral("one perspective map"));
    if (key == u"shadow.virtual" && !directional)
        return QStringLiteral("Virtual shadow maps are for a directional light; set light.type to directional.");
    if (key == u"shadow.cascades" && s.shadow.virtualMap)
        return QStringLiteral("A virtual map replaces cascades; turn off shadow.virtual to use them.");
    const bool cascades = directional && s.shadow.cascades > 1 && !s.shadow.virtualMap;
    if ((key == u"shadow.split" || key == u"shadow.split_lambda" || key == u"shadow.distance" || key == u"shadow.blend" || key == u"shadow.depth_fit")
        && !cascades)
        return s.shadow.virtualMap ? QStringLiteral("A virtual map replaces cascades; turn off shadow.virtual to split the view into cascades.")
               : directional ? QStringLiteral("With one map (shadow.cascades 1) there is no depth range to split; set shadow.cascades to 2 or more.")
                           : QStringLiteral("Cascades split a directional light's map; set light.type to directional and shadow.cascades to 2 or more.");
    if (key == u"shadow.split_lambda" && s.shadow.split != CascadeSplit::Practical)
        return QStringLiteral("Only the practical split blends uniform and logarithmic; set shadow.split to practical.");
    if ((key == u"shadow.virtual_pool" || key == u"shadow.virtual_levels" || key == u"shadow.virtual_lod_bias") && !(directional && s.shadow.virtualMap))
        return QStringLiteral("Virtual maps are off: turn on shadow.virtual (directional lights) to use it.");
    if ((key == u"contact.length" || key == u"contact.steps" || key == u"contact.thickness") && !s.contact.enabled)
        return QStringLiteral("Contact shadows are off: turn on contact.enabled to use it.");
    return {};
}

} // namespace shadowlab
