// Every light type shadows what the Embree reference says, pixel by pixel: directional, spot
// (unlit outside its cone) and point (six cube faces), on every preset and from several
// placements; a point light shadows in all six directions; a light inside a caster or on a
// receiver gives a clear, finite result.
#include "Application.h"
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "Measurement.h"
#include "MomentMath.h"
#include "ReferenceAgreement.h"
#include "SceneLibrary.h"
#include "SceneNames.h"
#include "SettingsKeys.h"
#include "ShaderProgram.h"
#include "ShadowViews.h"
#include "RayTracer.h"
#include "ShadowReference.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <QtTest>

#include <cmath>

using namespace shadowlab;

Q_DECLARE_METATYPE(glm::dvec3)

namespace {

using probe::Agreement;
using probe::fromAngles;
using probe::describe;
using probe::agreement;

// A closed room (six inward-facing walls that receive) around a point light, with a small cube
// between the light and the middle of each wall.
Scene roomScene()
{
    Scene s;
    s.name = QStringLiteral("room");
    s.meshes.push_back(meshes::plane(4.0f, 4.0f));
    s.meshes.push_back(meshes::cube());
    for (const glm::dvec3& axis : cubeFaceAxes()) {
        // The plane's normal +y turned to face the room's centre (-axis).
        glm::dmat4 wall = glm::translate(glm::dmat4(1.0), axis * 4.0);
        const glm::dvec3 inward = -axis;
        const glm::dvec3 turn = glm::cross(glm::dvec3(0, 1, 0), inward);
        if (glm::length(turn) > 0.5)
            wall = glm::rotate(wall, glm::radians(90.0), turn);
        else if (inward.y < 0.0)
            wall = glm::rotate(wall, glm::radians(180.0), glm::dvec3(1, 0, 0));
        s.objects.push_back({QStringLiteral("wall"), 0, wall, TextureKind::Checker, false, true});
        const glm::dmat4 block = glm::scale(glm::translate(glm::dmat4(1.0), axis * 1.5), glm::dvec3(0.3));
        s.objects.push_back({QStringLiteral("block"), 1, block, TextureKind::Wood, true, true});
    }
    return s;
}

// A renderer with maps of its own beside the test's: when it goes, its context goes with it, and
// the test's renderer's is made current again, whatever the test's outcome.
class FreshRenderer {
public:
    explicit FreshRenderer(HeadlessRenderer& test) : m_test(test) {}
    ~FreshRenderer()
    {
        m_own.reset();
        m_test.makeCurrent();
    }
    HeadlessRenderer* operator->() { return m_own.get(); }

private:
    HeadlessRenderer& m_test;
    std::unique_ptr<HeadlessRenderer> m_own = std::make_unique<HeadlessRenderer>();
};

} // namespace

