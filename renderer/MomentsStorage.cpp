#include "ShadowStorage.h"

#include "MomentMath.h"
#include "MomentsBlurPass.h"
#include "MomentsMap.h"
#include "MomentsPass.h"
#include "ShadowTechnique.h"

#include <QElapsedTimer>

#include <utility>

namespace shadowlab {

namespace {

// Moments storage: the moments pass into a filterable map of its own, then the blur within each
// view's tile and the mips. Every face is drawn and no offset applied: those are the depth
// map's cures for acne, which moments do not need.
class MomentsStorage final : public ShadowStorage {
public:
    MomentsStorage(GlFunctions* gl, bool wideTwoChannels) : m_gl(gl), m_map(gl), m_pass(gl), m_blur(gl), m_wideTwoChannels(wideTwoChannels) {}

    void ensure(const Settings& settings, ShadowTileGrid grid) override
    {
        const int channels = shadowTechnique(settings.filter.mode).momentChannels;
        m_channels = channels;
        m_map.ensureTiles(settings.map.size, grid.columns, grid.rows, settings.moments.format, channels == 2 && m_wideTwoChannels ? 4 : channels,
                          settings.moments.mipmaps, settings.moments.anisotropy);
    }

    ShadowStorageKey key(const Settings& settings, int sceneGeneration, bool reversedDepth, ShadowTileGrid grid) const override
    {
        const MomentWarp warp = momentWarp(settings);
        ShadowStorageKey key = commonStorageKey(settings, sceneGeneration, reversedDepth, grid);
        key.moments = true;
        key.momentTechnique = settings.filter.mode;
        key.momentFormat = settings.moments.format;
        key.exponentPositive = warp.positive;
        key.exponentNegative = warp.negative;
        key.blur = settings.moments.blur;
        key.mipmaps = settings.moments.mipmaps;
        return key;
    }

    bool cullsFrontFaces(const Settings&) const override { return false; }
    // The moments hold every surface, floors too (MomentsPass::render).
    bool leavesOutFloors(const Settings&) const override { return false; }

    void clear(const LightFrame& light, const Settings& settings, const QRect& tile) override
    {
        m_pass.clear(light, settings, m_map, tile);
        m_blur.render(m_map, 0, tile);     // no blur: only the mips, which would keep what was cleared
    }

    int draw(const GpuScene& scene, const LightFrame& light, const Settings& settings, const QRect& tile, const CasterTexels* texels,
             double* blurWallMs) override
    {
        const int draws = m_pass.render(scene, light, settings, m_map, tile, inTile(texels, tile));
        // The view's moments blurred within its tile, and the mips of a map of one view (those
        // of several would mix the views, which settings refuse).
        QElapsedTimer blur;
        if (blurWallMs) {
            m_gl->glFinish();
            blur.start();
        }
        m_blur.render(m_map, settings.moments.blur, tile, inTile(texels, tile));
        m_map.written().drew(m_blur.lastWritten());     // the blur spreads the casters by its radius
        countBlur(settings.moments.blur);
        if (blurWallMs) {
            m_gl->glFinish();
            *blurWallMs += double(blur.nsecsElapsed()) * 1e-6;
        }
        return draws;
    }

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
    bool m_wideTwoChannels;     // two moments in RGBA (Renderer::setWideTwoChannelMoments)
    int m_channels = 4;         // the technique's, which the counts use
};

} // namespace

std::unique_ptr<ShadowStorage> makeMomentsStorage(GlFunctions* gl, bool wideTwoChannels)
{
    return std::make_unique<MomentsStorage>(gl, wideTwoChannels);
}

} // namespace shadowlab
