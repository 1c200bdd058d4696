#include "FramePlan.h"

#include "MomentMath.h"
#include "VirtualPages.h"

namespace shadowlab {

FramePlan planFrame(const Settings& settings, bool softwareDriver, bool reversedDepthSupported)
{
    FramePlan plan;
    plan.settings = settings;
    plan.technique = &shadowTechnique(settings.filter.mode);
    plan.tuning = RasteriserTuning::of(settings.rasteriser.profile, softwareDriver);
    plan.shadows = settings.shadow.enabled;
    plan.virtualMap = plan.shadows && settings.shadow.virtualMap;
    plan.moments = plan.technique->map == ShadowMapKind::Moments;
    plan.severalViews = usesShadowViews(settings);
    plan.lightWarp = usesLightWarp(settings);
    plan.grid = plan.virtualMap ? ShadowTileGrid{settings.shadow.virtualPool, settings.shadow.virtualPool} : shadowTileGrid(settings);
    plan.tileSize = plan.virtualMap ? kVirtualSlotTexels : settings.map.size;
    plan.reversedDepthWanted = plan.shadows && settings.map.format == DepthFormat::Depth32F && !plan.moments;
    plan.reversedDepth = plan.reversedDepthWanted && reversedDepthSupported;
    plan.slices = plan.tuning.depthSlices && slicesDepth(settings) ? settings.map.slices : 1;
    plan.earlyOut = plan.shadows && settings.filter.earlyOut && plan.technique->penumbraOnly;
    plan.depthRange = plan.earlyOut || (plan.shadows && plan.technique->searchesBlockers);
    plan.contactShadows = plan.shadows && settings.contact.enabled;
    plan.visibleDepth = usesVisibleDepth(settings);
    plan.tapsPerLookup = plan.shadows ? plan.technique->taps(settings.filter) : 0;
    plan.lookupBlurRadius = plan.shadows && plan.moments ? lookupBlurRadius(settings) : 0;
    if (const int radius = plan.lookupBlurRadius)
        plan.tapsPerLookup = (radius + 1) * (radius + 1);       // the blur's bilinear reads (moments_common.glsl)
    plan.cache = plan.shadows ? settings.shadow.cache : ShadowCachePolicy::Off;
    return plan;
}

} // namespace shadowlab
