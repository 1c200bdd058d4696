#include "ShadowStorage.h"

#include "CachedCopy.h"
#include "DepthPass.h"
#include "ShadowCache.h"
#include "ShadowMap.h"

namespace shadowlab {

namespace {

// Depth storage: the depth pass into the renderer's depth map, with its raster state against
// acne (front-face culling, polygon offset).
class DepthStorage final : public ShadowStorage {
public:
    DepthStorage(GlFunctions* gl, ShadowMap& map, DepthPass& pass) : m_map(map), m_pass(pass), m_copy(gl) {}

    void ensure(const FramePlan& plan) override
    {
        if (keepsViews(plan.cache))
            m_copy.ensure(QSize(m_map.width(), m_map.height()), m_map.texture(), 0);
        else
            m_copy.release();
    }

    ShadowStorageKey key(const FramePlan& plan, int sceneGeneration) const override
    {
        const Settings& settings = plan.settings;
        ShadowStorageKey key = commonStorageKey(plan, sceneGeneration);
        key.cullFront = settings.bias.cullFront;
        key.skipFloors = settings.bias.skipFloors;
        key.polygonFactor = settings.bias.polygonFactor;
        key.polygonUnits = settings.bias.polygonUnits;
        key.slices = plan.slices;
        return key;
    }

    bool cullsFrontFaces(const FramePlan& plan) const override { return plan.settings.bias.cullFront; }
    bool leavesOutFloors(const FramePlan& plan) const override { return plan.settings.bias.skipFloors; }

    void clear(const LightFrame& light, const FramePlan&, const QRect& tile) override
    {
        if (tile.isEmpty())
            m_pass.clear(m_map, light.reversedDepth);
        else
            m_pass.clearTile(m_map, light.reversedDepth, tile);
    }

    int draw(const GpuScene& scene, const LightFrame& light, const FramePlan& plan, const QRect& tile, const CasterTexels* texels, double*) override
    {
        return m_pass.renderTile(scene, light, plan.settings.bias, m_map, tile, inTile(texels, tile), plan.settings.shadow.cutouts, plan.slices);
    }

    CachedDraw drawCached(const GpuScene& scene, const LightFrame& light, const FramePlan& plan, const QRect& tile, const CasterTexels* texels, double*,
                          CacheStep step, const std::vector<QRect>& areas) override
    {
        const BiasSettings& bias = plan.settings.bias;
        const bool cutouts = plan.settings.shadow.cutouts;
        CachedDraw drawn;
        // Outside the restored areas nothing moved; the moving casters write only within them.
        const std::optional<QRect> over = inTile(texels, tile);
        if (step == CacheStep::Refresh) {
            drawn.draws = m_pass.renderTile(scene, light, bias, m_map, tile, over, cutouts, 1, CasterSet::Still);
            m_copy.save(m_map.framebuffer(), tile);
            m_copiedTexels += qint64(tile.width()) * tile.height();
        } else {
            for (const QRect& area : areas.empty() ? std::vector<QRect>{tile} : areas) {
                const QRect copied = area & tile;
                m_copy.restore(m_map.framebuffer(), copied);
                m_map.written().drew(copied);
                m_copiedTexels += qint64(copied.width()) * copied.height();
            }
        }
        drawn.movingDraws = m_pass.drawOver(scene, light, bias, m_map, tile, over, cutouts, CasterSet::Moving);
        drawn.draws += drawn.movingDraws;
        return drawn;
    }

    qint64 cacheBytes() const override { return m_copy.bytes(); }

    Counts takeCounts() override
    {
        return {.clearedTexels = m_pass.takeClearedTexels(), .copiedTexels = std::exchange(m_copiedTexels, 0)};
    }

    qint64 bytes() const override
    {
        // 24-bit depth is stored in 32 bits.
        return qint64(m_map.width()) * m_map.height() * 4;
    }

private:
    ShadowMap& m_map;
    DepthPass& m_pass;
    CachedCopy m_copy;
    qint64 m_copiedTexels = 0;
};

} // namespace

std::unique_ptr<ShadowStorage> makeDepthStorage(GlFunctions* gl, ShadowMap& map, DepthPass& pass)
{
    return std::make_unique<DepthStorage>(gl, map, pass);
}

} // namespace shadowlab
