// The renderer on the headless platform, checked the way a person checks a shadow: points the
// cubes occlude (worked out by casting rays at the cubes) are dark, the rest of the plane is
// lit, acne appears without bias and not with the defaults, filters soften the edge.
#include "Application.h"
#include "ArtifactPresets.h"
#include "HeadlessRenderer.h"
#include "LitPass.h"
#include "RenderProbe.h"
#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShaderProgram.h"
#include "ShadowTechnique.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

using namespace shadowlab;

namespace {

const QSize kSize(320, 180);

struct PlaneSample {
    QPoint pixel;
    bool expectLit;     // by ray casting, with the volume and far-plane rules applied
    bool occluded;      // a cube is between the point and the light
    bool outsideVolume; // outside the light's map or beyond its far plane
};

bool occludedFrom(const Scene& scene, const LightFrame& light, const glm::dvec3& p)
{
    const glm::dvec3 towardLight = light.perspective ? light.position - p : -light.direction;
    for (std::size_t i = 1; i < scene.objects.size(); ++i) { // objects[0] is the ground
        if (probe::rayHitsCube(scene.objects[i].model, p, towardLight))
            return true;
    }
    return false;
}

bool hiddenFromCamera(const Scene& scene, const CameraFrame& camera, const glm::dvec3& p)
{
    for (std::size_t i = 1; i < scene.objects.size(); ++i) {
        if (probe::rayHitsCube(scene.objects[i].model, p, camera.position - p))
            return true;
    }
    return false;
}

// Points of the seed plane on a grid, classified by ray casting; points within `margin` of a
// shadow boundary (where a neighbour classifies differently) or of a cube's silhouette (where
// a neighbour is hidden from the camera, so the pixel may show the cube) are left out.
std::vector<PlaneSample> planeSamples(const Scene& scene, const LightFrame& light, const CameraFrame& camera, double margin = 0.08)
{
    std::vector<PlaneSample> samples;
    auto classify = [&](const glm::dvec3& p, bool& occluded, bool& outside) {
        const glm::dvec4 s = light.shadowMatrix * glm::dvec4(p, 1.0);
        const glm::dvec3 c = glm::dvec3(s) / s.w;
        outside = s.w <= 0.0 || c.x < 0.0 || c.x > 1.0 || c.y < 0.0 || c.y > 1.0 || c.z > 1.0;
        occluded = occludedFrom(scene, light, p);
        return outside || !occluded;
    };
    for (double x = -5.0; x <= 5.0; x += 0.125) {
        for (double z = -4.0; z <= 2.6; z += 0.125) {
            const glm::dvec3 p(x, -0.5, z);
            bool occluded = false, outside = false;
            const bool lit = classify(p, occluded, outside);
            bool stable = true;
            for (const glm::dvec3 d : {glm::dvec3(margin, 0, 0), glm::dvec3(-margin, 0, 0), glm::dvec3(0, 0, margin), glm::dvec3(0, 0, -margin)}) {
                bool o2 = false, out2 = false;
                stable = stable && classify(p + d, o2, out2) == lit && !hiddenFromCamera(scene, camera, p + d);
            }
            const auto pixel = probe::project(camera, p, kSize);
            if (!stable || !pixel || hiddenFromCamera(scene, camera, p))
                continue;
            samples.push_back({*pixel, lit, occluded, outside});
        }
    }
    return samples;
}

struct Agreement {
    int litExpected = 0;
    int shadowExpected = 0;
    int litWrong = 0;       // expected lit, rendered dark: acne or a leak of darkness
    int shadowWrong = 0;    // expected dark, rendered lit: peter panning or light leak
    int occludedButOutside = 0;
    int occludedButOutsideWrong = 0;
};

Agreement compare(const std::vector<PlaneSample>& samples, const QImage& shadowed, const QImage& unshadowed)
{
    Agreement a;
    for (const PlaneSample& s : samples) {
        const double ratio = probe::visibilityRatio(shadowed, unshadowed, s.pixel);
        if (s.expectLit) {
            ++a.litExpected;
            a.litWrong += ratio < 0.85;
            if (s.occluded && s.outsideVolume) {
                ++a.occludedButOutside;
                a.occludedButOutsideWrong += ratio < 0.85;
            }
        } else {
            ++a.shadowExpected;
            a.shadowWrong += ratio > 0.6;
        }
    }
    return a;
}

Settings seedWith(const QStringList& assignments)
{
    Settings s = presetSettings("seed");
    for (const QString& a : assignments)
        applyAssignment(s, a);
    return s;
}

Settings withoutShadows(Settings s)
{
    s.shadow.enabled = false;
    return s;
}

// Share of pixels whose brightness with shadows is strictly between shadow and light.
double penumbraShare(const QImage& shadowed, const QImage& unshadowed)
{
    int counted = 0, between = 0;
    for (int y = 0; y < shadowed.height(); ++y) {
        for (int x = 0; x < shadowed.width(); ++x) {
            if (probe::luminance(unshadowed, {x, y}) < 40.0)
                continue;
            ++counted;
            const double r = probe::visibilityRatio(shadowed, unshadowed, {x, y});
            between += r > 0.45 && r < 0.85;
        }
    }
    return counted ? double(between) / counted : 0.0;
}

int maxChannelDifference(const QImage& a, const QImage& b)
{
    int worst = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            worst = std::max({worst, std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)), std::abs(qBlue(p) - qBlue(q))});
        }
    }
    return worst;
}

} // namespace

class TestShadows : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;

    Agreement renderAndCompare(const Settings& settings, std::vector<PlaneSample>* samplesOut = nullptr)
    {
        const QImage unshadowed = m_headless->renderScene(withoutShadows(settings), kSize);
        const QImage shadowed = m_headless->renderScene(settings, kSize);
        const Renderer& r = m_headless->renderer();
        const std::vector<PlaneSample> samples = planeSamples(*r.scene(), r.lightFrame(), r.cameraFrame());
        if (samplesOut)
            *samplesOut = samples;
        return compare(samples, shadowed, unshadowed);
    }

    // Eight passes of `s` with the light 5 degrees further round its target each: how many drew
    // the map, cleared it and were drawn into a slice, and the casters' coverage each time.
    struct LightWalk {
        int drawn = 0, cleared = 0, sliced = 0;
        std::vector<double> casterCoverage;
    };
    LightWalk walkTheLight(Settings s)
    {
        const Renderer& r = m_headless->renderer();
        const LightAngles start = lightAngles(s.light.position, s.light.target);
        LightWalk walk;
        for (int step = 0; step < 8; ++step) {
            LightAngles a = start;
            a.azimuth += 5.0 * step;
            s.light.position = lightPosition(s.light.target, a);
            m_headless->renderFrame(s, kSize);
            walk.drawn += r.lastFrame().shadowPassRendered;
            walk.cleared += r.lastFrame().shadowMapCleared;
            walk.sliced += r.shadowMap().slice().scale < 1.0;
            walk.casterCoverage.push_back(r.shadowMap().depthSlices().casterCoverage());
        }
        return walk;
    }

