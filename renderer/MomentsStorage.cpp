#include "ShadowStorage.h"

#include "CachedCopy.h"
#include "CasterTexels.h"
#include "MomentMath.h"
#include "MomentsBlurPass.h"
#include "MomentsMap.h"
#include "MomentsPass.h"
#include "ShadowCache.h"
#include "ShadowReach.h"
#include "ShadowTechnique.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cmath>

#include <utility>

namespace shadowlab {

namespace {

// Moments storage: the moments pass into a filterable map of its own, then the blur within each
// view's tile and the mips. Every face is drawn and no offset applied: those are the depth
// map's cures for acne, which moments do not need.
class MomentsStorage final : public ShadowStorage {
public:
    explicit MomentsStorage(GlFunctions* gl) : m_gl(gl), m_map(gl), m_pass(gl), m_blur(gl), m_copy(gl) {}

    void ensure(const FramePlan& plan) override
    {
        const Settings& settings = plan.settings;
        m_channels = plan.technique->momentChannels == 3 ? 4 : plan.technique->momentChannels;     // RGB takes RGBA
        m_pass.clearWrittenOnly(plan.tuning.clearsWrittenMoments);
        m_map.ensureTiles(plan.tileSize, plan.grid.columns, plan.grid.rows, settings.moments.format, storedChannels(plan), settings.moments.mipmaps,
                          settings.moments.anisotropy, mapBlurWidth(settings) > 1);
        // The copy holds the moments before the blur, with the pass's depth, so the moving
        // casters are drawn over it as over the still ones, and the blur runs after both.
        if (keepsViews(plan.cache))
            m_copy.ensure(QSize(m_map.width(), m_map.height()), m_map.depthTexture(), m_map.texture());
        else
            m_copy.release();
    }

    ShadowStorageKey key(const FramePlan& plan, int sceneGeneration) const override
    {
        const Settings& settings = plan.settings;
        const MomentWarp warp = momentWarp(settings);
        ShadowStorageKey key = commonStorageKey(plan, sceneGeneration);
        key.moments = true;
        key.momentTechnique = settings.filter.mode;
        key.momentFormat = settings.moments.format;
        key.momentChannels = storedChannels(plan);
        key.exponentPositive = warp.positive;
        key.exponentNegative = warp.negative;
        key.blur = mapBlurWidth(settings);     // a blur in the lookup leaves the map as it is ...
        key.mipmaps = settings.moments.mipmaps;
        key.skipFloors = leavesOutFloors(plan);
        // ... but for the floors drawn around the casters, as far as it and the normal offset reach.
        if (MomentsPass::drawsFloorsAroundCasters(settings))
            key.floorReach = *tapReachTexels(settings) + lookupShiftTexels(settings);
        return key;
    }

    bool cullsFrontFaces(const FramePlan&) const override { return false; }
    // Floors cast nothing where they are left out or drawn only around the casters.
    bool leavesOutFloors(const FramePlan& plan) const override
    {
        return MomentsPass::leavesOutFloors(plan.settings) || MomentsPass::drawsFloorsAroundCasters(plan.settings);
    }

    void clear(const LightFrame& light, const FramePlan& plan, const QRect& tile) override
    {
        m_pass.clear(light, plan.settings, m_map, tile);
        m_blur.render(m_map, 0, tile);     // no blur: only the mips, which would keep what was cleared
    }

    int draw(const GpuScene& scene, const LightFrame& light, const FramePlan& plan, const QRect& tile, const CasterTexels* texels,
             double* blurWallMs) override
    {
        const MomentsPass::Area area = drawnArea(light, plan, tile, texels);
        const int draws = m_pass.render(scene, light, plan.settings, m_map, tile, area);
        prefilter(plan, tile, area.drawn, blurWallMs);
        return draws;
    }

    CachedDraw drawCached(const GpuScene& scene, const LightFrame& light, const FramePlan& plan, const QRect& tile, const CasterTexels* texels,
                          double* blurWallMs, CacheStep step, const std::vector<QRect>&) override
    {
        const Settings& settings = plan.settings;
        const MomentsPass::Area area = drawnArea(light, plan, tile, texels);
        CachedDraw drawn;
        if (step == CacheStep::Refresh) {
            drawn.draws = m_pass.render(scene, light, settings, m_map, tile, area, CasterSet::Still);
            m_copy.save(m_map.framebuffer(), tile);
        } else {
            // The whole tile: the blur reads the still casters' moments unblurred around the
            // moving ones, and the map holds them blurred.
            m_copy.restore(m_map.framebuffer(), tile);
            m_map.written().drew(tile);
        }
        m_counts.copiedTexels += qint64(tile.width()) * tile.height();
        drawn.movingDraws = m_pass.render(scene, light, settings, m_map, tile, area, CasterSet::Moving, false);
        drawn.draws += drawn.movingDraws;
        // The whole area blurred again: the moving casters' moments spread by the blur's radius,
        // and the still casters' must be read unblurred to blur the texels where both meet.
        prefilter(plan, tile, area.drawn, blurWallMs);
        return drawn;
    }

