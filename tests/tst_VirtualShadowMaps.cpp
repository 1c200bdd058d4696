// Virtual shadow maps (shadow.virtual): the clipmap's layout and page cache as pure data (pages
// on a grid the camera cannot move, least-recently-used slots, coarsening when the pool is too
// small), and on GL against the Embree reference: the shadows where the ray tracer puts them on
// every preset from overhead to grazing light and on two models, a texel of at most a pixel nearly everywhere, a
// still frame that draws no page, a camera move that draws only the pages it newly sees, a
// light move that draws them all, and a pool too small that coarsens with a count, not holes.
#include "Application.h"
#include "RasteriserTuning.h"
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "Measurement.h"
#include "ReferenceAgreement.h"
#include "SceneLibrary.h"
#include "SceneNames.h"
#include "SettingsKeys.h"
#include "TestFiles.h"
#include "TexelDensity.h"
#include "VirtualPages.h"
#include "VirtualPoolPicture.h"

#include <glm/trigonometric.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace shadowlab;

namespace {

using probe::Agreement;
using probe::fromAngles;
using probe::describe;

QString describe(const VirtualMapStats& v)
{
    return QString("%1 requested, %2 resident, %3 drawn, %4 coarsened by up to %5 levels, %6 overflow")
        .arg(v.requested).arg(v.resident).arg(v.drawn).arg(v.coarsened).arg(v.levelsCoarsened).arg(v.overflow);
}

Bounds box(glm::dvec3 min, glm::dvec3 max)
{
    Bounds b;
    b.extend(min);
    b.extend(max);
    return b;
}

LightSettings lightFrom(glm::dvec3 direction)
{
    LightSettings light;
    light.target = glm::dvec3(0.0);
    light.position = -direction * 50.0;
    return light;
}

// Misclassified pixels more than two pixels from every edge of the reference's shadow: what no
// texel of about a pixel explains (acne, leaks), where an edge a texel off, or a 3 x 3 filter's
// spread of it, is not.
int misclassifiedOffEdges(const VisibilityBuffer& buffer, const std::vector<float>& hard)
{
    const int w = buffer.size.width(), h = buffer.size.height();
    const auto shadowed = [&](int x, int y) { return hard[std::size_t(y * w + x)] < 0.5f; };
    int count = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int i = y * w + x;
            if (buffer.mask(i) != VisibilityBuffer::FacingLight || std::abs(buffer.visibility(i) - hard[std::size_t(i)]) <= 0.5f)
                continue;
            bool nearEdge = false;
            for (int ny = std::max(y - 2, 0); ny <= std::min(y + 2, h - 1) && !nearEdge; ++ny)
                for (int nx = std::max(x - 2, 0); nx <= std::min(x + 2, w - 1) && !nearEdge; ++nx)
                    nearEdge = shadowed(nx, ny) != shadowed(x, y);
            count += !nearEdge;
        }
    }
    return count;
}

Settings virtualSettings(const QString& scene)
{
    Settings s = presetSettings(scene);
    s.shadow.virtualMap = true;
    s.shadow.cascades = 1;
    s.filter.earlyOut = false;
    return s;
}

} // namespace

