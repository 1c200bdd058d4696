// light.warp = lispsm against the Embree reference, pixel by pixel: the warped map keeps every
// shadow where the ray tracer puts it, with every filter family, the bias spaces, the normal
// offset and cascades, on every preset and from light placements overhead to grazing; it gives
// the receivers near a low camera finer texels than the unwarped map; and where the camera
// looks along the light (down at a light straight above, or with the light at its back) it
// falls back to no warp with a clear, finite frame.
#include "Application.h"
#include "DepthMapPicture.h"
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "LightWarp.h"
#include "Measurement.h"
#include "ReferenceAgreement.h"
#include "SceneLibrary.h"
#include "SceneNames.h"
#include "SettingsKeys.h"
#include "TexelDensity.h"

#include <glm/trigonometric.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace shadowlab;

namespace {

using probe::Agreement;
using probe::fromAngles;
using probe::describe;

// The camera brought down toward its target's height: a view across the receivers, where the
// warp's gain near the camera is largest.
void lowerCamera(Settings& s, double factor)
{
    glm::dvec3 offset = s.camera.position - s.camera.target;
    offset.y *= factor;
    s.camera.position = s.camera.target + offset;
}

} // namespace

class TestLightWarp : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private Q_SLOTS:
    void initTestCase() { m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase() { m_headless.reset(); }

    void warpAgreesWithTheReference_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("azimuth");
        QTest::addColumn<double>("elevation");
        QTest::addColumn<bool>("low");
        QTest::addColumn<QStringList>("assignments");
        const struct {
            double azimuth, elevation;
        } placements[] = {{30, 75}, {200, 50}, {300, 35}, {120, 14}, {10, 89.5}};
        // Every family of filter, the bias spaces, normal offset, receiver planes, reversed
        // depth, strong and weak warps.
        const QList<QStringList> variants{
            {"filter.mode=hard"},
            {"filter.mode=hw-bilinear"},
            {"filter.mode=pcf", "filter.kernel=5"},
            {"filter.mode=poisson", "filter.radius=3"},
            {"filter.mode=pcss"},
            {"filter.mode=pcf-optimized", "filter.kernel=5"},
            {"filter.mode=dpcf"},
            {"filter.mode=vsm"},
            {"filter.mode=msm"},
            {"filter.mode=evsm4"},
            {"bias.space=texel", "bias.slope=1.5", "bias.min=0.5"},
            {"bias.normal=1", "filter.mode=pcf"},
            {"bias.receiver_plane=true", "filter.mode=pcf", "filter.kernel=5"},
            {"map.format=depth32f"},
            {"light.warp_scale=0.3"},
            {"light.warp_scale=3", "filter.mode=poisson"},
        };
        int k = 0;
        for (const QString& scene : sceneNames()) {
            // The foliage's edges are swept in tst_Cutouts (they dominate any count of pixels).
            if (scene == u"foliage")
                continue;
            for (const auto& p : placements) {
                const bool low = (k % 3) == 1 && cityBuildingCount(scene) == 0;
                const QStringList& variant = variants[k % variants.size()];
                QTest::newRow(qPrintable(QString("%1 az %2 el %3%4 %5").arg(scene).arg(p.azimuth).arg(p.elevation).arg(low ? " low" : "", variant.join(' '))))
                    << scene << p.azimuth << p.elevation << low << variant;
                ++k;
            }
        }
        // Cascades, each warped over its own slice.
        for (const QString scene : {"seed", "cubes", "city"}) {
            for (const QString filter : {"hw-bilinear", "pcf", "pcss"}) {
                QTest::newRow(qPrintable(QString("%1 4 cascades %2").arg(scene, filter)))
                    << QString(scene) << 200.0 << 50.0 << false << QStringList{"shadow.cascades=4", "map.size=1024", "filter.mode=" + filter};
            }
        }
    }

    void warpAgreesWithTheReference()
    {
        QFETCH(QString, scene);
        QFETCH(double, azimuth);
        QFETCH(double, elevation);
        QFETCH(bool, low);
        QFETCH(QStringList, assignments);
        Settings s = presetSettings(scene);
        applySetting(s, "light.warp", "lispsm");
        s.light.position = s.light.target + fromAngles(azimuth, elevation) * 1e3;
        if (cityBuildingCount(scene) > 0 && s.shadow.cascades == 1) {
            s.shadow.cascades = 4;      // a street-level view of the city needs them (tst_LightTypes)
            s.shadow.distance = 1e5;
        }
        for (const QString& a : assignments)
            applyAssignment(s, a);
        if (low)
            lowerCamera(s, 0.35);
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        const QSize size(240, 135);
        const VisibilityBuffer buffer = probe::visibility(renderer, s, size);
        for (int i = 0; i < buffer.pixelCount(); ++i) {
            const float v = buffer.visibility(i);
            QVERIFY2(std::isfinite(v) && v >= 0.0f && v <= 1.0f, qPrintable(QString("pixel %1: visibility %2").arg(i).arg(v)));
        }
        int warped = 0;
        for (const ShadowView& view : renderer.shadowViews().set.views)
            warped += view.fit.warped;
        const Agreement a = probe::agreement(buffer, probe::hardReference(renderer, buffer), renderer.lightFrame());
        QString numbers = describe(a) + QString(", %1 of %2 views warped").arg(warped).arg(renderer.shadowViews().set.views.size());
        QVERIFY2(a.counted > 300, qPrintable(numbers));
        // A light straight above the city shadows little more than the buildings' feet.
        QVERIFY2(a.referenceShadowed > 0.001 * a.counted, qPrintable(numbers));
        // The same bounds as every light type's (tst_LightTypes): shadows kept, no acne. Where a
        // technique misses them on its own (msm's overdarkening on the bleeding scene, say), the
        // warp must do no worse than the same frame unwarped.
        const bool keeps = a.falseLight <= 0.02 * a.referenceShadowed + 0.002 * a.counted;
        const bool clean = a.falseShadow <= 0.003 * a.counted;
        if (!keeps || !clean) {
            applySetting(s, "light.warp", "none");
            const VisibilityBuffer plainBuffer = probe::visibility(renderer, s, size);
            const Agreement p = probe::agreement(plainBuffer, probe::hardReference(renderer, plainBuffer), renderer.lightFrame());
            numbers += "; unwarped: " + describe(p);
            const double slack = 0.0005 * a.counted;
            QVERIFY2(keeps || a.falseLight <= 1.05 * p.falseLight + slack, qPrintable(numbers));
            QVERIFY2(clean || a.falseShadow <= 1.05 * p.falseShadow + slack, qPrintable(numbers));
        }
        qInfo().noquote() << numbers;
    }

    // A camera low over the receivers, the light from the side: over the receivers both maps
    // reach, the nearer half to the camera gets finer texels from the warped map than from the
    // unwarped one at the same size (what LiSPSM trades the far field's for), on each scene.
    void warpGivesTheNearFieldFinerTexels_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("azimuth");
        QTest::addColumn<int>("mapSize");
        for (const QString scene : {"seed", "torus", "cubes", "occluder"}) {
            for (double azimuth : {40.0, 160.0, 250.0})
                QTest::newRow(qPrintable(QString("%1 az %2").arg(scene).arg(azimuth))) << QString(scene) << azimuth << (azimuth < 90.0 ? 256 : 128);
        }
    }

    void warpGivesTheNearFieldFinerTexels()
    {
        QFETCH(QString, scene);
        QFETCH(double, azimuth);
        QFETCH(int, mapSize);
        Settings s = presetSettings(scene);
        s.light.position = s.light.target + fromAngles(azimuth, 40.0) * 1e3;
        s.map.size = mapSize;
        lowerCamera(s, 0.3);
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        const QSize size(320, 180);
        std::vector<double> plain, warped;
        const VisibilityBuffer plainBuffer = probe::visibility(renderer, s, size);
        measureTexelDensity(plainBuffer, renderer.shadowViews(), renderer.lightFrame(), s.map.size, &plain);
        applySetting(s, "light.warp", "lispsm");
        const VisibilityBuffer buffer = probe::visibility(renderer, s, size);
        const FittedLight fit = renderer.lastFit();
        measureTexelDensity(buffer, renderer.shadowViews(), renderer.lightFrame(), s.map.size, &warped);
        // The pixels both maps reach, nearest to the camera first.
        struct Pixel {
            double distance, plain, warped;
        };
        std::vector<Pixel> both;
        for (int i = 0; i < buffer.pixelCount(); ++i) {
            if (std::isfinite(plain[std::size_t(i)]) && std::isfinite(warped[std::size_t(i)]))
                both.push_back({glm::length(buffer.worldPosition(i) - s.camera.position), plain[std::size_t(i)], warped[std::size_t(i)]});
        }
        QVERIFY2(both.size() > 2000, qPrintable(QString("%1 pixels in both maps").arg(both.size())));
        std::sort(both.begin(), both.end(), [](const Pixel& p, const Pixel& q) { return p.distance < q.distance; });
        const auto median = [](std::vector<double> v) {
            std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
            return v[v.size() / 2];
        };
        // Medians of the nearest tenth, the nearer half and the farther half of those pixels.
        const auto medians = [&](std::size_t from, std::size_t to) {
            std::vector<double> p, w;
            for (std::size_t k = from; k < to; ++k) {
                p.push_back(both[k].plain);
                w.push_back(both[k].warped);
            }
            return std::pair(median(p), median(w));
        };
        const auto [tenthPlain, tenthWarped] = medians(0, both.size() / 10);
        const auto [nearPlain, nearWarped] = medians(0, both.size() / 2);
        const auto [farPlain, farWarped] = medians(both.size() / 2, both.size());
        const QString numbers = QString("pixels per texel (median) unwarped / %1: nearest tenth %2 / %3, nearer half %4 / %5, farther half %6 / %7 "
                                        "(%8 pixels); gain at the nearest receiver %9")
                                    .arg(fit.warped ? "warped" : "not warped (no gain)").arg(tenthPlain).arg(tenthWarped).arg(nearPlain)
                                    .arg(nearWarped).arg(farPlain).arg(farWarped).arg(both.size()).arg(fit.warpGain);
        if (fit.warped) {
            QVERIFY2(fit.warpGain >= kWarpLeastGain, qPrintable(numbers));
            QVERIFY2(tenthWarped < 0.95 * tenthPlain, qPrintable(numbers));
            QVERIFY2(nearWarped < nearPlain, qPrintable(numbers));
        } else {
            // Declined: the warp would have made even the nearest texels no finer. The frame
            // is the unwarped one, texel for texel, and says why.
            QVERIFY2(fit.warpSkip == FittedLight::WarpSkip::NoGain && fit.warpGain < kWarpLeastGain, qPrintable(numbers));
            QVERIFY2(tenthWarped == tenthPlain && farWarped == farPlain, qPrintable(numbers));
        }
        qInfo().noquote() << numbers;
    }

    // Where the camera looks along the light, there is no warp to take: none is drawn, and the
    // frame agrees with the reference as an unwarped one does.
    void warpFallsBackAlongTheLight_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<bool>("lightBehind");  // the light at the camera's back, or straight above a camera looking down
        for (const QString scene : {"seed", "cubes", "torus"}) {
            QTest::newRow(qPrintable(QString("%1 looking down, light above").arg(scene))) << QString(scene) << false;
            QTest::newRow(qPrintable(QString("%1 light behind the camera").arg(scene))) << QString(scene) << true;
        }
    }

    void warpFallsBackAlongTheLight()
    {
        QFETCH(QString, scene);
        QFETCH(bool, lightBehind);
        Settings s = presetSettings(scene);
        applySetting(s, "light.warp", "lispsm");
        const double reach = glm::length(s.camera.position - s.camera.target);
        if (lightBehind) {
            s.light.target = s.camera.target;
            s.light.position = s.camera.target + (s.camera.position - s.camera.target) * 100.0;
        } else {
            s.camera.position = s.camera.target + glm::dvec3(0.0, reach, 0.0);
            s.light.position = s.light.target + glm::dvec3(0.0, 1e3, 0.0);
        }
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        const VisibilityBuffer buffer = probe::visibility(renderer, s, QSize(200, 120));
        QVERIFY(!renderer.lastFit().warped);
        for (int i = 0; i < buffer.pixelCount(); ++i)
            QVERIFY(std::isfinite(buffer.visibility(i)));
        const Agreement a = probe::agreement(buffer, probe::hardReference(renderer, buffer), renderer.lightFrame());
        const QString numbers = describe(a);
        QVERIFY2(a.counted > 300, qPrintable(numbers));
        QVERIFY2(a.falseLight <= 0.02 * a.referenceShadowed + 0.002 * a.counted, qPrintable(numbers));
        QVERIFY2(a.falseShadow <= 0.003 * a.counted, qPrintable(numbers));
        qInfo().noquote() << numbers;
    }

    // The depth-map view's distances: under a warp a depth means a different distance at each
    // texel, and the view undoes the warp at the texel to name it (the legend gives depths only).
    void depthMapViewNamesTheWarpedDistance()
    {
        Settings s = presetSettings("cubes");
        applySetting(s, "light.warp", "lispsm");
        lowerCamera(s, 0.3);
        Renderer& renderer = m_headless->renderer();
        renderer.setScene(std::nullopt);
        probe::visibility(renderer, s, QSize(160, 90));
        const LightFrame& light = renderer.lightFrame();
        QVERIFY(light.volume.warped);
        QVERIFY(std::isnan(depthToDistance(light, 0.5)));
        for (const glm::dvec3& p : {glm::dvec3(0.0), glm::dvec3(1.5, 0.2, -1.0), glm::dvec3(-2.0, 0.0, 2.0), glm::dvec3(0.5, 1.0, 0.5)}) {
            const glm::dvec4 c = light.shadowMatrix * glm::dvec4(p, 1.0);
            const glm::dvec3 t = glm::dvec3(c) / c.w;
            const double expected = glm::dot(p - light.position, light.direction);
            const double distance = depthToDistance(light, t.z, glm::dvec2(t));
            QVERIFY2(std::abs(distance - expected) <= 1e-6 * std::max(1.0, std::abs(expected)),
                     qPrintable(QString("%1 wu named, %2 wu along the light").arg(distance).arg(expected)));
        }
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(TestLightWarp)
#include "tst_LightWarp.moc"