private Q_SLOTS:
    void initTestCase()
    {
        m_headless = std::make_unique<HeadlessRenderer>();
        qInfo("renderer: %s", qPrintable(m_headless->renderer().rendererString()));
    }
    void cleanupTestCase() { m_headless.reset(); }

    void shadowsFallWhereTheCubesOcclude_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("ortho, defaults") << QStringList{};
        QTest::newRow("perspective") << QStringList{"light.projection=perspective", "light.fov=90"};
        QTest::newRow("ortho, depth32f") << QStringList{"map.format=depth32f"};
        QTest::newRow("ortho, 1024 map, hard") << QStringList{"map.size=1024", "filter.mode=hard"};
        QTest::newRow("phong") << QStringList{"shading.model=phong"};
    }

    void shadowsFallWhereTheCubesOcclude()
    {
        QFETCH(QStringList, assignments);
        const Agreement a = renderAndCompare(seedWith(assignments));
        QVERIFY2(a.shadowExpected >= 20, qPrintable(QString("only %1 shadowed samples in view").arg(a.shadowExpected)));
        QVERIFY2(a.litExpected >= 200, qPrintable(QString("only %1 lit samples in view").arg(a.litExpected)));
        QVERIFY2(a.shadowWrong <= a.shadowExpected / 50,
                 qPrintable(QString("%1 of %2 occluded points render lit").arg(a.shadowWrong).arg(a.shadowExpected)));
        QVERIFY2(a.litWrong <= a.litExpected / 100,
                 qPrintable(QString("%1 of %2 unoccluded points render dark").arg(a.litWrong).arg(a.litExpected)));
    }

    void everyFilterShadowsTheOccludedPlane_data()
    {
        QTest::addColumn<QString>("mode");
        for (const QString& m : findSettingKey("filter.mode")->choices)
            QTest::newRow(qPrintable(m)) << m;
    }

    void everyFilterShadowsTheOccludedPlane()
    {
        QFETCH(QString, mode);
        const Agreement a = renderAndCompare(seedWith({"filter.mode=" + mode}));
        QVERIFY(a.shadowExpected >= 20);
        QVERIFY2(a.shadowWrong <= a.shadowExpected / 50, qPrintable(QString("%1 of %2").arg(a.shadowWrong).arg(a.shadowExpected)));
        QVERIFY2(a.litWrong <= a.litExpected / 100, qPrintable(QString("%1 of %2").arg(a.litWrong).arg(a.litExpected)));
    }

    // Each row of the technique table brings its own GLSL file into the lit pass, and the
    // file name stays out of the GLSL (whose preprocessor knows no strings).
    void eachTechniqueIncludesItsOwnFile()
    {
        for (const ShadowTechnique& t : shadowTechniques()) {
            Settings s = presetSettings("seed");
            s.filter.mode = t.mode;
            const QByteArray source = loadShaderSource(QStringLiteral("lit.frag"), LitPass::variantDefines(planFrame(s, true, true)));
            QCOMPARE(source.count("\nfloat filterShadow("), qsizetype(1));
            QVERIFY2(!source.contains("#include"), qPrintable(t.key));
            QVERIFY2(!source.contains('"'), qPrintable(t.key));
        }
    }

    void noBiasShowsAcneAndTheDefaultsDoNot()
    {
        const Agreement acne = renderAndCompare(seedWith({"bias.cull_front=false", "bias.footprint=false", "bias.skip_floors=false", "bias.slope=0", "bias.min=0", "filter.mode=hard"}));
        const double acneShare = double(acne.litWrong) / acne.litExpected;
        qInfo("falsely dark lit-plane samples: %.1f%% with no bias", 100.0 * acneShare);
        QVERIFY2(acneShare > 0.05, qPrintable(QString("only %1% acne without bias").arg(100.0 * acneShare)));

        const Agreement clean = renderAndCompare(presetSettings("seed"));
        const double cleanShare = double(clean.litWrong) / clean.litExpected;
        qInfo("falsely dark lit-plane samples: %.2f%% with the defaults", 100.0 * cleanShare);
        QVERIFY(cleanShare < 0.01);
    }

    void defaultsAreAtLeastAsAccurateAsTheTutorialConfiguration()
    {
        // Every sample, edges included: there the map's resolution and the filter show.
        auto misclassified = [this](const Settings& s) {
            const QImage unshadowed = m_headless->renderScene(withoutShadows(s), kSize);
            const QImage shadowed = m_headless->renderScene(s, kSize);
            const Renderer& r = m_headless->renderer();
            const Agreement a = compare(planeSamples(*r.scene(), r.lightFrame(), r.cameraFrame(), 0.0), shadowed, unshadowed);
            return std::pair(a.litWrong + a.shadowWrong, a.litExpected + a.shadowExpected);
        };
        const auto [tutorialWrong, total] =
            misclassified(seedWith({"filter.mode=pcf", "filter.kernel=3", "map.size=1024", "bias.slope=0.05", "bias.min=0.005",
                                    "light.fit=manual", "bias.cull_front=false"})); // a tutorial renders the classic +-10 volume
        const auto [defaultWrong, total2] = misclassified(presetSettings("seed"));
        qInfo("misclassified plane samples: tutorial configuration %d, defaults %d (of %d)", tutorialWrong, defaultWrong, total);
        QCOMPARE(total, total2);
        QVERIFY(defaultWrong <= tutorialWrong);
    }

    void beyondTheFarPlaneIsLit()
    {
        // Far plane between the high cube (3.3 from the light) and the plane under it (5.6):
        // the cube is in the map, but its shadow would land beyond the far plane.
        const Agreement a = renderAndCompare(seedWith({"light.fit=manual", "light.far=4.5"}));
        QVERIFY2(a.occludedButOutside >= 10, qPrintable(QString("%1 samples").arg(a.occludedButOutside)));
        QCOMPARE(a.occludedButOutsideWrong, 0);
    }

    void outsideTheLightVolumeIsLit()
    {
        const Agreement a = renderAndCompare(seedWith({"light.fit=manual", "light.extent=0.5"}));
        QVERIFY2(a.occludedButOutside >= 10, qPrintable(QString("%1 samples").arg(a.occludedButOutside)));
        QCOMPARE(a.occludedButOutsideWrong, 0);
    }

    void pcfSoftensTheEdge()
    {
        // A bias large enough for a 7x7 kernel on a coarse map, so only the edge is in between
        // (with a small bias a wide kernel darkens the whole lit plane: acne, not softness).
        const QStringList common{"map.size=512", "bias.slope=0.1", "bias.min=0.01"};
        const Settings hard = seedWith(common + QStringList{"filter.mode=hard"});
        const QImage unshadowed = m_headless->renderScene(withoutShadows(hard), kSize);
        const double hardShare = penumbraShare(m_headless->renderScene(hard, kSize), unshadowed);
        const double pcfShare = penumbraShare(m_headless->renderScene(seedWith(common + QStringList{"filter.mode=pcf", "filter.kernel=7"}), kSize), unshadowed);
        const double bilinearShare =
            penumbraShare(m_headless->renderScene(seedWith(common + QStringList{"filter.mode=hw-bilinear"}), kSize), unshadowed);
        qInfo("pixels between shadow and light: hard %.3f%%, pcf 7x7 %.3f%%, hw-bilinear %.3f%%", 100 * hardShare, 100 * pcfShare,
              100 * bilinearShare);
        QVERIFY(pcfShare > 3.0 * hardShare + 0.001);
        QVERIFY(pcfShare < 0.2); // in between only along the edges
        QVERIFY(bilinearShare > hardShare);
    }

    void pcfKernelOneEqualsHard()
    {
        const QImage hard = m_headless->renderScene(seedWith({"filter.mode=hard"}), kSize);
        const QImage pcf1 = m_headless->renderScene(seedWith({"filter.mode=pcf", "filter.kernel=1"}), kSize);
        QCOMPARE(maxChannelDifference(hard, pcf1), 0);
    }

    void shadowsOffRemovesTheDarkRegion()
    {
        std::vector<PlaneSample> samples;
        renderAndCompare(presetSettings("seed"), &samples);
        const QImage off = m_headless->renderScene(withoutShadows(presetSettings("seed")), kSize);
        const QImage on = m_headless->renderScene(presetSettings("seed"), kSize);
        int darkOn = 0, darkOff = 0;
        for (const PlaneSample& s : samples) {
            if (s.expectLit)
                continue;
            darkOn += probe::visibilityRatio(on, off, s.pixel) < 0.6;
            darkOff += probe::visibilityRatio(off, off, s.pixel) < 0.6;
        }
        QVERIFY(darkOn >= 20);
        QCOMPARE(darkOff, 0);
        QCOMPARE(m_headless->renderer().lastFrame().shadowDraws, 0);
    }

    void phongAndBlinnPhongDiffer()
    {
        const QImage blinn = m_headless->renderScene(seedWith({"shading.model=blinn-phong"}), kSize);
        const QImage phong = m_headless->renderScene(seedWith({"shading.model=phong"}), kSize);
        QVERIFY(maxChannelDifference(blinn, phong) > 5);
    }

    void shadowPassIsSkippedWhenOnlyTheCameraChanges()
    {
        // With the volume as set; a fitted volume follows the camera (next test).
        Renderer& r = m_headless->renderer();
        Settings s = seedWith({"light.fit=manual"});
        m_headless->renderFrame(s, kSize);
        const int before = r.shadowPassCount();

        s.camera.position = {1.0, 2.0, 5.0};
        m_headless->renderFrame(s, kSize);
        QVERIFY(!r.lastFrame().shadowPassRendered);
        s.bias.slope = 0.03; // lit-pass bias: the map stays valid
        s.filter.kernel = 5;
        m_headless->renderFrame(s, kSize);
        QVERIFY(!r.lastFrame().shadowPassRendered);
        QCOMPARE(r.shadowPassCount(), before);

        s.light.position.x += 0.25;
        m_headless->renderFrame(s, kSize);
        QVERIFY(r.lastFrame().shadowPassRendered);
        QCOMPARE(r.lastFrame().shadowDraws, 3);     // the three cubes: the ground shadows nothing (bias.skip_floors)
        s.bias.skipFloors = false;
        m_headless->renderFrame(s, kSize);
        QVERIFY(r.lastFrame().shadowPassRendered);
        QCOMPARE(r.lastFrame().shadowDraws, 4);
        s.bias.cullFront = !s.bias.cullFront;
        m_headless->renderFrame(s, kSize);
        QVERIFY(r.lastFrame().shadowPassRendered);
        s.map.size = 512;
        m_headless->renderFrame(s, kSize);
        QVERIFY(r.lastFrame().shadowPassRendered);
        QCOMPARE(r.shadowPassCount(), before + 4);
    }

    void aStillFrameDoesNoFitting_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("seed") << QStringList{};
        QTest::newRow("city, 4 cascades") << QStringList{"scene=city:300", "shadow.cascades=4"};
        QTest::newRow("point light") << QStringList{"light.type=point"};
    }
    void aStillFrameDoesNoFitting()
    {
        // Repainting what did not change refits nothing, and the fit it keeps is the fit a fresh
        // renderer computes for the same frame.
        QFETCH(QStringList, assignments);
        Renderer& r = m_headless->renderer();
        Settings s = seedWith(assignments);
        m_headless->renderFrame(s, kSize);
        const int fits = r.fitCount();
        for (int i = 0; i < 3; ++i)
            m_headless->renderFrame(s, kSize);
        QCOMPARE(r.fitCount(), fits);
        s.camera.position.x += 0.5;     // what the camera sees changed: fitted again, once
        m_headless->renderFrame(s, kSize);
        m_headless->renderFrame(s, kSize);
        QCOMPARE(r.fitCount(), fits + 1);
        m_headless->renderFrame(s, QSize(kSize.width() / 2, kSize.height()));   // so did its aspect
        QCOMPARE(r.fitCount(), fits + 2);
        m_headless->renderFrame(s, kSize);
        HeadlessRenderer fresh;
        fresh.renderFrame(s, kSize);
        QCOMPARE(r.shadowViews().set.views.size(), fresh.renderer().shadowViews().set.views.size());
        for (std::size_t i = 0; i < r.shadowViews().set.views.size(); ++i)
            QVERIFY(r.shadowViews().set.views[i].fit.volume == fresh.renderer().shadowViews().set.views[i].fit.volume);
        QCOMPARE(r.lastFit().texelAfter, fresh.renderer().lastFit().texelAfter);
    }

    void fittedShadowPassIsSkippedOnSmallCameraMoves()
    {
        Renderer& r = m_headless->renderer();
        Settings s = presetSettings("seed");
        m_headless->renderFrame(s, kSize);
        QVERIFY(r.lastFrame().lightFitted);
        QCOMPARE_LT(r.lastFrame().texelWorldSize, r.lastFrame().texelWorldSizeBeforeFit);
        const int before = r.shadowPassCount();
        for (int i = 1; i <= 10; ++i) {
            s.camera.position.x += 0.002;
            m_headless->renderFrame(s, kSize);
        }
        QVERIFY2(r.shadowPassCount() - before <= 2, qPrintable(QString("%1 passes for 10 small camera moves").arg(r.shadowPassCount() - before)));
        // Unsnapped, the map still covers only the casters' footprint, which a camera move that
        // keeps them all in view does not change; moving the light does.
        s.light.stabilize = false;
        m_headless->renderFrame(s, kSize);
        const int unsnapped = r.shadowPassCount();
        s.camera.position.x += 0.002;
        m_headless->renderFrame(s, kSize);
        QCOMPARE(r.shadowPassCount(), unsnapped);
        s.light.position.x += 0.01;
        m_headless->renderFrame(s, kSize);
        QCOMPARE(r.shadowPassCount(), unsnapped + 1);
    }

    void reversedDepthAndNormalOffsetShadowTheOccludedPlane_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("depth32f reversed, ortho") << QStringList{"map.format=depth32f"};
        QTest::newRow("depth32f reversed, perspective") << QStringList{"map.format=depth32f", "light.projection=perspective"};
        QTest::newRow("normal offset 1.5, no depth bias") << QStringList{"bias.normal=1.5", "bias.slope=0", "bias.min=0.0002"};
        QTest::newRow("fit manual") << QStringList{"light.fit=manual"};
    }

    void reversedDepthAndNormalOffsetShadowTheOccludedPlane()
    {
        QFETCH(QStringList, assignments);
        const Agreement a = renderAndCompare(seedWith(assignments));
        QVERIFY(a.shadowExpected >= 20);
        QVERIFY2(a.shadowWrong <= a.shadowExpected / 50, qPrintable(QString("%1 of %2 occluded points render lit").arg(a.shadowWrong).arg(a.shadowExpected)));
        QVERIFY2(a.litWrong <= a.litExpected / 100, qPrintable(QString("%1 of %2 unoccluded points render dark").arg(a.litWrong).arg(a.litExpected)));
        if (assignments.contains("map.format=depth32f"))
            QCOMPARE(m_headless->renderer().lastFrame().reversedDepth, m_headless->renderer().supportsReversedDepth());
    }

    void onlyTheVariantInUseIsCompiled()
    {
        HeadlessRenderer fresh;
        // The technique's, and the one without a lookup for receivers out of the casters' reach,
        // which every technique shares.
        fresh.renderFrame(presetSettings("seed"), kSize);
        QCOMPARE(fresh.renderer().compiledLitVariants(), 2);
        fresh.renderFrame(seedWith({"filter.mode=pcf64"}), kSize);
        fresh.renderFrame(presetSettings("seed"), kSize);
        QCOMPARE(fresh.renderer().compiledLitVariants(), 3);
    }

    void badSettingsKeepTheLastGoodState()
    {
        Renderer& r = m_headless->renderer();
        const QImage good = m_headless->renderScene(presetSettings("seed"), kSize);
        const int passes = r.shadowPassCount();
        Settings bad = presetSettings("seed");
        bad.light.nearPlane = 10.0; // >= far
        QVERIFY_THROWS_EXCEPTION(SettingsError, m_headless->renderFrame(bad, kSize));
        bad = presetSettings("seed");
        bad.map.size = r.maxTextureSize() * 2;
        try {
            m_headless->renderFrame(bad, kSize);
            QFAIL("expected a SettingsError for a map beyond GL_MAX_TEXTURE_SIZE");
        } catch (const SettingsError& e) {
            QCOMPARE(e.key(), QString("map.size"));
        }
        QCOMPARE(r.shadowPassCount(), passes);
        QCOMPARE(maxChannelDifference(m_headless->renderScene(presetSettings("seed"), kSize), good), 0);
        QCOMPARE(r.shadowPassCount(), passes); // the cached map survived the failed attempts
    }

    void emptyTargetDrawsNothing()
    {
        Renderer& r = m_headless->renderer();
        m_headless->makeCurrent();
        r.render(presetSettings("seed"), RenderTarget{0, QSize(0, 0)});
        r.render(presetSettings("seed"), RenderTarget{0, QSize(0, 100)});
        QCOMPARE(m_headless->renderScene(presetSettings("seed"), QSize(1, 1)).size(), QSize(1, 1));
    }

    void depthMapShowsTheCastersAndLinearisesPerspective()
    {
        // The classic map: the hand-set volume centred on the high cube, the ground drawn too.
        m_headless->renderFrame(seedWith({"light.fit=manual", "bias.cull_front=false", "bias.skip_floors=false"}), kSize);
        const QImage ortho = m_headless->renderDepthMap(QSize(256, 256));
        m_headless->renderFrame(seedWith({"light.projection=perspective", "light.fit=manual", "bias.cull_front=false", "bias.skip_floors=false"}), kSize);
        const QImage perspective = m_headless->renderDepthMap(QSize(256, 256));
        // The high cube is darker (nearer the light) than the plane just beyond it; the plane's
        // part before the near plane is clamped to depth 0, the darkest of all, so the
        // comparison is local.
        const double centre = probe::luminance(ortho, {128, 128});
        QVERIFY2(centre + 20 < probe::luminance(ortho, {128, 90}),
                 qPrintable(QString("cube %1, plane beyond it %2").arg(centre).arg(probe::luminance(ortho, {128, 90}))));
        // Linearised perspective depth spans a visible range instead of sitting near white.
        double lo = 255, hi = 0;
        for (int y = 0; y < 256; y += 8)
            for (int x = 0; x < 256; x += 8) {
                lo = std::min(lo, probe::luminance(perspective, {x, y}));
                hi = std::max(hi, probe::luminance(perspective, {x, y}));
            }
        QVERIFY2(hi - lo > 100, qPrintable(QString("perspective depth spans only %1..%2").arg(lo).arg(hi)));
        QVERIFY(maxChannelDifference(ortho, perspective) > 30);
    }

    // Receivers no caster reaches are shaded without a lookup, and those that straddle the
    // reach are drawn twice under its stencil mask: the frame and the measured shadow term must
    // be exactly what a lookup everywhere gives, for every technique, light, bias and scene.
    // The frame and the measured visibility with lookups everywhere and with the reach's
    // variants and mask: the same, pixel for pixel and float for float.
    FrameStats compareSkippingOutOfReach(const Settings& settings, const std::optional<Scene>& custom)
    {
        Renderer& renderer = m_headless->renderer();
        if (custom)
            renderer.setScene(*custom);
        const auto restore = qScopeGuard([&] { renderer.setScene(std::nullopt); });
        // The hardware profile looks up everywhere; the software one skips what no caster reaches.
        // One clear a draw for both: depth slices may turn a comparison within one 24-bit step
        // (slicedMapsShadeAsClearedOnes bounds that), where the reach must change nothing at all.
        Settings plain = settings, tuned = settings;
        plain.rasteriser.profile = RasteriserProfile::Hardware;
        tuned.rasteriser.profile = RasteriserProfile::Software;
        plain.map.slices = tuned.map.slices = 1;
        const QImage everywhere = m_headless->renderScene(plain, kSize);
        const VisibilityBuffer measuredEverywhere = renderer.renderVisibility(plain, kSize);
        const QImage skipping = m_headless->renderScene(tuned, kSize);
        const FrameStats stats = renderer.lastFrame();
        const VisibilityBuffer measuredSkipping = renderer.renderVisibility(tuned, kSize);
        // msm's moment bias shades a receiver no caster reaches a little under lit where it is
        // looked up (ShadowTechnique::litToItsBias): the lookups are skipped only while that stays
        // under a step (skippedLookupsReadTheSame), and the pixels agree to within one.
        const bool toItsBias = settings.shadow.enabled && shadowTechnique(settings.filter.mode).litToItsBias;
        const float visibilityTolerance = toItsBias ? 1.0f / 256.0f : 0.0f;
        const int channelTolerance = toItsBias ? 1 : 0;
        int differing = 0;
        for (int y = 0; y < kSize.height(); ++y) {
            for (int x = 0; x < kSize.width(); ++x) {
                const QRgb a = everywhere.pixel(x, y), b = skipping.pixel(x, y);
                differing += std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b)),
                                       std::abs(qAlpha(a) - qAlpha(b))}) > channelTolerance;
            }
        }
        if (differing != 0)
            QTest::qFail(qPrintable(QStringLiteral("%1 pixels differ (%2 of %3 draws without a lookup%4)")
                                        .arg(differing).arg(stats.litPlainDraws).arg(stats.litDraws)
                                        .arg(stats.litReachMasked ? QStringLiteral(", masked") : QString())),
                         __FILE__, __LINE__);
        int visibilityDiffers = 0;
        float worst = 0.0f;
        for (std::size_t i = 0; i < measuredEverywhere.positionVisibility.size(); ++i) {
            const float d = std::abs(measuredEverywhere.positionVisibility[i].w - measuredSkipping.positionVisibility[i].w);
            worst = std::max(worst, d);
            visibilityDiffers += !(d <= visibilityTolerance);
        }
        if (visibilityDiffers != 0)
            QTest::qFail(qPrintable(QStringLiteral("%1 measured visibilities differ (by up to %2)").arg(visibilityDiffers).arg(worst)), __FILE__,
                         __LINE__);
        return stats;
    }

    void outOfReachShadingChangesNothing_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<bool>("groundCasts");
        // A receiver that casts nothing (a scene file's "casts": false) is in no caster's
        // column, however the moments of an empty map filter.
        for (const QString& t : {QStringLiteral("msm"), QStringLiteral("vsm"), QStringLiteral("evsm4"), QStringLiteral("esm"), QStringLiteral("pcf")})
            QTest::newRow(qPrintable(QStringLiteral("ground casts nothing, ") + t)) << "seed" << QStringList{"filter.mode=" + t} << false;
        for (const ShadowTechnique& t : shadowTechniques())
            QTest::newRow(qPrintable(QStringLiteral("seed, ") + t.key)) << "seed" << QStringList{"filter.mode=" + t.key} << true;
        QTest::newRow("ground in the map") << "seed" << QStringList{"bias.cull_front=false"} << true;
        QTest::newRow("no bias") << "seed" << QStringList{"bias.cull_front=false", "bias.footprint=false", "bias.skip_floors=false", "bias.slope=0", "bias.min=0"} << true;
        QTest::newRow("normal offset") << "seed" << QStringList{"bias.normal=3"} << true;
        QTest::newRow("receiver plane") << "seed" << QStringList{"filter.mode=pcf", "filter.kernel=7", "bias.receiver_plane=true", "bias.cull_front=false"} << true;
        // The high cube wholly before the near plane of a manual volume, stored at depth 0:
        // receiver-plane taps on its own faces may still compare deeper than that.
        QTest::newRow("receiver plane, a caster before the near plane")
            << "seed" << QStringList{"light.type=spot", "light.fit=manual", "light.near=4.2", "filter.mode=pcf", "filter.kernel=7",
                                     "bias.receiver_plane=true", "bias.cull_front=false", "bias.footprint=false", "bias.skip_floors=false", "bias.slope=0", "bias.min=0"} << true;
        QTest::newRow("receiver plane, an ortho near plane through the cubes")
            << "seed" << QStringList{"light.fit=manual", "light.near=4.3", "filter.mode=pcf", "filter.kernel=5", "bias.receiver_plane=true",
                                     "bias.cull_front=false", "bias.footprint=false", "bias.skip_floors=false", "bias.slope=0", "bias.min=0"} << true;
        QTest::newRow("depth units") << "seed" << QStringList{"bias.space=depth", "bias.slope=0.002", "bias.min=0.0005"} << true;
        QTest::newRow("texel units") << "seed" << QStringList{"bias.space=texel"} << true;
        QTest::newRow("reversed depth") << "seed" << QStringList{"map.format=depth32f"} << true;
        QTest::newRow("small map") << "seed" << QStringList{"map.size=64", "filter.mode=pcf", "filter.kernel=9"} << true;
        QTest::newRow("polygon offset") << "seed" << QStringList{"bias.cull_front=false", "bias.polygon_factor=2", "bias.polygon_units=4"} << true;
        QTest::newRow("mipmapped vsm") << "seed" << QStringList{"filter.mode=vsm", "moments.mipmaps=true"} << true;
        QTest::newRow("pcss early out") << "seed" << QStringList{"filter.mode=pcss", "filter.early_out=true"} << true;
        QTest::newRow("pcf early out") << "seed" << QStringList{"filter.mode=pcf", "filter.kernel=5", "filter.early_out=true"} << true;
        QTest::newRow("spot") << "seed" << QStringList{"light.type=spot"} << true;
        QTest::newRow("spot, normal offset") << "seed" << QStringList{"light.type=spot", "bias.normal=2", "filter.mode=pcf"} << true;
        QTest::newRow("point") << "seed" << QStringList{"light.type=point"} << true;
        QTest::newRow("point, pcf") << "seed" << QStringList{"light.type=point", "filter.mode=pcf", "bias.cull_front=false"} << true;
        QTest::newRow("cascades") << "seed" << QStringList{"shadow.cascades=3"} << true;
        QTest::newRow("perspective") << "seed" << QStringList{"light.projection=perspective", "light.fov=70"} << true;
        QTest::newRow("light straight above") << "seed" << QStringList{"light.position=0,6,0"} << true;
        QTest::newRow("grazing light") << "seed" << QStringList{"light.position=-9,0.4,-1"} << true;
        QTest::newRow("light below the ground") << "seed" << QStringList{"light.position=-2,-4,-1"} << true;
        QTest::newRow("manual volume") << "seed" << QStringList{"light.fit=manual"} << true;
        QTest::newRow("manual volume cutting the ground, normal offset")
            << "seed" << QStringList{"light.fit=manual", "light.extent=2.2", "light.far=6.3", "bias.normal=6", "map.size=128"} << true;
        QTest::newRow("normal offset, wide pcf, small map") << "seed" << QStringList{"bias.normal=8", "filter.mode=pcf", "filter.kernel=9", "map.size=96"} << true;
        QTest::newRow("negative polygon offset")
            << "seed" << QStringList{"bias.cull_front=false", "bias.polygon_factor=-16", "bias.polygon_units=-10000", "bias.min=0.05"} << true;
        QTest::newRow("cascades, normal offset") << "seed" << QStringList{"shadow.cascades=4", "bias.normal=4", "filter.mode=pcf"} << true;
        QTest::newRow("contact shadows") << "seed" << QStringList{"contact.enabled=true"} << true;
        QTest::newRow("contact shadows, long march, cascades")
            << "seed" << QStringList{"contact.enabled=true", "contact.length=3", "contact.thickness=1", "shadow.cascades=3"} << true;
        QTest::newRow("camera low and close") << "seed" << QStringList{"camera.position=2.5,0.3,2.5", "camera.target=0,0.5,0"} << true;
        QTest::newRow("camera from below") << "seed" << QStringList{"camera.position=1,-3,4"} << true;
        QTest::newRow("camera inside the reach") << "seed" << QStringList{"camera.position=-1.2,2.5,-0.6", "camera.target=0,0,0"} << true;
        QTest::newRow("texel density") << "seed" << QStringList{"shading.texel_density=true"} << true;
        QTest::newRow("phong") << "seed" << QStringList{"shading.model=phong"} << true;
        for (const QString& name : sceneNames()) {
            if (name != QLatin1String("seed"))
                QTest::newRow(qPrintable(name)) << name << QStringList{} << true;
        }
        // Every artifact preset and its fix: the settings chosen to show what goes wrong.
        for (const ArtifactPreset& preset : artifactPresets()) {
            for (bool fixed : {false, true}) {
                const Settings settings = fixed ? artifactPresetFixed(preset) : artifactPresetSettings(preset);
                QStringList assignments;
                for (const SettingKey& key : settingKeys())
                    assignments << key.key + QLatin1Char('=') + settingValue(settings, key.key);
                QTest::newRow(qPrintable(QStringLiteral("preset %1%2").arg(preset.name, fixed ? QStringLiteral(", fixed") : QString())))
                    << settings.scene << assignments << true;
            }
        }
        QTest::newRow("city, spot") << "city" << QStringList{"light.type=spot"} << true;
        QTest::newRow("city, normal offset") << "city" << QStringList{"bias.normal=3", "filter.mode=pcf"} << true;
        QTest::newRow("cubes, camera aside") << "cubes" << QStringList{"camera.position=9,2,-6"} << true;
        QTest::newRow("torus, pcss") << "torus" << QStringList{"filter.mode=pcss"} << true;
        // A smooth-shaded caster's facets that face away from the light are unlit in both
        // variants (OWN_FACETS), also where no view holds them: beyond the shadow distance.
        QTest::newRow("torus, vsm") << "torus" << QStringList{"filter.mode=vsm"} << true;
        QTest::newRow("torus, beyond the shadow distance") << "torus" << QStringList{"shadow.cascades=2", "shadow.distance=1"} << true;
        QTest::newRow("torus, grazing spot light") << "torus" << QStringList{"light.type=spot", "light.position=-6,0.6,1"} << true;
        // Four moments draw floors only around the casters, and look up only within their reach.
        for (const QString& t : {QStringLiteral("evsm4"), QStringLiteral("msm"), QStringLiteral("msm-hausdorff")}) {
            const QStringList mode{"filter.mode=" + t};
            QTest::newRow(qPrintable(t + ", grazing light")) << "seed" << mode + QStringList{"light.position=-9,0.4,-1"} << true;
            QTest::newRow(qPrintable(t + ", spot")) << "seed" << mode + QStringList{"light.type=spot"} << true;
            QTest::newRow(qPrintable(t + ", point")) << "seed" << mode + QStringList{"light.type=point"} << true;
            QTest::newRow(qPrintable(t + ", cascades")) << "seed" << mode + QStringList{"shadow.cascades=3"} << true;
            QTest::newRow(qPrintable(t + ", wide blur in the map")) << "seed" << mode + QStringList{"moments.blur=9"} << true;
            QTest::newRow(qPrintable(t + ", 16-bit, larger bias")) << "seed" << mode + QStringList{"moments.format=16", "filter.moment_bias=0.003"} << true;
            QTest::newRow(qPrintable(t + ", strong bleeding reduction")) << "seed" << mode + QStringList{"filter.bleeding=0.9"} << true;
            QTest::newRow(qPrintable("cubes, " + t)) << "cubes" << mode << true;
            QTest::newRow(qPrintable("city, " + t)) << "city" << mode << true;
        }
    }

    void outOfReachShadingChangesNothing()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        QFETCH(bool, groundCasts);
        Settings settings = presetSettings(scene);
        for (const QString& a : assignments)
            applyAssignment(settings, a);
        std::optional<Scene> custom;
        if (!groundCasts) {
            custom = buildScene(scene);
            custom->objects.front().castsShadow = false;
        }
        compareSkippingOutOfReach(settings, custom);
    }

    // A flat receiver's mask is its plane's pieces in the columns: exact on planes turned any
    // way, mirrored, seen from low and far, and on maps whose texels are far finer than a pixel.
    void flatReceiversAreMaskedExactly_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<double>("tilt");       // degrees the ground turns about x
        QTest::addColumn<bool>("mirrored");     // the ground's model flips x
        QTest::newRow("tilted 25 degrees") << QStringList{} << 25.0 << false;
        QTest::newRow("tilted -40 degrees, pcf 5") << QStringList{"filter.mode=pcf", "filter.kernel=5"} << -40.0 << false;
        QTest::newRow("mirrored") << QStringList{} << 0.0 << true;
        QTest::newRow("tilted and mirrored, normal offset") << QStringList{"bias.normal=3"} << 15.0 << true;
        QTest::newRow("camera grazing the ground") << QStringList{"camera.position=6,0.03,7", "camera.target=0,0.3,0"} << 0.0 << false;
        QTest::newRow("camera an inch above") << QStringList{"camera.position=1.5,0.002,3", "camera.target=-2,0.01,-3"} << 0.0 << false;
        QTest::newRow("camera far above") << QStringList{"camera.position=0.5,90,1", "camera.target=0,0,0", "camera.fov=10"} << 0.0 << false;
        QTest::newRow("camera far away, low") << QStringList{"camera.position=60,1.5,70"} << 0.0 << false;
        QTest::newRow("fine map, far camera") << QStringList{"map.size=8192", "camera.position=40,25,50"} << 0.0 << false;
        QTest::newRow("spot light on a tilted ground") << QStringList{"light.type=spot", "filter.mode=pcf"} << 20.0 << false;
        QTest::newRow("point light, cube faces") << QStringList{"light.type=point"} << 10.0 << false;
        QTest::newRow("cascades on a tilted ground") << QStringList{"shadow.cascades=3"} << 12.0 << false;
    }

    void flatReceiversAreMaskedExactly()
    {
        QFETCH(QStringList, assignments);
        QFETCH(double, tilt);
        QFETCH(bool, mirrored);
        Settings settings = presetSettings("seed");
        for (const QString& a : assignments)
            applyAssignment(settings, a);
        Scene scene = buildScene("seed");
        SceneObject& ground = scene.objects.front();
        ground.model = glm::rotate(glm::dmat4(1.0), glm::radians(tilt), glm::dvec3(1.0, 0.0, 0.0)) * ground.model;
        if (mirrored)
            ground.model = glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0)) * ground.model;
        const FrameStats stats = compareSkippingOutOfReach(settings, scene);
        qInfo("masked %d, %d of %d draws without a lookup", int(stats.litReachMasked), stats.litPlainDraws, stats.litDraws);
    }

    // Casters turned against the light reach only the hull of their own box's image: the
    // columns are prisms, not boxes, and a slab that straddles them (a receiver that is not
    // flat) is masked by the prisms' faces. Exact under every light, and tighter than boxes.
    void turnedCastersMaskExactly_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("directional") << QStringList{};
        QTest::newRow("directional, pcf 7") << QStringList{"filter.mode=pcf", "filter.kernel=7"};
        QTest::newRow("grazing light") << QStringList{"light.position=-9,0.8,3"};
        QTest::newRow("light straight above") << QStringList{"light.position=0.01,7,0"};
        QTest::newRow("spot") << QStringList{"light.type=spot"};
        QTest::newRow("point") << QStringList{"light.type=point"};
        QTest::newRow("cascades") << QStringList{"shadow.cascades=3"};
        QTest::newRow("normal offset") << QStringList{"bias.normal=4"};
        QTest::newRow("camera low, among the columns") << QStringList{"camera.position=2.6,0.4,-1.8", "camera.target=-0.5,0.2,0.8"};
    }

    void turnedCastersMaskExactly()
    {
        QFETCH(QStringList, assignments);
        Settings settings = presetSettings("seed");
        for (const QString& a : assignments)
            applyAssignment(settings, a);
        Scene scene = buildScene("seed");
        // Every cube turned a different way, and a slab under them, 3 x 0.2 x 3, that casts nothing.
        for (std::size_t i = 1; i < scene.objects.size(); ++i) {
            const glm::dvec3 axis = glm::normalize(glm::dvec3(double(i), 1.0, 2.0 - double(i)));
            scene.objects[i].model = scene.objects[i].model * glm::rotate(glm::dmat4(1.0), glm::radians(25.0 + 20.0 * double(i)), axis);
        }
        SceneObject slab = scene.objects[1];
        slab.name = QStringLiteral("slab");
        slab.castsShadow = false;           // a receiver only, so that it straddles the columns
        slab.model = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.3, -0.4, 0.6)), glm::dvec3(1.5, 0.1, 1.5));
        scene.objects.push_back(slab);
        const FrameStats stats = compareSkippingOutOfReach(settings, scene);
        m_headless->renderer().setScene(scene);
        m_headless->renderScene(settings, kSize);
        const ShadowReach& reach = m_headless->renderer().shadowReach();
        QCOMPARE(reach.partlyCount(), 2);                   // the ground and the slab
        qInfo("masked %d, %d of %d draws without a lookup, %d faces in the mask", int(stats.litReachMasked), stats.litPlainDraws, stats.litDraws,
              int(reach.mask.size()));
        m_headless->renderer().setScene(std::nullopt);
    }

    // Seed's ground is out of reach except around the cubes' columns: it is drawn with and
    // without a lookup under the mask, and a scene where nothing casts needs no lookup at all.
    void lookupsOnlyWhereACasterReaches()
    {
        m_headless->renderScene(presetSettings("seed"), kSize);
        const ShadowReach& reach = m_headless->renderer().shadowReach();
        QVERIFY(!reach.boxes.empty());
        QCOMPARE(reach.partlyCount(), 1);                   // the ground
        QVERIFY(reach.screenShare < 0.5);
        // The ground is flat: its mask is the pieces of its plane in the columns, no box face.
        QVERIFY(!reach.mask.empty());
        const double groundHeight = reach.mask.front().front().y;
        for (const convex::Polygon& piece : reach.mask) {
            for (const glm::dvec3& p : piece)
                QVERIFY2(std::abs(p.y - groundHeight) < 1e-6, qPrintable(QStringLiteral("a mask corner at height %1").arg(p.y)));
        }
        const FrameStats& stats = m_headless->renderer().lastFrame();
        QVERIFY(stats.litReachMasked);
        QCOMPARE(stats.litPlainDraws, 1);
        // Shadows of the cubes only: no caster at all.
        Scene ground = buildScene("seed");
        ground.objects.resize(1);
        m_headless->renderer().setScene(ground);
        m_headless->renderScene(presetSettings("seed"), kSize);
        QVERIFY(m_headless->renderer().shadowReach().boxes.empty());
        QCOMPARE(m_headless->renderer().lastFrame().litPlainDraws, m_headless->renderer().lastFrame().litDraws);
        m_headless->renderer().setScene(std::nullopt);
    }

    // A camera among the casters (the tutorial's, in the cubes' row; one behind a cube; one on
    // the ground's piece in a column) still masks: only the ground straddles, a cube that pokes
    // past the map's near plane, far plane or square is its own receiver, and the mask's parts
    // count only what of them is in view. The frame is the one that looks up everywhere.
    void camerasAmongTheCastersStillMask_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("the tutorial's camera") << QStringList{"camera.position=0,0,3", "camera.target=0,0,-1"};
        QTest::newRow("behind a cube, looking past it") << QStringList{"camera.position=2.6,0.6,3.2", "camera.target=-1,0,-2"};
        QTest::newRow("on the ground in a column") << QStringList{"camera.position=0.4,-0.45,0.9", "camera.target=-2,-0.3,-2"};
        QTest::newRow("tutorial camera, pcf 5 and normal offset")
            << QStringList{"camera.position=0,0,3", "camera.target=0,0,-1", "filter.mode=pcf", "filter.kernel=5", "bias.normal=2"};
        QTest::newRow("tutorial camera, a tight light volume")
            << QStringList{"camera.position=0,0,3", "camera.target=0,0,-1", "light.fit=manual", "light.near=4", "light.far=9"};
    }

    void camerasAmongTheCastersStillMask()
    {
        QFETCH(QStringList, assignments);
        Settings settings = presetSettings("seed");
        for (const QString& a : assignments)
            applyAssignment(settings, a);
        const FrameStats stats = compareSkippingOutOfReach(settings, std::nullopt);
        const ShadowReach& reach = m_headless->renderer().shadowReach();
        QCOMPARE(reach.partlyCount(), 1);   // the ground
        QVERIFY2(stats.litReachMasked, qPrintable(QStringLiteral("the mask covers %1 of the frame").arg(reach.screenShare)));
        QCOMPARE(stats.litPlainDraws, 1);   // the ground outside its pieces
    }

    // The city's thousands of buildings are drawn in batches: draws stay far below the objects
    // and do not grow with them, in the lit pass and the shadow pass.
    void manyObjectsAreDrawnInBatches()
    {
        int draws[2] = {0, 0};
        for (int k = 0; k < 2; ++k) {
            Settings s = presetSettings("city");
            applyAssignment(s, k == 0 ? "scene=city:2000" : "scene=city:8000");
            m_headless->renderer().invalidateShadowMap();
            m_headless->renderScene(s, kSize);
            const FrameStats& stats = m_headless->renderer().lastFrame();
            QVERIFY2(stats.shadowPassRendered, "the first frame of a scene draws its map");
            QVERIFY2(stats.shadowDraws < 200, qPrintable(QString::number(stats.shadowDraws)));
            QVERIFY2(stats.litDraws < 260, qPrintable(QString::number(stats.litDraws)));
            draws[k] = stats.shadowDraws;
        }
        QVERIFY2(draws[1] <= draws[0] + 10, qPrintable(QStringLiteral("%1 draws for 2,000 buildings, %2 for 8,000").arg(draws[0]).arg(draws[1])));
    }

    // A batch bakes each object's placement into its vertices: a mirroring placement keeps its
    // front faces (the winding turns with it), so mirrored cubes look like the cubes they are.
    void batchesKeepMirroredObjectsWhole()
    {
        const auto grid = [](bool mirrored) {
            Scene scene = buildScene("seed");
            const SceneObject cube = scene.objects.at(1);
            scene.objects.resize(1);
            for (int i = 0; i < 80; ++i) {
                SceneObject c = cube;
                c.texture = TextureKind::Flat;
                c.model = glm::translate(glm::dmat4(1.0), glm::dvec3(-4.0 + (i % 10) * 0.9, 0.3, -3.0 + (i / 10) * 0.8));
                c.model = glm::scale(c.model, glm::dvec3(mirrored && i % 2 ? -0.25 : 0.25, 0.25, 0.25));
                scene.objects.push_back(c);
            }
            return scene;
        };
        Settings s = presetSettings("seed");
        m_headless->renderer().setScene(grid(false));
        const QImage plain = m_headless->renderScene(s, kSize);
        QVERIFY(m_headless->renderer().lastFrame().litDraws < 40);
        m_headless->renderer().setScene(grid(true));
        const QImage mirrored = m_headless->renderScene(s, kSize);
        m_headless->renderer().setScene(std::nullopt);
        int differing = 0;
        for (int y = 0; y < kSize.height(); ++y)
            for (int x = 0; x < kSize.width(); ++x)
                differing += probe::luminance(plain, {x, y}) - probe::luminance(mirrored, {x, y}) > 8.0
                    || probe::luminance(mirrored, {x, y}) - probe::luminance(plain, {x, y}) > 8.0;
        QVERIFY2(differing < 20, qPrintable(QStringLiteral("%1 pixels differ").arg(differing)));
    }

    // map.slices: a map drawn into the next slice of its depth range instead of cleared shades
    // as one cleared before every draw, while the light walks around the scene, so each draw
    // lands where the last ones drew nothing and stands over what they left; the depth pane
    // shows the same map. Every technique that reads the depth map, every bias and scene, a
    // point light's six faces; spot and perspective lights keep their map's every bit and clear
    // every draw.
    void slicedMapsShadeAsClearedOnes_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        for (const ShadowTechnique& t : shadowTechniques()) {
            if (t.samplers.front() != ShadowSampler::Moments)
                QTest::newRow(qPrintable(QStringLiteral("seed, ") + t.key)) << "seed" << QStringList{"filter.mode=" + t.key};
        }
        QTest::newRow("pcf early out") << "seed" << QStringList{"filter.mode=pcf", "filter.kernel=5", "filter.early_out=true"};
        QTest::newRow("pcss early out") << "seed" << QStringList{"filter.mode=pcss", "filter.early_out=true"};
        QTest::newRow("receiver plane") << "seed" << QStringList{"filter.mode=pcf", "filter.kernel=7", "bias.receiver_plane=true"};
        QTest::newRow("ground in the map") << "seed" << QStringList{"bias.cull_front=false"};
        QTest::newRow("ground in the map, polygon offset") << "seed" << QStringList{"bias.cull_front=false", "bias.polygon_factor=2", "bias.polygon_units=4", "bias.min=0"};
        QTest::newRow("depth units") << "seed" << QStringList{"bias.space=depth", "bias.slope=0.002", "bias.min=0.0005"};
        // A bias in depth units is compared in the slice's stored depth: scaled with it, or the
        // shadows would detach by n times as much as set.
        QTest::newRow("depth units, peter panning") << "seed" << QStringList{"bias.space=depth", "bias.slope=0", "bias.min=0.02"};
        QTest::newRow("texel units") << "seed" << QStringList{"bias.space=texel"};
        QTest::newRow("polygon offset") << "seed" << QStringList{"bias.polygon_factor=2", "bias.polygon_units=4", "bias.min=0"};
        QTest::newRow("normal offset") << "seed" << QStringList{"bias.normal=3"};
        QTest::newRow("manual volume") << "seed" << QStringList{"light.fit=manual"};
        QTest::newRow("perspective") << "seed" << QStringList{"light.projection=perspective", "light.fov=70"};
        QTest::newRow("spot") << "seed" << QStringList{"light.type=spot", "filter.mode=pcf"};
        QTest::newRow("small map, wide pcf") << "seed" << QStringList{"map.size=64", "filter.mode=pcf", "filter.kernel=9"};
        QTest::newRow("8 slices") << "seed" << QStringList{"map.slices=8", "filter.mode=pcf"};
        QTest::newRow("3 slices") << "seed" << QStringList{"map.slices=3"};
        QTest::newRow("slices changed mid-way") << "seed" << QStringList{"map.slices=3", "raise slices"};
        QTest::newRow("lispsm") << "city" << QStringList{"light.warp=lispsm"};
        // A point light's faces move to the next slice together: a face that gains or loses its
        // casters as the light walks, and its neighbours', read through one slice.
        QTest::newRow("point") << "seed" << QStringList{"light.type=point"};
        QTest::newRow("point, pcf 5") << "seed" << QStringList{"light.type=point", "filter.mode=pcf", "filter.kernel=5"};
        QTest::newRow("point, pcss early out") << "seed" << QStringList{"light.type=point", "filter.mode=pcss", "filter.early_out=true"};
        QTest::newRow("point, depth units") << "seed" << QStringList{"light.type=point", "bias.space=depth", "bias.slope=0.002", "bias.min=0.0005"};
        QTest::newRow("point, ground in the map") << "seed" << QStringList{"light.type=point", "bias.cull_front=false", "bias.skip_floors=false"};
        QTest::newRow("point, cubes") << "cubes" << QStringList{"light.type=point"};
        for (const QString& name : sceneNames()) {
            if (name != QLatin1String("seed"))
                QTest::newRow(qPrintable(name)) << name << QStringList{};
        }
    }

    void slicedMapsShadeAsClearedOnes()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        // Raised from 3 to 8 slices after the fourth draw, one into a cycle: the earlier slices
        // lie anywhere under the new ones' and are cleared first.
        const bool raise = assignments.removeAll(QStringLiteral("raise slices")) > 0;
        Settings sliced = presetSettings(scene);
        for (const QString& a : assignments)
            applyAssignment(sliced, a);
        if (sliced.map.slices == 1)
            sliced.map.slices = 4;
        sliced.rasteriser.profile = RasteriserProfile::Software;   // slices are its optimisation, on any driver
        // Sliced whatever share of the map the casters cover (a wide filter's or a blocker
        // search's reach covers all of it), so every technique's lookups are checked on slices:
        // the next test checks where slices are left out.
        sliced.map.sliceCoverage = 1.0;
        Settings cleared = sliced;
        cleared.map.slices = 1;
        // Around the target and up and down, a step the slices do not divide: the map wraps.
        const LightAngles start = lightAngles(sliced.light.position, sliced.light.target);
        const int steps = 2 * sliced.map.slices + 3;
        const auto at = [&](Settings s, int step) {
            LightAngles a = start;
            a.azimuth += 47.0 * step;
            a.elevation = std::clamp(start.elevation + (step % 3 - 1) * 12.0, 8.0, 85.0);
            s.light.position = lightPosition(s.light.target, a);
            return s;
        };
        Renderer& r = m_headless->renderer();
        std::vector<QImage> expected, expectedMaps;
        for (int step = 0; step < steps; ++step) {
            expected.push_back(m_headless->renderScene(at(cleared, step), kSize));
            expectedMaps.push_back(m_headless->renderDepthMap(QSize(128, 128)));
            QVERIFY(r.lastFrame().shadowMapCleared);
        }
        int clears = 0;
        for (int step = 0; step < steps; ++step) {
            Settings s = at(sliced, step);
            if (raise && step >= 4)
                s.map.slices = 8;
            const QImage actual = m_headless->renderScene(s, kSize);
            const QImage actualMap = m_headless->renderDepthMap(QSize(128, 128));
            QVERIFY(r.lastFrame().shadowPassRendered);
            clears += r.lastFrame().shadowMapCleared;
            // The map keeps log2(map.slices) fewer bits of depth: a comparison within one
            // 24-bit step of its edge may go the other way, a pixel or two on a contact line.
            int differ = 0;
            for (int y = 0; y < kSize.height(); ++y)
                for (int x = 0; x < kSize.width(); ++x)
                    differ += expected[std::size_t(step)].pixel(x, y) != actual.pixel(x, y);
            QVERIFY2(differ <= 5, qPrintable(QString("step %1: %2 of %3 pixels differ from the cleared map's").arg(step).arg(differ).arg(kSize.width() * kSize.height())));
            // The depth pane shows the same depths, to a level of its colour ramp.
            const QImage& map = expectedMaps[std::size_t(step)];
            int paneDiffer = 0, worst = 0;
            for (int y = 0; y < map.height(); ++y) {
                for (int x = 0; x < map.width(); ++x) {
                    const QRgb e = map.pixel(x, y), a = actualMap.pixel(x, y);
                    const int d = std::max({std::abs(qRed(e) - qRed(a)), std::abs(qGreen(e) - qGreen(a)), std::abs(qBlue(e) - qBlue(a))});
                    paneDiffer += d > 0;
                    worst = std::max(worst, d);
                }
            }
            QVERIFY2(worst <= 1 && paneDiffer <= map.width() * map.height() / 100,
                     qPrintable(QString("step %1: %2 depth-pane pixels differ, by up to %3 of 255").arg(step).arg(paneDiffer).arg(worst)));
        }
        // One clear in map.slices draws, the first included; a spot, perspective or warped map
        // clears every draw.
        const int n = r.lastPlan().slices;
        const bool point = sliced.light.type == LightType::Point;
        QCOMPARE(n > 1, point || (sliced.light.projection == LightProjection::Ortho && sliced.light.warp == LightWarp::None));
        if (point)      // and a face whose casters left it is cleared where they were
            QVERIFY2(clears >= (steps + n - 1) / n && clears < steps, qPrintable(QString("%1 passes of %2 cleared").arg(clears).arg(steps)));
        else
            QCOMPARE(clears, raise ? 3 : (steps + n - 1) / n);     // raised: draws 0 and 3 of 3, then 4 of 8
        // A measurement draws into the first slice after a clear, whatever came before: the
        // same settings measure the same. The walk ended in a later slice (its last draw is the
        // third of a cycle, or the fifth after the raise).
        Settings last = at(sliced, steps - 1);
        if (raise)
            last.map.slices = 8;
        const bool laterSlice = r.shadowMap().depthSlices().index() > 0;
        QCOMPARE(laterSlice, n > 1);
        m_headless->makeCurrent();
        r.renderVisibility(last, kSize);
        QCOMPARE(r.lastFrame().shadowMapCleared, laterSlice);
        QCOMPARE(r.shadowMap().depthSlices().index(), 0);
    }

    // A draw into a slice reads what its casters cover from memory, where after a clear it
    // finds it in the cache: where they may cover most of the map (the ground drawn into it)
    // each draw clears; where they cover a third (seed's cubes), one in map.slices does.
    void slicesOnlyWhereCastersCoverLittleOfTheMap_data()
    {
        QTest::addColumn<bool>("groundInMap");
        QTest::addColumn<double>("sliceCoverage");  // map.slice_coverage
        QTest::addColumn<int>("clears");            // in 8 draws of 4 slices
        QTest::newRow("cubes only") << false << 0.85 << 2;
        QTest::newRow("the ground too") << true << 0.85 << 8;
        // map.slice_coverage moves the line: whatever the casters cover, or never.
        QTest::newRow("the ground too, sliced at any coverage") << true << 1.0 << 2;
        QTest::newRow("cubes only, never sliced") << false << 0.0 << 8;
    }

    void slicesOnlyWhereCastersCoverLittleOfTheMap()
    {
        QFETCH(bool, groundInMap);
        QFETCH(double, sliceCoverage);
        QFETCH(int, clears);
        Settings s = groundInMap ? seedWith({"bias.cull_front=false", "bias.skip_floors=false"}) : seedWith({"bias.cull_front=true"});
        s.map.sliceCoverage = sliceCoverage;
        const LightWalk walk = walkTheLight(s);
        QCOMPARE(walk.drawn, 8);
        QCOMPARE(walk.cleared, clears);
        for (const double coverage : walk.casterCoverage)
            QCOMPARE(coverage > 0.85, groundInMap);
    }

    // A point light's faces are sliced while a slice keeps their depth steps under an eighth of
    // a texel at the far plane, (far - near) / near up to 512 at 2048² and 4 slices: not where
    // it is 10^4, whose steps a slice would widen to 2.4 texels.
    void pointFacesSliceWhileTheirDepthStepsAllow_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<bool>("sliced");
        QTest::newRow("fitted") << QStringList{} << true;
        QTest::newRow("far / near 400") << QStringList{"light.fit=manual", "light.near=0.25", "light.far=100"} << true;
        QTest::newRow("far / near 600") << QStringList{"light.fit=manual", "light.near=0.166", "light.far=100"} << false;
        QTest::newRow("far / near 600 at 1024²") << QStringList{"light.fit=manual", "light.near=0.166", "light.far=100", "map.size=1024"} << true;
        QTest::newRow("far / near 10^4") << QStringList{"light.fit=manual", "light.near=0.01", "light.far=100"} << false;
    }

    void pointFacesSliceWhileTheirDepthStepsAllow()
    {
        QFETCH(QStringList, assignments);
        QFETCH(bool, sliced);
        Settings s = seedWith(assignments + QStringList{"light.type=point"});
        s.rasteriser.profile = RasteriserProfile::Software;
        const LightWalk walk = walkTheLight(s);
        QCOMPARE(walk.drawn, 8);
        QCOMPARE(walk.cleared, sliced ? 2 : 8);
        QCOMPARE(walk.sliced, sliced ? 8 : 0);
    }

    void everyPresetRenders()
    {
        for (const QString& name : sceneNames()) {
            const QImage on = m_headless->renderScene(presetSettings(name), kSize);
            const QImage off = m_headless->renderScene(withoutShadows(presetSettings(name)), kSize);
            int darker = 0;
            for (int y = 0; y < kSize.height(); y += 2)
                for (int x = 0; x < kSize.width(); x += 2)
                    darker += probe::visibilityRatio(on, off, {x, y}) < 0.6;
            QVERIFY2(darker > 50, qPrintable(QString("%1: only %2 shadowed pixels").arg(name).arg(darker)));
        }
    }
};

#include "HeadlessTestMain.h"
SHADOWLAB_TEST_MAIN(TestShadows)
#include "tst_Shadows.moc"