    qint64 cacheBytes() const override { return m_copy.bytes(); }

private:
    // Where in `tile` the pass draws: around its casters (core/CasterTexels.h), and, where floors
    // are drawn only around them (MomentsPass::drawsFloorsAroundCasters), floors as far again
    // around each caster as a lookup beside it reads: a receiver within its reach of one reads
    // up to twice that from it. The rest holds the far plane's moments, which a receiver's
    // footprint there, floors and far plane both behind it, reads as lit.
    // Each caster's rectangle is a piece, so casters far apart clear and draw only their own
    // texels, and a floor is drawn once in each.
    MomentsPass::Area drawnArea(const LightFrame& light, const FramePlan& plan, const QRect& tile, const CasterTexels* texels) const
    {
        const std::optional<QRect> casters = inTile(texels, tile);
        if (!casters || casters->isEmpty())
            return {casters, {}};
        int margin = 0;
        const bool floors = MomentsPass::drawsFloorsAroundCasters(plan.settings);
        if (floors) {
            // A cached copy holds the floors for wherever the moving casters go next.
            const std::optional<double> reach = lookupReachTexels(plan.settings, light);
            if (!reach || keepsViews(plan.cache))
                return {};      // the whole tile, floors everywhere
            margin = int(std::min(std::ceil(2.0 * *reach), double(std::max(m_map.width(), m_map.height()))));
        }
        // The pieces are the view's own texels: found within the tile moved there, then moved into it.
        const QRect whole = tile.isEmpty() ? QRect(0, 0, m_map.width(), m_map.height()) : tile;
        MomentsPass::Area area{.drawn = QRect(), .pieces = aroundCasters(*texels, margin, whole.translated(-whole.topLeft()), MomentsPass::kMostPieces),
                               .floorsInPieces = floors};
        for (QRect& piece : area.pieces) {
            piece.translate(whole.topLeft());
            *area.drawn |= piece;
        }
        return area;
    }

    void prefilter(const FramePlan& plan, const QRect& tile, const std::optional<QRect>& area, double* blurWallMs)
    {
        const Settings& settings = plan.settings;
        // The view's moments blurred within its tile, and the mips of a map of one view (those
        // of several would mix the views, which settings refuse).
        QElapsedTimer blur;
        if (blurWallMs) {
            m_gl->glFinish();
            blur.start();
        }
        const int width = mapBlurWidth(settings);
        m_blur.render(m_map, width, tile, area);
        m_map.written().drew(m_blur.lastWritten());     // the blur spreads the casters by its radius
        countBlur(width);
        if (blurWallMs) {
            m_gl->glFinish();
            *blurWallMs += double(blur.nsecsElapsed()) * 1e-6;
        }
    }

public:
    const MomentsMap* momentsMap() const override { return &m_map; }

    Counts takeCounts() override
    {
        Counts counts = std::exchange(m_counts, Counts{});
        counts.clearedTexels = m_pass.takeClearedTexels();
        return counts;
    }

    // As a GPU stores them: the technique's channels, whatever a software rasteriser widens.
    qint64 bytes() const override { return m_map.bytes(m_channels); }

private:
    // Two moments in four channels where the rasteriser profile says so (RasteriserTuning).
    static int storedChannels(const FramePlan& plan)
    {
        const int channels = plan.technique->momentChannels;
        return channels == 2 && plan.tuning.wideTwoChannelMoments ? 4 : channels;
    }

    void countBlur(int width)
    {
        const qint64 texels = m_blur.lastTexels();
        const qint64 texel = qint64(m_channels) * (m_map.format() == MomentFormat::Rgba16F ? 2 : 4);
        const int taps = std::max(1, width | 1);
        m_counts.blurTexels += texels;
        m_counts.blurBytes += texels * texel * (taps + 1);
    }

    GlFunctions* m_gl;
    Counts m_counts;
    MomentsMap m_map;
    MomentsPass m_pass;
    MomentsBlurPass m_blur;
    CachedCopy m_copy;
    int m_channels = 4;         // the technique's as a GPU stores them, which the counts use
};

} // namespace

std::unique_ptr<ShadowStorage> makeMomentsStorage(GlFunctions* gl)
{
    return std::make_unique<MomentsStorage>(gl);
}

} // namespace shadowlab
