#include "ShadowStorage.h"

#include "MomentMath.h"
#include "MomentsBlurPass.h"
#include "MomentsMap.h"
#include "MomentsPass.h"

#include <QElapsedTimer>

namespace shadowlab {

namespace {

// Moments storage: the moments pass into a filterable map of its own, then the blur within each
// view's tile and the mips. Every face is drawn and no offset applied: those are the depth
// map's cures for acne, which moments do not need.
class MomentsStorage final : public ShadowStorage {
public:
    explicit MomentsStorage(GlFunctions* gl) : m_gl(gl), m_map(gl), m_pass(gl), m_blur(gl) {}

    void ensure(const Settings& settings, ShadowTileGrid grid) override
    {
        m_map.ensureTiles(settings.map.size, grid.columns, grid.rows, settings.moments.format, settings.moments.mipmaps,
                          settings.moments.anisotropy);
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

    int draw(const GpuScene& scene, const LightFrame& light, const Settings& settings, const QRect& tile, double* blurWallMs) override
    {
        const int draws = m_pass.render(scene, light, settings, m_map, tile);
        // The view's moments blurred within its tile, and the mips of a map of one view (those
        // of several would mix the views, which settings refuse).
        QElapsedTimer blur;
        if (blurWallMs) {
            m_gl->glFinish();
            blur.start();
        }
        m_blur.render(m_map, settings.moments.blur, tile);
        if (blurWallMs) {
            m_gl->glFinish();
            *blurWallMs += double(blur.nsecsElapsed()) * 1e-6;
        }
        return draws;
    }

    const MomentsMap* momentsMap() const override { return &m_map; }

private:
    GlFunctions* m_gl;
    MomentsMap m_map;
    MomentsPass m_pass;
    MomentsBlurPass m_blur;
};

} // namespace

std::unique_ptr<ShadowStorage> makeMomentsStorage(GlFunctions* gl)
{
    return std::make_unique<MomentsStorage>(gl);
}

} // namespace shadowlab