class TestVirtualShadowMaps : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private Q_SLOTS:
    void initTestCase() { m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase() { m_headless.reset(); }

    // The coarsest window holds the whole scene, depth spans it, and each level halves the texel,
    // for boxes of every size and light directions from overhead to grazing.
    void layoutCoversTheScene_data()
    {
        QTest::addColumn<double>("size");
        QTest::addColumn<double>("elevation");
        for (double size : {1e-3, 1.0, 2000.0, 1e6}) {
            for (double elevation : {90.0, 45.0, 3.0})
                QTest::newRow(qPrintable(QString("size %1 el %2").arg(size).arg(elevation))) << size << elevation;
        }
    }
    void layoutCoversTheScene()
    {
        QFETCH(double, size);
        QFETCH(double, elevation);
        const Bounds scene = box(glm::dvec3(-size, 0.0, -0.5 * size) + 3.0 * size, glm::dvec3(size, 0.2 * size, 0.5 * size) + 3.0 * size);
        LightSettings light = lightFrom(-fromAngles(30.0, elevation));
        light.target = scene.center();
        light.position = light.target + fromAngles(30.0, elevation) * 10.0 * size;
        for (int levels : {1, 8, 16}) {
            const VirtualLayout layout = virtualLayout(light, scene, levels);
            QCOMPARE(layout.levels, levels);
            QVERIFY(std::isfinite(layout.finestTexel) && layout.finestTexel > 0.0);
            QCOMPARE(layout.texel(1), 2.0 * layout.texel(0));
            const double coarsest = 2.0 * layout.pageWorld(levels - 1);
            QVERIFY2(std::abs(coarsest - layout.coarsest.width()) <= 1e-9 * coarsest, qPrintable(QString::number(coarsest)));
            for (const glm::dvec3& corner : scene.corners()) {
                const glm::dvec3 p = glm::dvec3(layout.view * glm::dvec4(corner, 1.0));
                QVERIFY(p.x > layout.coarsest.left && p.x < layout.coarsest.right);
                QVERIFY(p.y > layout.coarsest.bottom && p.y < layout.coarsest.top);
                QVERIFY(-p.z > layout.coarsest.nearPlane && -p.z < layout.coarsest.farPlane);
            }
            // The coarsest window is the scene's, wherever the camera is; finer ones follow it in
            // whole pages, and stay finite for a camera far away.
            for (const glm::dvec3 camera : {scene.center(), scene.max * 1.5, glm::dvec3(1e7)}) {
                const std::vector<glm::ivec2> windows = virtualWindows(layout, camera);
                QCOMPARE(int(windows.size()), levels);
                QCOMPARE(windows.back(), glm::ivec2(-kVirtualLevelPages / 2));
            }
        }
    }

    // A page's volume is its square on the grid and a border of kVirtualPageBorder texels, and
    // neighbouring pages meet exactly.
    void pagesTileTheGrid()
    {
        const VirtualLayout layout = virtualLayout(lightFrom(glm::normalize(glm::dvec3(0.3, -1.0, 0.2))), box(glm::dvec3(-10), glm::dvec3(10)), 6);
        for (int level : {0, 3, 5}) {
            const LightVolume a = virtualPageVolume(layout, {level, -3, 7});
            const LightVolume b = virtualPageVolume(layout, {level, -2, 7});
            const double border = kVirtualPageBorder * layout.texel(level);
            QVERIFY(std::abs((a.right - border) - (b.left + border)) < 1e-12 * layout.coarsest.width());
            QVERIFY(std::abs(a.width() - kVirtualSlotTexels * layout.texel(level)) < 1e-9 * a.width());
            QCOMPARE(a.nearPlane, layout.coarsest.nearPlane);
            QCOMPARE(a.farPlane, layout.coarsest.farPlane);
        }
    }

    // The cache keeps pages across frames, places new ones in free slots, then in those of the
    // least recently used, and never evicts what the frame asks for.
    void cacheIsLeastRecentlyUsed()
    {
        VirtualPageCache cache;
        cache.reset(2);     // 4 slots
        auto first = cache.update({{0, 0, 0}, {0, 1, 0}, {0, 0, 0}}, 4);
        QCOMPARE(first.requested, 2);
        QCOMPARE(int(first.draw.size()), 2);
        auto again = cache.update({{0, 1, 0}, {0, 0, 0}}, 4);
        QVERIFY(again.draw.empty());
        cache.update({{0, 2, 0}, {0, 3, 0}}, 4);        // fills the pool
        QCOMPARE(cache.resident(), 4);
        // (0,0,0) and (0,1,0) were last used a frame earlier than (0,2,0), (0,3,0): they go first.
        auto next = cache.update({{0, 2, 0}, {0, 4, 0}}, 4);
        QCOMPARE(next.evicted, 1);
        QCOMPARE(int(next.draw.size()), 1);
        QVERIFY(cache.slotOf({0, 2, 0}));
        QVERIFY(cache.slotOf({0, 4, 0}));
        QVERIFY(cache.slotOf({0, 3, 0}));
        QCOMPARE(int(!cache.slotOf({0, 0, 0})) + int(!cache.slotOf({0, 1, 0})), 1);
        std::set<int> used;
        for (const auto& [page, slot] : cache.residentPages())
            used.insert(slot);
        QCOMPARE(int(used.size()), cache.resident());
    }

    // More requests than slots: the finest level's move to their parents until they fit, with a
    // count, and every request is then served by a resident page at its level or coarser.
    void cacheCoarsensWhenThePoolIsSmall()
    {
        VirtualPageCache cache;
        cache.reset(2);
        std::vector<VirtualPage> requests;
        for (int x = 0; x < 4; ++x) {
            for (int y = 0; y < 4; ++y)
                requests.push_back({0, x, y});
        }
        requests.push_back({2, 0, 0});
        const auto update = cache.update(requests, 4);
        QCOMPARE(update.requested, 17);
        QVERIFY(update.coarsened > 0);
        QCOMPARE(update.levelsCoarsened, 2);
        QCOMPARE(update.overflow, 0);
        QVERIFY(cache.resident() <= cache.capacity());
        for (const VirtualPage& p : requests) {
            bool served = false;
            for (int level = p.level; level < 4 && !served; ++level)
                served = bool(cache.slotOf({level, p.x >> (level - p.level), p.y >> (level - p.level)}));
            QVERIFY2(served, qPrintable(QString("page %1 %2 %3").arg(p.level).arg(p.x).arg(p.y)));
        }
    }

    // The table holds each resident page of a level's window at its wrapped place, once, and
    // nothing for pages outside the window.
    void pageTableWrapsTheWindows()
    {
        VirtualPageCache cache;
        cache.reset(4);
        const std::vector<glm::ivec2> windows{{-70, 5}, {-64, -64}};
        cache.update({{0, -70, 5}, {0, 57, 132}, {0, 58, 5}, {1, 3, -1}}, 2);
        const std::vector<std::uint16_t> table = cache.pageTable(windows);
        QCOMPARE(int(table.size()), 2 * kVirtualLevelPages * kVirtualLevelPages);
        const auto at = [&](int level, int x, int y) {
            const int wx = ((x % 128) + 128) % 128, wy = ((y % 128) + 128) % 128;
            return table[std::size_t((level * 128 + wy) * 128 + wx)];
        };
        QCOMPARE(int(at(0, -70, 5)), *cache.slotOf({0, -70, 5}) + 1);
        QCOMPARE(int(at(0, 57, 132)), *cache.slotOf({0, 57, 132}) + 1);
        QCOMPARE(int(at(1, 3, -1)), *cache.slotOf({1, 3, -1}) + 1);
        // (0, 58, 5) lies beyond level 0's window (-70 + 128 = 58): not in the table.
        QCOMPARE(int(std::count_if(table.begin(), table.end(), [](std::uint16_t v) { return v != 0; })), 3);
        QCOMPARE(*decodePageRequest(1 + 0 * 16384 + 3 * 128 + 2, windows), (VirtualPage{0, -68, 8}));
        QCOMPARE(*decodePageRequest(1 + 1 * 16384, windows), (VirtualPage{1, -64, -64}));
        QVERIFY(!decodePageRequest(0, windows));
        QVERIFY(!decodePageRequest(1 + 2 * 16384, windows));
    }

    // What a virtual map cannot be combined with is refused with the key to change.
    void refusesWhatItCannotDo_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<QString>("key");
        QTest::newRow("point light") << QStringList{"light.type=point"} << "light.type";
        QTest::newRow("cascades") << QStringList{"shadow.cascades=4"} << "shadow.cascades";
        QTest::newRow("lispsm") << QStringList{"light.warp=lispsm"} << "light.warp";
        QTest::newRow("manual fit") << QStringList{"light.fit=manual"} << "light.fit";
        QTest::newRow("vsm") << QStringList{"filter.mode=vsm"} << "filter.mode";
        QTest::newRow("pcss") << QStringList{"filter.mode=pcss"} << "filter.mode";
        QTest::newRow("pcf 9 and a normal offset") << QStringList{"filter.mode=pcf", "filter.kernel=9", "bias.normal=1"} << "bias.normal";
        QTest::newRow("poisson 6") << QStringList{"filter.mode=poisson", "filter.radius=6"} << "filter.mode";
        QTest::newRow("early-out") << QStringList{"filter.mode=pcf", "filter.early_out=true"} << "filter.early_out";
    }
    void refusesWhatItCannotDo()
    {
        QFETCH(QStringList, assignments);
        QFETCH(QString, key);
        Settings s = virtualSettings("seed");
        for (const QString& a : assignments)
            applyAssignment(s, a);
        const std::vector<SettingsIssue> issues = validate(s);
        QVERIFY(!issues.empty());
        QCOMPARE(issues.front().key, key);
        QVERIFY2(issues.front().message.contains("shadow.virtual=false"), qPrintable(issues.front().message));
        // What fits a page's border is taken.
        Settings fine = virtualSettings("seed");
        applyAssignment(fine, "filter.mode=pcf");
        applyAssignment(fine, "filter.kernel=7");
        applyAssignment(fine, "bias.normal=1");
        QVERIFY(validate(fine).empty());
    }

    // Against the ray tracer at the very pixels drawn: every preset, light from overhead to
    // grazing, the filters a page's border holds, the bias spaces, normal offset, receiver
    // planes and reversed depth; the same bounds as every light type's (tst_LightTypes).
    void virtualAgreesWithTheReference_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("azimuth");
        QTest::addColumn<double>("elevation");
        QTest::addColumn<QStringList>("assignments");
        const struct {
            double azimuth, elevation;
        } placements[] = {{30, 75}, {200, 50}, {300, 30}, {120, 14}, {10, 89.5}};
        const QList<QStringList> variants{
            {"filter.mode=hard"},
            {"filter.mode=hw-bilinear"},
            {"filter.mode=pcf", "filter.kernel=5"},
            {"filter.mode=poisson", "filter.radius=3"},
            {"filter.mode=pcf-dither4"},
            {"filter.mode=pcf64"},
            {"bias.space=texel", "bias.slope=1.5", "bias.min=0.5"},
            {"bias.normal=1", "bias.footprint=false", "filter.mode=pcf"},   // the normal offset alone against acne
            {"bias.receiver_plane=true", "filter.mode=pcf", "filter.kernel=5"},
            {"map.format=depth32f"},
            {"shadow.virtual_levels=12"},
            {"shadow.virtual_pool=12", "filter.mode=pcf"},
            {"shadow.virtual_lod_bias=1"},
        };
        int k = 0;
        for (const QString& scene : sceneNames()) {
            if (scene == u"foliage")
                continue;   // its cut-out edges are tst_Cutouts' to sweep
            for (const auto& p : placements) {
                const QStringList& variant = variants[k % variants.size()];
                QTest::newRow(qPrintable(QString("%1 az %2 el %3 %4").arg(scene).arg(p.azimuth).arg(p.elevation).arg(variant.join(' '))))
                    << scene << p.azimuth << p.elevation << variant;
                ++k;
            }
        }
        // The extremes of the camera: straight down from high up, along the light (the light at
        // its back), at grazing view over the ground.
        QTest::newRow("seed camera straight down from high") << "seed" << 200.0 << 50.0 << QStringList{"camera.position=0,60,0.01", "camera.target=0,0,0"};
        QTest::newRow("cubes camera along the light") << "cubes" << 200.0 << 50.0
                                                     << QStringList{"camera.position=-4.53,5.75,-1.65", "camera.target=0,0,0", "filter.mode=pcf"};
        QTest::newRow("torus camera grazing") << "torus" << 300.0 << 30.0 << QStringList{"camera.position=0.3,0.08,4", "camera.target=0,0.05,0"};
        // Models: the engine of assimp-testmodels through a scene file, curved and finned, on a
        // ground much wider than it (a level's texel there spans far more than the default world
        // bias), and a PLY model alone.
        const QString engine = writeFile(m_dir, QStringLiteral("engine.json"), QByteArrayLiteral(R"({
  "models": [ { "file": ")") + kTestModels.toUtf8() + QByteArrayLiteral(R"(glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "scale": 0.01 } ],
  "ground": true, "camera.position": [4, 3, 6] })"));
        QTest::newRow("engine scene file az 200 el 65") << engine << 200.0 << 65.0 << QStringList{};
        QTest::newRow("engine scene file az 30 el 40 pcf") << engine << 30.0 << 40.0 << QStringList{"filter.mode=pcf"};
        QTest::newRow("engine scene file az 300 el 20, camera low") << engine << 300.0 << 20.0 << QStringList{"camera.position=-3,0.6,4"};
        const QString wuson = kTestModels + QStringLiteral("PLY/Wuson.ply");
        QTest::newRow("Wuson az 120 el 55") << wuson << 120.0 << 55.0 << QStringList{};
        QTest::newRow("Wuson az 250 el 25 hw-bilinear") << wuson << 250.0 << 25.0 << QStringList{"filter.mode=hw-bilinear"};
    }
    void virtualAgreesWithTheReference()
    {
        QFETCH(QString, scene);
        QFETCH(double, azimuth);
        QFETCH(double, elevation);
        QFETCH(QStringList, assignments);
        Settings s = virtualSettings(scene);
        s.light.position = s.light.target + fromAngles(azimuth, elevation) * 1e3;
        for (const QString& a : assignments)
            applyAssignment(s, a);
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        const QSize size(240, 135);
        const VisibilityBuffer buffer = probe::visibility(renderer, s, size);
        for (int i = 0; i < buffer.pixelCount(); ++i) {
            const float v = buffer.visibility(i);
            QVERIFY2(std::isfinite(v) && v >= 0.0f && v <= 1.0f, qPrintable(QString("pixel %1: visibility %2").arg(i).arg(v)));
        }
        const VirtualMapStats& pages = renderer.lastFrame().virtualPages;
        const std::vector<float> hard = probe::hardReference(renderer, buffer);
        const Agreement a = probe::agreement(buffer, hard, renderer.lightFrame());
        const int offEdges = misclassifiedOffEdges(buffer, hard);
        const QString numbers = describe(a) + QString(" (%1 away from the reference's edges)").arg(offEdges) + "; pages: " + describe(pages);
        QVERIFY2(renderer.lastFrame().virtualMap && pages.requested > 0 && pages.resident >= 1, qPrintable(numbers));
        QCOMPARE(pages.overflow, 0);
        QVERIFY2(a.counted > 300, qPrintable(numbers));
        QVERIFY2(a.referenceShadowed > 0.001 * a.counted, qPrintable(numbers));
        if (isPresetName(scene)) {
            QVERIFY2(a.falseLight <= 0.02 * a.referenceShadowed + 0.002 * a.counted, qPrintable(numbers));
            QVERIFY2(a.falseShadow <= 0.003 * a.counted, qPrintable(numbers));
        } else {
            // A model's curved and finned caster has far more edge than a preset's boxes, and at
            // about a texel a pixel each edge may be a pixel off. No acne and no leak, then:
            // every misclassified pixel but a few lies at an edge of the shadow.
            QVERIFY2(offEdges <= 0.002 * a.counted, qPrintable(numbers));
        }
        qInfo().noquote() << numbers;
    }

    // Nearly every receiver pixel gets a texel of at most its own size, on each scene and from
    // a camera brought down to the receivers, where a single map's near texels are coarsest.
    void texelsCoverAtMostAPixel_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("lower");
        for (const QString scene : {"seed", "torus", "cubes", "occluder", "city"}) {
            for (double lower : {1.0, 0.3})
                QTest::newRow(qPrintable(QString("%1 camera x%2").arg(scene).arg(lower))) << QString(scene) << lower;
        }
    }
    void texelsCoverAtMostAPixel()
    {
        QFETCH(QString, scene);
        QFETCH(double, lower);
        Settings s = virtualSettings(scene);
        s.light.position = s.light.target + fromAngles(160.0, 40.0) * 1e3;
        glm::dvec3 offset = s.camera.position - s.camera.target;
        offset.y *= lower;
        s.camera.position = s.camera.target + offset;
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        const VisibilityBuffer buffer = probe::visibility(renderer, s, QSize(320, 180));
        const TexelDensity density = measureVirtualTexelDensity(buffer, *renderer.virtualMap());
        const QString numbers = QString("%1 of %2 pixels fine, median %3 px per texel; pages: %4")
                                    .arg(density.fine).arg(density.counted).arg(density.medianPixelsPerTexel).arg(describe(renderer.lastFrame().virtualPages));
        QVERIFY2(density.counted > 1000, qPrintable(numbers));
        QVERIFY2(density.fineShare() >= 0.95, qPrintable(numbers));
        // ... and not far finer than needed: half a pixel or more per texel at the median.
        QVERIFY2(density.medianPixelsPerTexel >= 0.25 && density.medianPixelsPerTexel <= 1.0, qPrintable(numbers));
        qInfo().noquote() << numbers;
    }

    // A still frame draws no page and asks for none; a small camera move draws only the pages
    // it newly needs; moving the light draws every page again.
    void pagesAreKeptUntilTheLightMoves_data()
    {
        QTest::addColumn<QString>("scene");
        for (const QString scene : {"seed", "cubes", "city"})
            QTest::newRow(qPrintable(scene)) << QString(scene);
    }
    void pagesAreKeptUntilTheLightMoves()
    {
        QFETCH(QString, scene);
        Settings s = virtualSettings(scene);
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        const QSize size(320, 180);
        HeadlessRenderer& headless = *m_headless;
        headless.renderFrame(s, size);
        const VirtualMapStats first = renderer.lastFrame().virtualPages;
        QVERIFY2(first.drawn == first.resident && first.drawn > 0, qPrintable(describe(first)));
        const int passes = renderer.shadowPassCount();
        headless.renderFrame(s, size);
        const VirtualMapStats still = renderer.lastFrame().virtualPages;
        QVERIFY2(still.drawn == 0 && still.requestDraws == 0, qPrintable(describe(still)));
        QCOMPARE(renderer.shadowPassCount(), passes);
        // The camera a little along its view: most pages stay.
        const glm::dvec3 step = (s.camera.target - s.camera.position) * 0.03;
        s.camera.position += step;
        s.camera.target += step;
        headless.renderFrame(s, size);
        const VirtualMapStats moved = renderer.lastFrame().virtualPages;
        QVERIFY2(moved.requestDraws > 0, qPrintable(describe(moved)));
        QVERIFY2(moved.drawn <= 0.5 * moved.requested, qPrintable(describe(moved)));
        // The light: nothing cached holds.
        s.light.position = s.light.target + (s.light.position - s.light.target) * 1.0 + glm::dvec3(0.5, 0.0, 0.0);
        headless.renderFrame(s, size);
        const VirtualMapStats lightMoved = renderer.lastFrame().virtualPages;
        QVERIFY2(lightMoved.drawn == lightMoved.resident, qPrintable(describe(lightMoved)));
        qInfo().noquote() << "first:" << describe(first) << "| camera moved:" << describe(moved) << "| light moved:" << describe(lightMoved);
    }

    // The defaults as fine as the anchor's: on the city's street camera at most half the
    // misclassified pixels of 4 stabilised cascades of 2048² (Unreal renders its sun 1.5 levels
    // finer than a texel per pixel), and a 1920 x 1080 view of it fits the default pool whole.
    void defaultsBeatTheCascadesAndFitAFullHdView()
    {
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        Settings cascades = presetSettings(QStringLiteral("city"));
        for (const char* a : {"shadow.cascades=4", "map.size=2048", "light.stabilize=true"})
            applyAssignment(cascades, QString::fromLatin1(a));
        Settings virtualMap = presetSettings(QStringLiteral("city"));
        applyAssignment(virtualMap, QStringLiteral("shadow.virtual=true"));
        const QSize size(640, 360);
        const VisibilityBuffer c = probe::visibility(renderer, cascades, size);
        const Agreement ca = probe::agreement(c, probe::hardReference(renderer, c), renderer.lightFrame());
        const VisibilityBuffer v = probe::visibility(renderer, virtualMap, size);
        const Agreement va = probe::agreement(v, probe::hardReference(renderer, v), renderer.lightFrame());
        qInfo().noquote() << "cascades:" << describe(ca) << "| virtual:" << describe(va);
        const int virtualWrong = va.falseShadow + va.falseLight, cascadesWrong = ca.falseShadow + ca.falseLight;
        QVERIFY2(2 * virtualWrong <= cascadesWrong, qPrintable(QString("virtual %1 px, cascades %2 px").arg(virtualWrong).arg(cascadesWrong)));

        probe::visibility(renderer, virtualMap, QSize(1920, 1080));
        const VirtualMapStats& pages = renderer.lastFrame().virtualPages;
        QVERIFY2(pages.coarsened == 0 && pages.overflow == 0 && pages.resident > 900, qPrintable(describe(pages)));
    }

    // A pool far too small for the view coarsens the finest requests, says by how much, and
    // the shadows stay where the reference has them (coarser, but no holes of light).
    void aSmallPoolCoarsens()
    {
        Settings s = virtualSettings("cubes");
        s.shadow.virtualPool = 4;
        s.filter.mode = FilterMode::Hard;
        glm::dvec3 offset = s.camera.position - s.camera.target;
        offset.y *= 0.3;
        s.camera.position = s.camera.target + offset;
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        const VisibilityBuffer buffer = probe::visibility(renderer, s, QSize(320, 180));
        const VirtualMapStats& pages = renderer.lastFrame().virtualPages;
        QVERIFY2(pages.coarsened > 0 && pages.levelsCoarsened >= 1 && pages.resident <= 16, qPrintable(describe(pages)));
        QCOMPARE(pages.overflow, 0);
        const Agreement a = probe::agreement(buffer, probe::hardReference(renderer, buffer), renderer.lightFrame());
        QVERIFY2(a.falseLight <= 0.05 * a.referenceShadowed + 0.004 * a.counted, qPrintable(describe(a)));
        const TexelDensity density = measureVirtualTexelDensity(buffer, *renderer.virtualMap());
        QVERIFY2(density.fineShare() < 0.95, qPrintable(QString::number(density.fineShare())));
        qInfo().noquote() << describe(pages) << "|" << describe(a);
    }

    // The requests reduced on the GPU to a flag per page (the hardware profile) are the pages the
    // CPU finds in the whole read-back (the software profile), in the same order, so the pool
    // places them alike and the frames are byte for byte the same, on every scene and from
    // cameras high, low and aside.
    void gpuReductionFindsThePagesTheCpuFinds_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        for (const QString scene : {"seed", "cubes", "city", "foliage", "torus"})
            QTest::newRow(qPrintable(scene)) << QString(scene) << QStringList{};
        QTest::newRow("city from high above") << "city" << QStringList{"camera.position=0,800,1", "camera.target=0,0,0"};
        QTest::newRow("seed, camera low") << "seed" << QStringList{"camera.position=4,0.2,5", "camera.target=0,0.3,0"};
        QTest::newRow("cubes, camera aside, 12 levels") << "cubes" << QStringList{"camera.position=9,2,-6", "shadow.virtual_levels=12"};
        QTest::newRow("city, lod bias 2") << "city" << QStringList{"shadow.virtual_lod_bias=2", "shadow.virtual_pool=64"};
    }

    void gpuReductionFindsThePagesTheCpuFinds()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        Settings s = virtualSettings(scene);
        for (const QString& a : assignments)
            applyAssignment(s, a);
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        // The software profile reduces the requests on the CPU, the hardware one on the GPU.
        std::vector<QImage> frames;
        const auto pagesOf = [&](RasteriserProfile profile) -> std::set<std::uint64_t> {
            s.rasteriser.profile = profile;
            renderer.invalidateShadowMap();     // every page placed afresh
            frames.push_back(m_headless->renderScene(s, QSize(320, 180)));
            const VirtualShadowMap::Reduction expected = profile == RasteriserProfile::Software ? VirtualShadowMap::Reduction::Cpu
                                                                                               : VirtualShadowMap::Reduction::Gpu;
            if (renderer.virtualMap()->reduction() != expected)
                return {};
            std::set<std::uint64_t> keys;
            for (const VirtualPage& page : renderer.virtualMap()->requests())
                keys.insert(page.key());
            if (keys.size() != renderer.virtualMap()->requests().size())
                return {};      // a page twice: the comparison below fails
            return keys;
        };
        const std::set<std::uint64_t> cpu = pagesOf(RasteriserProfile::Software);
        const std::set<std::uint64_t> gpu = pagesOf(RasteriserProfile::Hardware);
        QVERIFY(!cpu.empty());
        QVERIFY2(cpu == gpu, qPrintable(QStringLiteral("%1 pages from the CPU, %2 from the GPU").arg(cpu.size()).arg(gpu.size())));
        QVERIFY(frames[0] == frames[1]);
    }

    // The window's requests come back a frame later: the frame that moves the camera asks and
    // does not wait, a later one places the very pages a synchronous frame would have; the
    // first requests of an empty pool and a turned light's are taken at once.
    void asyncRequestsArriveAFrameLater()
    {
        Settings s = virtualSettings("city");
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        renderer.setVirtualAsyncRequests(true);
        const auto restore = qScopeGuard([&] { renderer.setVirtualAsyncRequests(false); });
        const QSize size(320, 180);
        s.light.position += glm::dvec3(0.3, 0.0, 0.0);      // a layout of its own: an empty pool
        m_headless->renderFrame(s, size);
        const VirtualMapStats first = renderer.lastFrame().virtualPages;
        QVERIFY2(first.drawn > 0 && !first.requestsPending, qPrintable(describe(first)));
        const glm::dvec3 step = (s.camera.target - s.camera.position) * 0.05;
        s.camera.position += step;
        s.camera.target += step;
        m_headless->renderFrame(s, size);
        const VirtualMapStats asked = renderer.lastFrame().virtualPages;
        QVERIFY2(asked.requestDraws > 0 && asked.requestsPending && asked.drawn == 0, qPrintable(describe(asked)));
        m_headless->renderFrame(s, size);
        const VirtualMapStats arrived = renderer.lastFrame().virtualPages;
        QVERIFY2(!arrived.requestsPending && arrived.requestDraws == 0 && arrived.drawn > 0, qPrintable(describe(arrived)));
        std::set<std::uint64_t> async;
        for (const VirtualPage& page : renderer.virtualMap()->requests())
            async.insert(page.key());
        m_headless->renderFrame(s, size);
        QCOMPARE(renderer.lastFrame().virtualPages.drawn, 0);
        // The same camera's requests taken in the same frame.
        renderer.setVirtualAsyncRequests(false);    // asks again
        m_headless->renderFrame(s, size);
        std::set<std::uint64_t> sync;
        for (const VirtualPage& page : renderer.virtualMap()->requests())
            sync.insert(page.key());
        QVERIFY(!sync.empty());
        QVERIFY2(async == sync, qPrintable(QStringLiteral("%1 pages asynchronously, %2 at once").arg(async.size()).arg(sync.size())));
        QCOMPARE(renderer.lastFrame().virtualPages.drawn, 0);       // they were all resident already
    }

    // The depth pane's pool: every resident page in its own slot of the pool with its level,
    // the counts of the frame, the slot under the pointer and its level's page table.
    void thePoolShowsItsPagesAndLevels()
    {
        Settings s = virtualSettings("city");
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        m_headless->renderFrame(s, QSize(320, 180));
        const std::optional<VirtualPoolFacts> pool = virtualPoolFacts(renderer);
        QVERIFY(pool);
        const VirtualMapStats& pages = renderer.lastFrame().virtualPages;
        QCOMPARE(int(pool->resident.size()), pages.resident);
        QCOMPARE(pool->poolSide, s.shadow.virtualPool);
        QCOMPARE(pool->counts.requested, pages.requested);
        std::set<int> used;
        int finest = kMaxVirtualLevels;
        for (const VirtualPoolFacts::Slot& slot : pool->resident) {
            QVERIFY(slot.slot >= 0 && slot.slot < pool->poolSide * pool->poolSide);
            QVERIFY(slot.page.level >= 0 && slot.page.level < pool->levels);
            used.insert(slot.slot);
            finest = std::min(finest, slot.page.level);
            // The page lies in its level's window, where the page table holds it.
            const glm::ivec2 at = glm::ivec2(slot.page.x, slot.page.y) - pool->windows.at(std::size_t(slot.page.level));
            QVERIFY(at.x >= 0 && at.y >= 0 && at.x < kVirtualLevelPages && at.y < kVirtualLevelPages);
        }
        QCOMPARE(int(used.size()), int(pool->resident.size()));      // one page a slot
        QCOMPARE(pool->tableLevel, finest);                          // no pointer: the finest level's table
        QVERIFY(!pool->pointerSlot);
        const QString summary = virtualPoolSummary(*pool);
        QVERIFY2(summary.contains(QString::number(pages.resident)) && summary.contains(QString::number(pages.requested)), qPrintable(summary));
        // The pointer over a slot's centre picks it, and the table follows its level.
        const VirtualPoolFacts::Slot& last = pool->resident.back();
        const QPointF centre((last.slot % pool->poolSide + 0.5) / pool->poolSide, (last.slot / pool->poolSide + 0.5) / pool->poolSide);
        QCOMPARE(poolSlotAt(pool->poolSide, centre), std::optional<int>(last.slot));
        const std::optional<VirtualPoolFacts> pointed = virtualPoolFacts(renderer, centre);
        QCOMPARE(pointed->pointerSlot, std::optional<int>(last.slot));
        QCOMPARE(pointed->tableLevel, last.page.level);
        QVERIFY(virtualSlotText(*pointed, last.slot).contains(QStringLiteral("level %1").arg(last.page.level)));
        QVERIFY(!poolSlotAt(pool->poolSide, QPointF(1.2, 0.5)));
        // Not a virtual map: no pool.
        s.shadow.virtualMap = false;
        m_headless->renderFrame(s, QSize(320, 180));
        QVERIFY(!virtualPoolFacts(renderer));
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
    QTemporaryDir m_dir;
};

SHADOWLAB_TEST_MAIN(TestVirtualShadowMaps)
#include "tst_VirtualShadowMaps.moc"
