#pragma once

#include "Settings.h"

#include <QString>

namespace shadowlab {

// Whether `rendererString` (GL_RENDERER and friends) names a software rasteriser, whose "GPU"
// times are CPU times and whose timer queries miss its deferred work.
bool isSoftwareRenderer(const QString& rendererString);

// The optimisations that pay on one kind of rasteriser, in one place, and which of them are on.
// Each was measured on a software rasteriser (llvmpipe, docs/performance.md), where the whole
// pipeline runs on the CPU and a cleared texel or a byte read costs as much as a caster's
// fragment. None has been measured on a GPU, so the hardware profile runs the plain path until
// GPU figures show a gain (scripts/gpu-bundle.sh benches both profiles). Frames are the same
// pixels whichever are on: the tests render both profiles and compare.
struct RasteriserTuning {
    bool software = false;              // the profile, resolved: tuned for a software rasteriser
    // The shadow reach (core/ShadowReach.h): the lit pass shades the receivers that no caster can
    // reach without a lookup, through stencil masks and its draw orders (LitPass).
    bool skipsOutOfReach = false;
    // Depth slices (map.slices): a plain depth24 map, or a point light's faces, cleared once in n
    // passes (DepthSlices::beginDraw, ShadowMap::beginPass).
    bool depthSlices = false;
    // Two moments (vsm, evsm2) stored in RGBA rather than RG: llvmpipe blurs a 2048² RGBA32F map
    // faster than an RG32F one, where a GPU reads half the bytes from RG.
    bool wideTwoChannelMoments = false;
    // A moments map of one view cleared only where its last passes wrote, not whole: llvmpipe
    // clears a surface texel by texel, where a GPU clears a whole one fastest. Pays where the
    // casters cover less than the map: with coverage (vsm, evsm2, esm), which leaves floors out,
    // and for evsm4 and msm, which draw them only around the casters.
    bool clearsWrittenMoments = false;
    // A virtual map's page requests deduplicated on the CPU from the read-back, rather than by a
    // point per requesting pixel on the GPU, which costs a software rasteriser six times as much.
    bool cpuVirtualRequests = false;
    // The min/max depth mip (DepthRangePass, for pcss's and dpcf's blocker search and
    // filter.early_out) rebuilt at its finest level only over the texels the map holds casters
    // in now or held them in at the last build, not over the whole map: llvmpipe reads every texel
    // of a 2048² map for it at several times a shadow pass's cost (a point light's six faces:
    // 34 ms), where a GPU reduces a map in microseconds.
    bool rangesWrittenTexels = false;

    // `profile` resolved against the driver: auto is software where `rendererString` names a
    // software rasteriser.
    static RasteriserTuning of(RasteriserProfile profile, const QString& rendererString);
    static RasteriserTuning of(RasteriserProfile profile, bool softwareDriver);

    bool operator==(const RasteriserTuning&) const = default;
};

// "software" or "hardware": the profile a frame was drawn under, for benchmarks and reports.
QString profileName(const RasteriserTuning& tuning);

// A software rasteriser (llvmpipe) allocates its binning memory per frame, in proportion to the
// target's tiles, and frees it when the frame is done; glibc hands the freed top of its heaps
// back to the kernel, so every frame pays the page faults again. Its textures and a
// measurement's read-backs come and go the same way. Where `rendererString` names a software
// rasteriser, blocks up to 256 MiB come from the heap rather than fresh mappings, and up to
// 256 MiB freed stays with the process. Process-wide, so it is set up with the application's
// first context (HeadlessRenderer, the window's first view), once; a GPU driver's process is
// left as it is.
void retainFreedHeapForSoftwareRasteriser(const QString& rendererString);

} // namespace shadowlab