class TestLightTypes : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private Q_SLOTS:
    void initTestCase() { m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase() { m_headless.reset(); }

    void eachTypeAgreesWithTheReference_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("type");
        QTest::addColumn<glm::dvec3>("direction");   // from the target toward the light
        QTest::addColumn<double>("distance");
        QTest::addColumn<QString>("filter");
        const struct {
            double azimuth, elevation;
        } placements[] = {{30, 75}, {200, 50}, {300, 35}};
        const QStringList filters{"hard", "hw-bilinear", "pcf"};
        for (const QString& scene : sceneNames()) {
            // The foliage's lattice and leaves cast several times the other presets' shadow
            // edge per pixel, and what is wrong lies along edges: tst_Cutouts sweeps these
            // light types there against the edge's length.
            if (scene == u"foliage")
                continue;
            int k = 0;
            for (const QString type : {"directional", "spot", "point"}) {
                for (const auto& p : placements) {
                    // Point lights sit among the objects, spots a little farther out.
                    const double distance = type == "point" ? 3.5 + k % 2 : type == "spot" ? 7.0 : 1e3;
                    QTest::newRow(qPrintable(QString("%1 %2 az %3 el %4").arg(scene, type).arg(p.azimuth).arg(p.elevation)))
                        << scene << QString(type) << fromAngles(p.azimuth, p.elevation) << distance << filters[k % 3];
                    ++k;
                }
            }
        }
    }

    void eachTypeAgreesWithTheReference()
    {
        QFETCH(QString, scene);
        QFETCH(QString, type);
        QFETCH(glm::dvec3, direction);
        QFETCH(double, distance);
        QFETCH(QString, filter);
        Settings s = presetSettings(scene);
        applySetting(s, "light.type", type);
        applySetting(s, "filter.mode", filter);
        s.light.fov = 100.0;
        s.light.position = s.light.target + direction * distance;
        // A street-level view of a kilometre of city needs cascades (one map has texels of
        // half a metre there); the last reaches the camera's far plane, so all of it is tested.
        if (cityBuildingCount(scene) > 0 && type == "directional") {
            s.shadow.cascades = 4;
            s.shadow.distance = 1e5;
        }
        m_headless->renderer().setScene(std::nullopt);
        const QSize size(240, 135);
        const Agreement a = agreement(m_headless->renderer(), s, size);
        const QString numbers = describe(a);
        QVERIFY2(a.counted > 300, qPrintable(numbers));
        QVERIFY2(a.referenceShadowed > 0.005 * a.counted, qPrintable(numbers));
        // Shadows kept (at most 2 % of the reference's shadow lost at edges) and no acne.
        QVERIFY2(a.falseLight <= 0.02 * a.referenceShadowed + 0.002 * a.counted, qPrintable(numbers));
        QVERIFY2(a.falseShadow <= 0.003 * a.counted, qPrintable(numbers));
        if (type == "spot") {
            // The cone leaves part of the view unlit, and the renderer agrees there (above).
            const VisibilityBuffer buffer = probe::visibility(m_headless->renderer(), s, size);
            const LightFrame& light = m_headless->renderer().lightFrame();
            int outside = 0;
            for (int i = 0; i < buffer.pixelCount(); ++i) {
                if (buffer.mask(i) != VisibilityBuffer::FacingLight)
                    continue;
                const glm::dvec3 d = glm::normalize(buffer.worldPosition(i) - light.position);
                if (glm::dot(d, light.direction) < light.spotCosine - 1e-3) {
                    ++outside;
                    QCOMPARE(buffer.visibility(i), 0.0f);
                }
            }
            qInfo().noquote() << outside << "pixels outside the cone";
        }
        if (type == "point") {
            const ShadowViewFrames& views = m_headless->renderer().shadowViews();
            QCOMPARE(int(views.frames.size()), 6);
        }
        qInfo().noquote() << numbers;
    }

    // A point light in the middle of a room, a block before each wall: every wall has the
    // block's shadow where the reference puts it.
    void pointLightShadowsInAllSixDirections_data()
    {
        QTest::addColumn<int>("face");
        QTest::addColumn<QString>("filter");
        for (int face = 0; face < 6; ++face) {
            for (const QString filter : {"hard", "pcf"})
                QTest::newRow(qPrintable(QString("face %1 %2").arg(face).arg(filter))) << face << QString(filter);
        }
    }

    void pointLightShadowsInAllSixDirections()
    {
        QFETCH(int, face);
        QFETCH(QString, filter);
        m_headless->renderer().setScene(roomScene());
        Settings s;
        applySetting(s, "light.type", "point");
        applySetting(s, "filter.mode", filter);
        s.light.position = {0.12, 0.2, -0.07};
        s.light.target = {0.0, -1.0, 0.0};
        const glm::dvec3 axis = cubeFaceAxes()[std::size_t(face)];
        const glm::dvec3 side = std::abs(axis.y) > 0.5 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        // From beside the light, looking at the wall's middle, so the block does not hide its shadow.
        s.camera.position = -axis * 1.0 + side * 3.0 + glm::cross(axis, side) * 0.5;
        s.camera.target = axis * 4.0;
        s.camera.fov = 60.0;
        const Agreement a = agreement(m_headless->renderer(), s, QSize(200, 150));
        const QString numbers = describe(a);
        const FrameStats& stats = m_headless->renderer().lastFrame();
        m_headless->renderer().setScene(std::nullopt);
        QVERIFY2(a.counted > 1000, qPrintable(numbers));
        // The block's shadow on the wall is in view...
        QVERIFY2(a.referenceShadowed > 0.02 * a.counted, qPrintable(numbers));
        // ... and rendered where the reference has it.
        QVERIFY2(a.falseLight <= 0.03 * a.referenceShadowed + 0.002 * a.counted, qPrintable(numbers));
        QVERIFY2(a.falseShadow <= 0.003 * a.counted, qPrintable(numbers));
        // Faces that see no visible receiver are not drawn.
        QCOMPARE(int(stats.viewDraws.size()), 6);
        qInfo().noquote() << numbers;
    }

    // A point light whose near plane lies at 1e-4 of its far one, as the fit puts it when the
    // light is inside a caster's bounds (a rock model's): a depth near 1 then holds too few
    // bits for a distance inverted from it, and an exponential warp read that as shadow over
    // the lit floor (evsm4: 32 % of the cubes' frame). Every moment technique agrees with the
    // reference as the depth maps do.
    void momentsKeepTheirPrecisionWithTheNearPlaneClose_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("filter");
        for (const QString scene : {"seed", "cubes"}) {
            for (const QString filter : {"vsm", "evsm2", "evsm4", "msm", "msm-hausdorff", "esm"})
                QTest::newRow(qPrintable(scene + " " + filter)) << QString(scene) << QString(filter);
        }
    }

    void momentsKeepTheirPrecisionWithTheNearPlaneClose()
    {
        QFETCH(QString, scene);
        QFETCH(QString, filter);
        Settings s = presetSettings(scene);
        applySetting(s, "light.type", "point");
        applySetting(s, "filter.mode", filter);
        applySetting(s, "light.fit", "manual");
        s.light.nearPlane = 1e-3;
        s.light.farPlane = 20.0;
        m_headless->renderer().setScene(std::nullopt);
        const Agreement a = agreement(m_headless->renderer(), s, QSize(200, 150));
        const QString numbers = describe(a);
        QVERIFY2(a.counted > 1000 && a.referenceShadowed > 0.01 * a.counted, qPrintable(numbers));
        QVERIFY2(a.falseShadow <= 0.003 * a.counted, qPrintable(numbers));
        QVERIFY2(a.falseLight <= 0.02 * a.referenceShadowed + 0.002 * a.counted, qPrintable(numbers));
        qInfo().noquote() << numbers;
    }

    // A tile no view uses (3 cascades in a 2 x 2 map) reads lit, also after 4 cascades drew into
    // it: the depth-map view and its depth span show what the lookups can read, nothing older.
    void aTileNoViewUsesReadsLit()
    {
        m_headless->renderer().setScene(std::nullopt);
        Settings s = presetSettings("seed");
        s.shadow.cascades = 4;
        s.map.size = 256;
        m_headless->renderFrame(s, QSize(160, 90));
        s.shadow.cascades = 3;
        m_headless->renderFrame(s, QSize(160, 90));
        const ShadowMap& map = m_headless->renderer().shadowMap();
        QCOMPARE(map.width(), 512);
        QCOMPARE(map.height(), 512);
        m_headless->makeCurrent();
        GlFunctions* gl = m_headless->functions();
        std::vector<float> depth(std::size_t(map.width()) * std::size_t(map.height()));
        gl->glBindTexture(GL_TEXTURE_2D, map.texture());
        gl->glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        gl->glBindTexture(GL_TEXTURE_2D, 0);
        int drawn = 0, unusedWritten = 0;
        for (int y = 0; y < map.height(); ++y) {
            for (int x = 0; x < map.width(); ++x) {
                const bool unused = x >= map.size() && y >= map.size();     // column 1, row 1: the fourth cascade's
                const bool written = depth[std::size_t(y) * std::size_t(map.width()) + std::size_t(x)] < 1.0f;
                unusedWritten += unused && written;
                drawn += !unused && written;
            }
        }
        QVERIFY(drawn > 1000);
        QCOMPARE(unusedWritten, 0);
    }

    // A shadow pass clears and draws only where casters are (core/CasterTexels.h) and leaves a
    // view without casters alone: as the light moves, every frame is still, byte for byte, the
    // frame a fresh map gives. The counts say what was left out.
    void movingLightDrawsOnlyWhereCastersAre_data()
    {
        QTest::addColumn<QStringList>("light");
        QTest::newRow("point") << QStringList{"light.type=point"};
        QTest::newRow("point, vsm, blur pass") << QStringList{"light.type=point", "filter.mode=vsm", "moments.blur=5", "moments.blur_at=map"};
        QTest::newRow("point, evsm2, blur in the lookup") << QStringList{"light.type=point", "filter.mode=evsm2", "moments.blur=5"};
        QTest::newRow("4 cascades, pcf") << QStringList{"shadow.cascades=4", "filter.mode=pcf"};
        QTest::newRow("spot, msm") << QStringList{"light.type=spot", "filter.mode=msm", "moments.blur=7"};
        QTest::newRow("directional, esm") << QStringList{"filter.mode=esm"};
        // Cleared and drawn in pieces around each caster; four moments draw their floors there.
        QTest::newRow("directional, vsm") << QStringList{"filter.mode=vsm"};
        QTest::newRow("directional, evsm4") << QStringList{"filter.mode=evsm4"};
        QTest::newRow("directional, msm-hausdorff, blur pass") << QStringList{"filter.mode=msm-hausdorff", "moments.blur=9"};
        QTest::newRow("3 cascades, evsm4") << QStringList{"shadow.cascades=3", "filter.mode=evsm4"};
        QTest::newRow("point, msm") << QStringList{"light.type=point", "filter.mode=msm"};
    }

    void movingLightDrawsOnlyWhereCastersAre()
    {
        QFETCH(QStringList, light);
        m_headless->renderer().setScene(std::nullopt);
        FreshRenderer fresh(*m_headless);
        const QSize size(160, 90);
        Settings s = presetSettings("seed");
        s.map.size = 256;
        for (const QString& assignment : light)
            applySetting(s, assignment.section('=', 0, 0), assignment.section('=', 1));
        const glm::dvec3 start = s.light.position;
        for (int step = 0; step < 6; ++step) {
            const double a = 0.35 * step;
            s.light.position = start + glm::dvec3(std::cos(a) - 1.0, 0.2 * std::sin(a), std::sin(a));
            const QImage moving = m_headless->renderScene(s, size);
            Settings other = s;
            other.map.size = 272;       // a new map, then this one again: cleared whole
            fresh->renderFrame(other, size);
            const QImage reference = fresh->renderScene(s, size);
            QVERIFY2(moving == reference, qPrintable(QString("step %1: the frame differs from a fresh map's").arg(step)));
        }
        // A counted pass: what it cleared is no more than its views' tiles, and a point light
        // over the seed's casters clears at most the two faces that see them.
        const FrameCounts counts = countFrames(*m_headless, s, size);
        const int views = int(m_headless->renderer().shadowViews().set.views.size());
        const std::int64_t tile = std::int64_t(s.map.size) * s.map.size;
        QVERIFY2(counts.clearedTexels <= views * tile, qPrintable(QString::number(counts.clearedTexels)));
        if (s.light.type == LightType::Point)
            QVERIFY2(counts.clearedTexels <= 2 * tile, qPrintable(QString::number(counts.clearedTexels)));
        QVERIFY(counts.shadow.samples > 0 && counts.shadow.primitives > 0);
        QVERIFY(counts.lit.samples > 0 && counts.lookupFragments > 0 && counts.lookupFragments <= counts.lit.samples);
        QVERIFY(counts.mapBytes >= views * tile * 4);
        // The blur (two axes) covers the views with casters, no more: two faces of a point light.
        const int drawnViews = s.light.type == LightType::Point ? 2 : views;
        if (isMomentTechnique(s.filter.mode) && mapBlurWidth(s) > 1)
            QVERIFY2(counts.blurTexels > 0 && counts.blurTexels <= 2 * drawnViews * tile, qPrintable(QString::number(counts.blurTexels)));
        else
            QCOMPARE(counts.blurTexels, std::int64_t(0));   // a blur in the lookup, or none: no pass over the map
    }

    // A moments map keeps the far plane's moments where nothing was drawn (zeros with coverage);
    // another technique of as many channels reads them in its own encoding (msm's far plane is
    // no evsm4 moment, and four moments without coverage are none of vsm's), so a switch between
    // them, or of an exponent, gives the frame a fresh map gives, where casters moved away from
    // a tile as well.
    void switchingTheMomentEncodingKeepsFramesRight_data()
    {
        QTest::addColumn<QStringList>("first");
        QTest::addColumn<QStringList>("then");
        QTest::newRow("point: vsm, then evsm2") << QStringList{"light.type=point", "filter.mode=vsm"}
                                                << QStringList{"light.type=point", "filter.mode=evsm2"};
        QTest::newRow("point: msm, then vsm") << QStringList{"light.type=point", "filter.mode=msm"}
                                              << QStringList{"light.type=point", "filter.mode=vsm"};
        QTest::newRow("cascades: msm, then evsm4") << QStringList{"shadow.cascades=4", "filter.mode=msm"}
                                                   << QStringList{"shadow.cascades=4", "filter.mode=evsm4"};
        QTest::newRow("cascades: esm c40, then c20") << QStringList{"shadow.cascades=4", "filter.mode=esm", "filter.exponent_positive=40"}
                                                     << QStringList{"shadow.cascades=4", "filter.mode=esm", "filter.exponent_positive=20"};
    }

    void switchingTheMomentEncodingKeepsFramesRight()
    {
        QFETCH(QStringList, first);
        QFETCH(QStringList, then);
        m_headless->renderer().setScene(std::nullopt);
        FreshRenderer fresh(*m_headless);
        const QSize size(160, 90);
        const auto settings = [](const QStringList& assignments, const glm::dvec3& light) {
            Settings s = presetSettings("seed");
            s.map.size = 128;
            for (const QString& assignment : assignments)
                applySetting(s, assignment.section('=', 0, 0), assignment.section('=', 1));
            s.light.position = light;
            return s;
        };
        // The first technique with the light at one place, the second with it elsewhere, so
        // tiles the first drew are empty for the second.
        const glm::dvec3 start = presetSettings("seed").light.position;
        m_headless->renderFrame(settings(first, start), size);
        const Settings second = settings(then, start + glm::dvec3(1.5, 0.5, 1.0));
        const QImage switched = m_headless->renderScene(second, size);
        const QImage reference = fresh->renderScene(second, size);
        QVERIFY(switched == reference);
    }

    // Two channels (esm's moment and coverage) stored in RGBA (the software profile's choice,
    // RasteriserTuning::wideTwoChannelMoments) or in RG read the same: the frames are byte for
    // byte alike, whatever else the profiles leave out (the reach, the clear).
    void twoMomentsReadTheSameWideOrNarrow()
    {
        for (const char* mode : {"esm"}) {
            std::array<QImage, 2> frames;
            for (const bool wide : {true, false}) {
                FreshRenderer own(*m_headless);
                Settings s = presetSettings("torus");
                s.rasteriser.profile = wide ? RasteriserProfile::Software : RasteriserProfile::Hardware;
                s.map.size = 256;
                applySetting(s, "filter.mode", mode);
                frames[wide ? 0 : 1] = own->renderScene(s, QSize(160, 90));
                QCOMPARE(own->renderer().momentsMap()->channels(), wide ? 4 : 2);
            }
            QVERIFY2(frames[0] == frames[1], mode);
        }
    }

    // Cascades cover the whole shadow distance: the pixels within it agree with the reference,
    // and so do those next to each seam (within 5 % of a split), blended or not, stabilised
    // or not; pixels beyond the distance are lit, as the setting says.
    void cascadesAgreeAcrossTheSeams_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("cascades");
        QTest::addColumn<double>("blend");
        QTest::addColumn<bool>("stabilize");
        QTest::addColumn<QString>("split");
        QTest::addColumn<QString>("filter");
        QTest::addColumn<QString>("depthFit");
        // (Logarithmic splits put every seam within a metre of a camera whose near plane is a
        // few centimetres, out of these views; tst_LightRig checks their coverage.)
        const QStringList splits{"uniform", "practical"};
        int k = 0;
        for (const QString scene : {"seed", "cubes", "city"}) {
            // (Two cascades' one seam sits behind the near buildings or objects of these views.)
            for (int cascades : {3, 4}) {
                for (double blend : {0.0, 0.2}) {
                    const bool stabilize = (k % 2) == 0;
                    QTest::newRow(qPrintable(QString("%1 %2 cascades blend %3 %4 %5").arg(scene).arg(cascades).arg(blend).arg(stabilize ? "stabilised" : "tight", splits[(k / 2) % 2])))
                        << QString(scene) << cascades << blend << stabilize << splits[(k / 2) % 2] << QString() << QString("distance");
                    ++k;
                }
            }
        }
        // The wide filters read around the pixel: their taps, and PCSS's blocker search, must
        // stay inside the cascade's own tile of the map.
        for (const QString scene : {"seed", "city"}) {
            for (const QString filter : {"pcss", "poisson", "pcf"}) {
                QTest::newRow(qPrintable(QString("%1 4 cascades %2").arg(scene, filter)))
                    << QString(scene) << 4 << 0.1 << true << QString("practical") << QString(filter) << QString("distance");
            }
        }
        // Sample-distribution cascades: split over what the frame draws, the same coverage.
        for (const QString scene : {"seed", "cubes", "city"}) {
            for (int cascades : {2, 4}) {
                const bool stabilize = cascades == 4;
                QTest::newRow(qPrintable(QString("%1 %2 cascades sdsm %3").arg(scene).arg(cascades).arg(stabilize ? "stabilised" : "tight")))
                    << QString(scene) << cascades << 0.1 << stabilize << QString("practical") << QString() << QString("sdsm");
            }
        }
    }

    void cascadesAgreeAcrossTheSeams()
    {
        QFETCH(QString, scene);
        QFETCH(int, cascades);
        QFETCH(double, blend);
        QFETCH(bool, stabilize);
        QFETCH(QString, split);
        QFETCH(QString, filter);
        QFETCH(QString, depthFit);
        Settings s = presetSettings(scene);
        applySetting(s, "shadow.depth_fit", depthFit);
        if (!filter.isEmpty()) {
            applySetting(s, "filter.mode", filter);
            // Wide: a tap or a blocker search near a tile's edge reaches well into the next tile.
            applySetting(s, "filter.radius", "4");
            applySetting(s, "filter.kernel", "7");
        }
        s.shadow.cascades = cascades;
        s.shadow.blend = blend;
        s.light.stabilize = stabilize;
        applySetting(s, "shadow.split", split);
        s.map.size = 1024;
        // The distance ends inside the view, so pixels beyond it are there to check too.
        const double viewDistance = glm::length(s.camera.target - s.camera.position);
        s.shadow.distance = cityBuildingCount(scene) > 0 ? 100.0 : viewDistance * 1.3;
        m_headless->renderer().setScene(std::nullopt);
        Renderer& renderer = m_headless->renderer();
        const VisibilityBuffer buffer = probe::visibility(renderer, s, QSize(320, 180));
        const ShadowViewFrames& views = renderer.shadowViews();
        QCOMPARE(int(views.set.views.size()), cascades);
        const RayTracer tracer(*renderer.scene(), buffer.cameraPosition);
        ReferenceOptions options;
        options.area = false;
        const ReferenceVisibility reference = traceReference(tracer, buffer, renderer.lightFrame(), options);
        const glm::dvec3 forward = -glm::dvec3(views.camera.view[0][2], views.camera.view[1][2], views.camera.view[2][2]);
        int counted = 0, shadowed = 0, falseShadow = 0, falseLight = 0, seamCounted = 0, seamWrong = 0, beyond = 0, beyondShadowed = 0;
        for (int i = 0; i < buffer.pixelCount(); ++i) {
            if (buffer.mask(i) != VisibilityBuffer::FacingLight)
                continue;
            const double depth = glm::dot(buffer.worldPosition(i) - views.camera.position, forward);
            const float measured = buffer.visibility(i), expected = reference.hard[std::size_t(i)];
            if (depth > s.shadow.distance * 1.001) {
                ++beyond;
                beyondShadowed += measured < 0.5f;
                continue;
            }
            if (depth > s.shadow.distance * 0.999)
                continue;
            ++counted;
            shadowed += expected < 0.5f;
            const bool wrong = std::abs(measured - expected) > 0.5f;
            falseShadow += measured < expected - 0.5f;
            falseLight += measured > expected + 0.5f;
            for (int c = 0; c + 1 < cascades; ++c) {
                const double seam = views.set.views[std::size_t(c)].splitFar;
                if (std::abs(depth - seam) < 0.05 * seam) {
                    ++seamCounted;
                    seamWrong += wrong;
                }
            }
        }
        const QString numbers = QString("%1 counted within the distance, %2 shadowed, %3 false shadow, %4 false light; %5 next to a seam, "
                                        "%6 wrong there; %7 beyond, %8 of them shadowed")
                                    .arg(counted).arg(shadowed).arg(falseShadow).arg(falseLight).arg(seamCounted).arg(seamWrong).arg(beyond).arg(beyondShadowed);
        QVERIFY2(counted > 2000 && shadowed > 0.01 * counted, qPrintable(numbers));
        QVERIFY2(falseLight <= 0.02 * shadowed + 0.002 * counted, qPrintable(numbers));
        QVERIFY2(falseShadow <= 0.003 * counted, qPrintable(numbers));
        QVERIFY2(seamCounted > 50, qPrintable(numbers));
        QVERIFY2(seamWrong <= 0.01 * seamCounted + 2, qPrintable(numbers));
        QCOMPARE(beyondShadowed, 0);
        qInfo().noquote() << numbers;
    }

    // shadow.depth_fit = sdsm: the prepass's range holds every pixel the frame draws within
    // the distance, the cascades split it, and it is measured again only when the camera, the
    // scene or the size changes (a light moving keeps it).
    void sdsmFollowsTheFrame_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("more");
        QTest::newRow("city, street") << "city" << QStringList{};
        QTest::newRow("city, a street end close up") << "city" << QStringList{"camera.position=-98,1.7,-590", "camera.target=-98,3,-610"};
        QTest::newRow("city, from a roof") << "city" << QStringList{"camera.position=0,60,300", "camera.target=0,0,0"};
        QTest::newRow("seed") << "seed" << QStringList{};
        QTest::newRow("foliage, camera low") << "foliage" << QStringList{"camera.position=-1,0.6,3", "camera.target=0,0.5,-1"};
    }

    void sdsmFollowsTheFrame()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, more);
        Settings s = presetSettings(scene);
        for (const QString& a : more)
            applyAssignment(s, a);
        applySetting(s, "shadow.cascades", "4");
        applySetting(s, "shadow.depth_fit", "sdsm");
        s.shadow.distance = cityBuildingCount(scene) > 0 ? 300.0 : 30.0;
        m_headless->renderer().setScene(std::nullopt);
        Renderer& renderer = m_headless->renderer();
        const QSize size(320, 180);
        const VisibilityBuffer buffer = probe::visibility(renderer, s, size);
        QVERIFY(renderer.lastFrame().visibleDepthDraws > 0);
        QVERIFY(renderer.visibleDepthRange().has_value());
        const ShadowViewFrames& views = renderer.shadowViews();
        const double low = views.set.views.front().splitNear, high = views.set.views.back().splitFar;
        const glm::dvec3 forward = -glm::dvec3(views.camera.view[0][2], views.camera.view[1][2], views.camera.view[2][2]);
        int drawn = 0, outside = 0;
        double nearest = 1e300, farthest = 0.0;
        for (int i = 0; i < buffer.pixelCount(); ++i) {
            if (buffer.mask(i) == VisibilityBuffer::Background)
                continue;
            const double depth = glm::dot(buffer.worldPosition(i) - views.camera.position, forward);
            nearest = std::min(nearest, depth);
            farthest = std::max(farthest, depth);
            if (depth > s.shadow.distance)
                continue;
            ++drawn;
            outside += depth < low || depth > high;
        }
        const QString numbers = QString("cascades split %1..%2, pixels drawn %3..%4, %5 of %6 outside").arg(low).arg(high).arg(nearest).arg(farthest).arg(outside).arg(drawn);
        qInfo().noquote() << numbers;
        QVERIFY2(drawn > 1000 && outside <= 0.001 * drawn, qPrintable(numbers));
        // Tighter than the distance's range wherever the view does not reach both of its ends.
        QVERIFY2(low >= views.camera.nearPlane && high <= s.shadow.distance * (1.0 + 1e-9), qPrintable(numbers));
        QVERIFY2(low > views.camera.nearPlane * 2.0 || high < s.shadow.distance * 0.9, qPrintable(numbers));
        // A still frame and a moving light measure nothing again; a moving camera does.
        probe::visibility(renderer, s, size);
        QCOMPARE(renderer.lastFrame().visibleDepthDraws, 0);
        Settings lit = s;
        lit.light.position.x += 0.3 * glm::length(s.light.position - s.light.target);
        probe::visibility(renderer, lit, size);
        QCOMPARE(renderer.lastFrame().visibleDepthDraws, 0);
        Settings moved = s;
        moved.camera.position += 0.05 * (s.camera.target - s.camera.position);
        probe::visibility(renderer, moved, size);
        QVERIFY(renderer.lastFrame().visibleDepthDraws > 0);
    }

    // Stabilised maps do not shimmer: over a camera walk of a third of a texel per frame, the
    // receivers whose shadow flips are far fewer than with tight, unsnapped maps.
    void stabilisedMapsFlickerLess_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("cascades");
        // (On the small presets the casters, not the camera, bound the tight fit, so a sliding
        // camera moves neither map and neither flickers: the city is where the view does.)
        QTest::newRow("city, one map") << "city" << 1;
        QTest::newRow("city, 2 cascades") << "city" << 2;
        QTest::newRow("city, 4 cascades") << "city" << 4;
    }

    void stabilisedMapsFlickerLess()
    {
        QFETCH(QString, scene);
        QFETCH(int, cascades);
        m_headless->renderer().setScene(std::nullopt);
        const QSize size(480, 270);
        FlickerResult result[2];
        for (bool stabilize : {false, true}) {
            Settings s = presetSettings(scene);
            s.shadow.cascades = cascades;
            s.shadow.distance = cityBuildingCount(scene) > 0 ? 300.0 : 30.0;
            s.light.stabilize = stabilize;
            Renderer& renderer = m_headless->renderer();
            result[stabilize] = measureFlicker(renderer, s, subTexelPath(renderer, s, size, kFlickerFrames, kFlickerStepTexels), size);
        }
        const QString numbers = QString("flicker %1 % unstabilised, %2 % stabilised over %3 frames of %4 receiver pixels")
                                    .arg(100 * result[0].flicker).arg(100 * result[1].flicker).arg(result[1].frames).arg(result[1].pixels);
        QVERIFY2(result[1].pixels > 10000, qPrintable(numbers));
        QVERIFY2(result[0].flicker > 0.0, qPrintable(numbers));
        QVERIFY2(result[1].flicker <= 0.1 * result[0].flicker, qPrintable(numbers));
        qInfo().noquote() << numbers;
    }

    // The walk renders at full size only where the maps move; where they stay put its answer
    // (nothing flickers, the same receivers) is the one every frame rendered gives.
    void flickerWalkSkipsOnlyStillMaps_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<bool>("stabilize");
        QTest::addColumn<bool>("moves");
        QTest::newRow("seed, stabilised: snapped, the maps stay put") << "seed" << true << false;
        QTest::newRow("seed, unstabilised") << "seed" << false << true;
        QTest::newRow("city, unstabilised") << "city" << false << true;
    }

    void flickerWalkSkipsOnlyStillMaps()
    {
        QFETCH(QString, scene);
        QFETCH(bool, stabilize);
        QFETCH(bool, moves);
        m_headless->renderer().setScene(std::nullopt);
        const QSize size(320, 180);
        Settings s = presetSettings(scene);
        s.light.stabilize = stabilize;
        if (cityBuildingCount(scene) > 0)
            s.shadow.distance = 300.0;
        Renderer& renderer = m_headless->renderer();
        const std::vector<CameraSettings> path = subTexelPath(renderer, s, size, kFlickerFrames, kFlickerStepTexels);
        const FlickerResult every = measureFlicker(renderer, s, path, size, FlickerWalk::EveryFrame);
        const FlickerResult skipped = measureFlicker(renderer, s, path, size, FlickerWalk::WhereMapsMove);
        QCOMPARE(every.mapMoves > 0, moves);
        QCOMPARE(skipped.mapMoves, every.mapMoves);
        QCOMPARE(skipped.frames, every.frames);
        QCOMPARE(skipped.pixels, every.pixels);
        QCOMPARE(skipped.flicker, every.flicker);
        QCOMPARE(skipped.worstPair, every.worstPair);
        QCOMPARE(skipped.meanChange, every.meanChange);
        QVERIFY(every.pixels > 1000);
    }

    // A light inside a caster: everything it could light is behind the caster's walls.
    // A light on a receiver: grazing everything, still finite. Neither gives NaN.
    void degenerateLightPlacementsAreClear_data()
    {
        QTest::addColumn<QString>("type");
        QTest::addColumn<glm::dvec3>("position");
        QTest::addColumn<bool>("allDark");
        QTest::addColumn<bool>("agrees");
        for (const QString type : {"spot", "point"}) {
            QTest::newRow(qPrintable(type + " inside the high cube")) << QString(type) << glm::dvec3(0.05, 1.5, -0.03) << true << true;
            QTest::newRow(qPrintable(type + " resting on the ground")) << QString(type) << glm::dvec3(0.8, -0.499, 0.4) << false << true;
            // Exactly in the ground's plane the ground is lit edge-on (N.L = 0): which side of
            // zero it falls is rounding, in the reference too; only finiteness is asserted.
            QTest::newRow(qPrintable(type + " in the ground's plane")) << QString(type) << glm::dvec3(0.8, -0.5, 0.4) << false << false;
        }
    }

    void degenerateLightPlacementsAreClear()
    {
        QFETCH(QString, type);
        QFETCH(glm::dvec3, position);
        QFETCH(bool, allDark);
        QFETCH(bool, agrees);
        Settings s = presetSettings("seed");
        applySetting(s, "light.type", type);
        s.light.fov = 120.0;
        s.light.position = position;
        s.light.target = position + glm::dvec3(0.3, -1.0, 0.2);
        m_headless->renderer().setScene(std::nullopt);
        const VisibilityBuffer buffer = probe::visibility(m_headless->renderer(), s, QSize(160, 90));
        for (int i = 0; i < buffer.pixelCount(); ++i) {
            if (buffer.mask(i) == VisibilityBuffer::Background)
                continue;
            const float v = buffer.visibility(i);
            QVERIFY2(std::isfinite(v) && v >= 0.0f && v <= 1.0f, qPrintable(QString("pixel %1: visibility %2").arg(i).arg(v)));
        }
        if (!agrees)
            return;
        const Agreement a = agreement(m_headless->renderer(), s, QSize(160, 90));
        const QString numbers = describe(a);
        QVERIFY2(a.falseLight <= 0.02 * a.referenceShadowed + 0.002 * a.counted, qPrintable(numbers));
        QVERIFY2(a.falseShadow <= 0.003 * a.counted + 2, qPrintable(numbers));
        if (allDark)
            QVERIFY2(a.referenceShadowed == a.counted, qPrintable(numbers));
        qInfo().noquote() << numbers;
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(TestLightTypes)
#include "tst_LightTypes.moc"
