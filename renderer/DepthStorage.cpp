#include "ShadowStorage.h"

#include "DepthPass.h"
#include "ShadowMap.h"

namespace shadowlab {

namespace {

// Depth storage: the depth pass into the renderer's depth map, with its raster state against
// acne (front-face culling, polygon offset).
class DepthStorage final : public ShadowStorage {
public:
    DepthStorage(ShadowMap& map, DepthPass& pass) : m_map(map), m_pass(pass) {}

    void ensure(const FramePlan&) override {}

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

    Counts takeCounts() override { return {.clearedTexels = m_pass.takeClearedTexels()}; }

    qint64 bytes() const override
    {
        // 24-bit depth is stored in 32 bits.
        return qint64(m_map.width()) * m_map.height() * 4;
    }

private:
    ShadowMap& m_map;
    DepthPass& m_pass;
};

} // namespace

std::unique_ptr<ShadowStorage> makeDepthStorage(ShadowMap& map, DepthPass& pass)
{
    return std::make_unique<DepthStorage>(map, pass);
}

} // namespace shadowlab
