#pragma once

#include "CasterTexels.h"
#include "FramePlan.h"
#include "GpuScene.h"
#include "LightMath.h"
#include "Settings.h"
#include "ShadowViews.h"

#include <QRect>

#include <memory>
#include <optional>
#include <vector>

namespace shadowlab {

class DepthPass;
class MomentsMap;
class ShadowMap;

// Everything the stored views depend on but their volumes; while it and the volumes stay
// equal, the shadow pass is skipped.
struct ShadowStorageKey {
    int sceneGeneration = 0;
    bool reversedDepth = false;
    int mapSize = 0;
    DepthFormat format = DepthFormat::Depth24;
    int columns = 1;
    int rows = 1;
    bool cutouts = true;            // shadow.cutouts: cut-out casters drawn through their mask
    // What shadow.cache keeps: nothing (0: drawn again when a caster moves), a copy of each
    // view's still casters (1), or a virtual map's pages (2).
    int cache = 0;
    // The depth pass's raster state against acne (depth storage only).
    bool cullFront = false;
    bool skipFloors = false;        // bias.skip_floors: floors the light is above left out (or, in a
                                    // moments map without coverage, drawn only around the casters)
    double polygonFactor = 0.0;
    double polygonUnits = 0.0;
    int slices = 1;                 // FramePlan::slices: the lit pass reads the map through its slice
    // What the moments pass stores and how it is prefiltered (moments storage only).
    bool moments = false;
    FilterMode momentTechnique = FilterMode::Hard;
    MomentFormat momentFormat = MomentFormat::Rgba32F;
    int momentChannels = 0;         // stored: the technique's, or four where the profile widens two
    double exponentPositive = 0.0;
    double exponentNegative = 0.0;
    int blur = 0;
    bool mipmaps = false;
    // How far around the casters a moments map without coverage draws its floors: the lookup's
    // reach (MomentsPass::drawsFloorsAroundCasters), its blur and normal offset; 0 elsewhere.
    double floorReach = 0.0;

    bool operator==(const ShadowStorageKey&) const = default;
};

// Where `texels` says the casters lie, moved into `tile`; nullopt without texels (anywhere).
inline std::optional<QRect> inTile(const CasterTexels* texels, const QRect& tile)
{
    return texels ? std::optional<QRect>(texels->drawn.translated(tile.topLeft())) : std::nullopt;
}

// What every storage's key holds: the scene, the depth convention, the map's size, format and tiles.
inline ShadowStorageKey commonStorageKey(const FramePlan& plan, int sceneGeneration)
{
    ShadowStorageKey key;
    key.sceneGeneration = sceneGeneration;
    key.reversedDepth = plan.reversedDepth;
    key.mapSize = plan.tileSize;
    key.format = plan.settings.map.format;
    key.columns = plan.grid.columns;
    key.rows = plan.grid.rows;
    key.cutouts = plan.settings.shadow.cutouts;
    key.cache = plan.cache == ShadowCachePolicy::Off ? 0 : plan.cache == ShadowCachePolicy::Pages ? 2 : 1;
    return key;
}

// Where a light's views are stored, each in its tile of the one map, and the passes that fill
// them: depth (the depth pass) or moments (the moments pass, then its blur and mips). The
// renderer and the light rig do not ask which: a technique's row names its storage
// (ShadowTechnique::map), and the storage answers.
class ShadowStorage {
public:
    virtual ~ShadowStorage() = default;

    // Textures for the views of `plan` in its tiles (the depth map itself is the renderer's,
    // shared by every storage: its texel grid is the one the lit pass looks up in).
    virtual void ensure(const FramePlan& plan) = 0;
    // What the stored views of `plan` depend on besides their volumes.
    virtual ShadowStorageKey key(const FramePlan& plan, int sceneGeneration) const = 0;
    // Whether the pass drawing `plan` culls front faces (bias.cull_front): where a flat
    // one-sided caster facing the light then casts nothing (core/ShadowReach.h).
    virtual bool cullsFrontFaces(const FramePlan& plan) const = 0;
    // Whether floors the light is above cast nothing (bias.skip_floors): the same for a floor.
    // A depth map leaves them out; a moments map leaves them out or draws them only around its
    // casters (renderer/MomentsPass.h).
    virtual bool leavesOutFloors(const FramePlan& plan) const = 0;
    // The whole map read lit (every tile), or one view's `tile` of it.
    virtual void clear(const LightFrame& light, const FramePlan& plan, const QRect& tile = QRect()) = 0;
    // Draws one view into its tile; returns the casters drawn. `texels`: where in the tile
    // (its own texels) the casters lie (core/CasterTexels.h); null: anywhere. `blurWallMs`,
    // when given, gets the wall time of a prefilter pass added (glFinish around it).
    virtual int draw(const GpuScene& scene, const LightFrame& light, const FramePlan& plan, const QRect& tile, const CasterTexels* texels,
                     double* blurWallMs) = 0;
    // shadow.cache's two draws of a view (renderer/ShadowCache.h), over a copy of the still
    // casters that the storage keeps beside its map: Refresh clears the tile, draws the still
    // casters, keeps a copy of the tile, then draws the moving casters over it; Restore copies
    // `areas` of the tile back (texels of the map; none: all of it), where the moving casters
    // were and are, and draws them over it. Either prefilters after, so the view holds what
    // draw() would have drawn. A storage may restore more than `areas` (a blurred one must).
    enum class CacheStep { Refresh, Restore };
    struct CachedDraw {
        int draws = 0;              // casters drawn, the moving ones included
        int movingDraws = 0;        // of which moving
    };
    virtual CachedDraw drawCached(const GpuScene& scene, const LightFrame& light, const FramePlan& plan, const QRect& tile, const CasterTexels* texels,
                                  double* blurWallMs, CacheStep step, const std::vector<QRect>& areas = {}) = 0;
    // Bytes of the copy kept for shadow.cache (0 without one).
    virtual qint64 cacheBytes() const = 0;

    // What its clears and prefilter did since the last call (and starts counting again).
    struct Counts {
        qint64 clearedTexels = 0;   // texels cleared (depth) or filled with the far plane's moments
        qint64 blurTexels = 0;      // texels the blur wrote, both axes
        qint64 blurBytes = 0;       // bytes the blur read and wrote
        qint64 copiedTexels = 0;    // texels shadow.cache copied to and from its copy
    };
    virtual Counts takeCounts() = 0;
    // Bytes of the textures a lookup or a pass of this storage uses.
    virtual qint64 bytes() const = 0;
    // The moments the lit pass reads; null for a storage of depth alone.
    virtual const MomentsMap* momentsMap() const { return nullptr; }
};

// The storage of each kind, built on first use: depth draws into the renderer's `map` with its
// `pass`; moments own their map and passes.
std::unique_ptr<ShadowStorage> makeDepthStorage(GlFunctions* gl, ShadowMap& map, DepthPass& pass);
std::unique_ptr<ShadowStorage> makeMomentsStorage(GlFunctions* gl);

} // namespace shadowlab
