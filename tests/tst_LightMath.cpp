// Light and camera math without GL: finite, orthonormal, and mapping the right things to the
// right places for every light direction, including straight above and below.
#include "ConvexClipping.h"
#include "LightFitting.h"
#include "LightMath.h"
#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowReach.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <algorithm>
#include <cstdint>

using namespace shadowlab;

Q_DECLARE_METATYPE(glm::dvec3)

namespace {

bool isOrthonormal(const glm::dmat4& view)
{
    const glm::dmat3 r(view);
    const glm::dmat3 product = glm::transpose(r) * r;
    for (int c = 0; c < 3; ++c) {
        for (int row = 0; row < 3; ++row) {
            if (std::abs(product[c][row] - (c == row ? 1.0 : 0.0)) > 1e-12)
                return false;
        }
    }
    return std::abs(glm::determinant(r) - 1.0) < 1e-12;
}

glm::dvec3 toShadowSpace(const LightFrame& f, const glm::dvec3& p)
{
    const glm::dvec4 s = f.shadowMatrix * glm::dvec4(p, 1.0);
    return glm::dvec3(s) / s.w;
}

std::vector<FitObject> fitObjects(const Scene& scene, const glm::dvec3& shift = glm::dvec3(0.0))
{
    std::vector<FitObject> objects;
    for (const SceneObject& o : scene.objects) {
        objects.push_back({scene.worldBounds(o).transformed(glm::translate(glm::dmat4(1.0), shift)), o.castsShadow, true,
                           scene.meshes[std::size_t(o.mesh)].convex});
    }
    return objects;
}

// Does the segment p + t d, t in (0, reach], pass through the box (slab test)?
bool segmentHitsBox(const Bounds& b, const glm::dvec3& p, const glm::dvec3& d, double reach)
{
    double t0 = 1e-9, t1 = reach;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-300) {
            if (p[a] <= b.min[a] || p[a] >= b.max[a])
                return false;
            continue;
        }
        double lo = (b.min[a] - p[a]) / d[a], hi = (b.max[a] - p[a]) / d[a];
        if (lo > hi)
            std::swap(lo, hi);
        t0 = std::max(t0, lo);
        t1 = std::min(t1, hi);
        if (t0 > t1)
            return false;
    }
    return true;
}

// Points on the top and bottom faces of a box, on a grid, that lie inside every frustum in `seen`.
std::vector<glm::dvec3> surfaceSamples(const Bounds& b, const std::vector<glm::dmat4>& seen)
{
    std::vector<glm::dvec3> points;
    constexpr int n = 160;
    for (int k = 0; k < 2 * (n + 1) * (n + 1); ++k) {
        const int i = k % (n + 1), j = (k / (n + 1)) % (n + 1);
        {
            const double y = k < (n + 1) * (n + 1) ? b.max.y : b.min.y;
            const glm::dvec3 p(glm::mix(b.min.x, b.max.x, (i + 0.5) / (n + 1)), y, glm::mix(b.min.z, b.max.z, (j + 0.5) / (n + 1)));
            const bool visible = std::all_of(seen.begin(), seen.end(), [&](const glm::dmat4& m) {
                const glm::dvec4 c = m * glm::dvec4(p, 1.0);
                return c.w > 0.0 && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w;
            });
            if (visible)
                points.push_back(p);
        }
    }
    return points;
}

} // namespace

class TestLightMath : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void cameraFootprintIsWhatTheCameraSeesAsTheLightSeesIt()
    {
        // A light straight down over a flat 20 x 20 ground box, covering [-10, 10]^2: map
        // coordinates are the ground's x and z scaled to [0, 1].
        LightSettings light;
        light.position = {0.0, 10.0, 0.0};
        light.target = {0.0, 0.0, 0.0};
        light.extent = 10.0;
        light.nearPlane = 1.0;
        light.farPlane = 20.0;
        light.fit = LightFit::Manual;
        const LightFrame frame = computeLightFrame(light);
        Bounds ground;
        ground.extend(glm::dvec3(-10.0, -0.1, -10.0));
        ground.extend(glm::dvec3(10.0, 0.0, 10.0));
        // A camera straight above (0, 0, 3), looking down with a 40° field of view from height 5:
        // it sees about 2 * 5 * tan(20°) = 3.6 units of ground around that point.
        CameraSettings camera;
        camera.position = {0.0, 5.0, 3.0};
        camera.target = {0.0, 0.0, 3.001};
        camera.fov = 40.0;
        const CameraFrame view = computeCameraFrame(camera, 1.0, ground);
        const std::vector<glm::dvec2> footprint = cameraFootprint(ground, view.viewProjection, frame.shadowMatrix);
        QVERIFY(footprint.size() >= 4);
        glm::dvec2 lo(1e9), hi(-1e9);
        double area = 0.0;
        for (std::size_t i = 0; i < footprint.size(); ++i) {
            const glm::dvec2 a = footprint[i], b = footprint[(i + 1) % footprint.size()];
            area += a.x * b.y - a.y * b.x;
            lo = glm::min(lo, a);
            hi = glm::max(hi, a);
        }
        QVERIFY2(area > 0.0, "counter-clockwise");
        const glm::dvec4 centre = frame.shadowMatrix * glm::dvec4(0.0, 0.0, 3.0, 1.0);
        QVERIFY(lo.x < centre.x && centre.x < hi.x && lo.y < centre.y && centre.y < hi.y);
        const double side = 2.0 * 5.0 * std::tan(glm::radians(20.0)) / 20.0;    // in map units
        QVERIFY2(std::abs((hi.x - lo.x) - side) < 0.02 && std::abs((hi.y - lo.y) - side) < 0.02,
                 qPrintable(QString("footprint %1 x %2, expected about %3").arg(hi.x - lo.x).arg(hi.y - lo.y).arg(side)));
        // Looking away from the ground: nothing seen, no footprint.
        camera.target = {0.0, 10.0, 3.001};
        QVERIFY(cameraFootprint(ground, computeCameraFrame(camera, 1.0, ground).viewProjection, frame.shadowMatrix).empty());
    }

    void frameIsFiniteAndOrthonormal_data()
    {
        QTest::addColumn<glm::dvec3>("position");
        QTest::addColumn<bool>("perspective");
        const struct {
            const char* name;
            glm::dvec3 position;
        } cases[] = {
            {"seed light", {-2.0, 4.0, -1.0}},
            {"straight above", {0.0, 5.0, 0.0}},
            {"straight below", {0.0, -5.0, 0.0}},
            {"almost above", {1e-9, 5.0, 0.0}},
            {"grazing (N.L = 1e-3)", {5.0, 5e-3, 0.0}},
            {"horizontal (N.L = 0)", {5.0, 0.0, 0.0}},
            {"far away", {3e6, 4e6, -1e6}},
        };
        for (const auto& c : cases) {
            QTest::newRow(QByteArray(c.name).append(" ortho").constData()) << c.position << false;
            QTest::newRow(QByteArray(c.name).append(" perspective").constData()) << c.position << true;
        }
    }

    void frameIsFiniteAndOrthonormal()
    {
        QFETCH(glm::dvec3, position);
        QFETCH(bool, perspective);
        LightSettings light;
        light.position = position;
        light.target = {0.0, 0.0, 0.0};
        light.projection = perspective ? LightProjection::Perspective : LightProjection::Ortho;
        light.nearPlane = 0.5;
        light.farPlane = glm::length(position) * 2.0;
        const LightFrame f = computeLightFrame(light);
        QVERIFY(isFinite(f.view));
        QVERIFY(isFinite(f.projection));
        QVERIFY(isFinite(f.shadowMatrix));
        QVERIFY(isOrthonormal(f.view));
        QCOMPARE_LT(std::abs(glm::length(f.direction) - 1.0), 1e-12);
        // The target lands in the middle of the map, in front of the far plane.
        const glm::dvec3 t = toShadowSpace(f, light.target);
        QCOMPARE_LT(std::abs(t.x - 0.5), 1e-9);
        QCOMPARE_LT(std::abs(t.y - 0.5), 1e-9);
        QVERIFY(t.z > 0.0 && t.z < 1.0);
    }

    void orthoDepthIsLinearAlongTheLight()
    {
        LightSettings light; // seed: (-2, 4, -1) -> origin, near 1, far 7.5
        const LightFrame f = computeLightFrame(light);
        const glm::dvec3 atNear = light.position + f.direction * light.nearPlane;
        const glm::dvec3 atFar = light.position + f.direction * light.farPlane;
        const glm::dvec3 halfway = light.position + f.direction * (light.nearPlane + light.farPlane) * 0.5;
        QCOMPARE_LT(std::abs(toShadowSpace(f, atNear).z - 0.0), 1e-12);
        QCOMPARE_LT(std::abs(toShadowSpace(f, atFar).z - 1.0), 1e-12);
        QCOMPARE_LT(std::abs(toShadowSpace(f, halfway).z - 0.5), 1e-12);
    }

    void orthoExtentCoversTheMap()
    {
        LightSettings light;
        light.position = {0.0, 10.0, 0.0}; // straight above: x and z span the map
        light.extent = 4.0;
        const LightFrame f = computeLightFrame(light);
        const glm::dvec3 corner = toShadowSpace(f, {4.0, 0.0, 4.0});
        QCOMPARE_LT(std::abs(std::abs(corner.x - 0.5) - 0.5), 1e-12);
        QCOMPARE_LT(std::abs(std::abs(corner.y - 0.5) - 0.5), 1e-12);
        QCOMPARE(texelWorldSize(light, 1024), 8.0 / 1024.0);
    }

    void invalidLightsThrowNamingTheKey_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<double>("nearPlane");
        QTest::addColumn<double>("farPlane");
        QTest::addColumn<bool>("atTarget");
        QTest::addColumn<bool>("perspective");
        QTest::newRow("light at its target") << "light.position" << 1.0 << 10.0 << true << false;
        QTest::newRow("near = far") << "light.far" << 5.0 << 5.0 << false << false;
        QTest::newRow("near > far") << "light.far" << 6.0 << 5.0 << false << false;
        QTest::newRow("perspective near = 0") << "light.near" << 0.0 << 5.0 << false << true;
        QTest::newRow("perspective near < 0") << "light.near" << -1.0 << 5.0 << false << true;
        QTest::newRow("near is NaN") << "light.far" << std::nan("") << 5.0 << false << false;
    }

    void invalidLightsThrowNamingTheKey()
    {
        QFETCH(QString, key);
        QFETCH(double, nearPlane);
        QFETCH(double, farPlane);
        QFETCH(bool, atTarget);
        QFETCH(bool, perspective);
        LightSettings light;
        light.nearPlane = nearPlane;
        light.farPlane = farPlane;
        light.projection = perspective ? LightProjection::Perspective : LightProjection::Ortho;
        if (atTarget)
            light.position = light.target;
        try {
            computeLightFrame(light);
            QFAIL("expected a SettingsError");
        } catch (const SettingsError& e) {
            QCOMPARE(e.key(), key);
        }
    }

    // The fit for every extreme light of the audit, with and without a camera and snapping:
    // light.fit=scene: finite, orthonormal, and covering (inside the map, between near and far)
    // every visible receiver point that a caster shadows, for light directions all over the
    // sphere, any distance from the target, and scenes far from the origin.
    void fitCoversEveryShadowedReceiver_data()
    {
        QTest::addColumn<glm::dvec3>("direction");   // from the target toward the light
        QTest::addColumn<double>("distance");
        QTest::addColumn<bool>("perspective");
        QTest::addColumn<double>("offset");
        const struct {
            const char* name;
            glm::dvec3 direction;
            double distance;
            bool perspective;
            double offset;
        } cases[] = {
            {"seed", {-2, 4, -1}, 4.6, false, 0.0},
            {"seed, twice as far", {-2, 4, -1}, 9.2, false, 0.0},
            {"seed, 1e6 away", {-2, 4, -1}, 1e6, false, 0.0},
            {"seed perspective", {-2, 4, -1}, 4.6, true, 0.0},
            {"seed perspective, far", {-2, 4, -1}, 400.0, true, 0.0},
            {"within 0.1 deg of straight above", {std::sin(glm::radians(0.1)), std::cos(glm::radians(0.1)), 0}, 8.0, false, 0.0},
            {"straight above", {0, 1, 0}, 6.0, false, 0.0},
            {"straight above perspective", {0, 1, 0}, 6.0, true, 0.0},
            {"straight below", {0, -1, 0}, 6.0, false, 0.0},
            {"grazing 0.1 deg", {std::cos(glm::radians(0.1)), std::sin(glm::radians(0.1)), 0.3}, 6.0, false, 0.0},
            {"grazing 2 deg perspective", {std::cos(glm::radians(2.0)), std::sin(glm::radians(2.0)), 0}, 12.0, true, 0.0},
            {"low from behind", {1, 0.3, 2}, 1000.0, false, 0.0},
            {"offset 1e5", {-2, 4, -1}, 4.6, false, 1e5},
            {"offset 1e6", {-2, 4, -1}, 1e6, false, 1e6},
            {"offset 1e6 perspective", {-2, 4, -1}, 10.0, true, 1e6},
        };
        for (const auto& c : cases)
            QTest::newRow(c.name) << c.direction << c.distance << c.perspective << c.offset;
    }

    void fitCoversEveryShadowedReceiver()
    {
        QFETCH(glm::dvec3, direction);
        QFETCH(double, distance);
        QFETCH(bool, perspective);
        QFETCH(double, offset);
        const glm::dvec3 shift(offset, 0.5 * offset, -offset);
        const Scene scene = buildScene("seed");
        const std::vector<FitObject> objects = fitObjects(scene, shift);
        Settings settings = presetSettings("seed");
        settings.camera.position += shift;
        settings.camera.target += shift;
        LightSettings light;
        light.target = shift;
        light.position = shift + glm::normalize(direction) * distance;
        light.projection = perspective ? LightProjection::Perspective : LightProjection::Ortho;
        Bounds all;
        for (const FitObject& o : objects)
            all.extend(o.bounds);
        const glm::dmat4 camera = computeCameraFrame(settings.camera, 16.0 / 9.0, all).viewProjection;
        const LightFrame manual = computeLightFrame(light);

        for (const bool withCamera : {false, true}) {
            for (const bool stabilize : {false, true}) {
                light.stabilize = stabilize;
                const FittedLight fit = fitLight(light, objects, withCamera ? std::optional(camera) : std::nullopt, 2048);
                QVERIFY(fit.fitted && fit.anythingToShadow);
                const LightFrame f = computeLightFrame(light, fit.volume, true);
                QVERIFY(isFinite(f.view) && isFinite(f.shadowMatrix) && isFinite(f.depthShadowMatrix));
                QVERIFY(isOrthonormal(f.view));
                QVERIFY(std::isfinite(fit.texelAfter) && fit.texelAfter > 0.0);
                QCOMPARE_LT(glm::length(f.direction - manual.direction), 1e-12);
                std::vector<glm::dmat4> seen;
                if (withCamera)
                    seen.push_back(camera);
                int shadowed = 0;
                for (const FitObject& receiver : objects) {
                    for (const glm::dvec3& p : surfaceSamples(receiver.bounds, seen)) {
                        const glm::dvec3 toLight = perspective ? f.position - p : -f.direction;
                        const double reach = perspective ? 1.0 : 1e30;
                        const bool inShadow = std::any_of(objects.begin(), objects.end(), [&](const FitObject& caster) {
                            return &caster != &receiver && segmentHitsBox(caster.bounds, p, toLight, reach);
                        });
                        if (!inShadow)
                            continue;
                        ++shadowed;
                        const glm::dvec3 t = toShadowSpace(f, p);
                        const double tolerance = 1e-6;
                        QVERIFY2(t.x > -tolerance && t.x < 1.0 + tolerance && t.y > -tolerance && t.y < 1.0 + tolerance,
                                 qPrintable(QString("shadowed point (%1, %2) outside the map").arg(t.x).arg(t.y)));
                        QVERIFY2(t.z > -tolerance && t.z < 1.0 + tolerance, qPrintable(QString("shadowed point at depth %1").arg(t.z)));
                    }
                }
                QVERIFY2(shadowed > 0, "the case must shadow something to test the fit");
            }
        }
    }

    // A directional light is a direction: its distance from the target changes nothing.
    void directionalFitIgnoresDistance_data()
    {
        QTest::addColumn<double>("distance");
        for (const double d : {1.0, 4.6, 1e3, 1e6})
            QTest::newRow(qPrintable(QString("distance %1").arg(d))) << d;
    }

    void directionalFitIgnoresDistance()
    {
        QFETCH(double, distance);
        const Scene scene = buildScene("seed");
        const Settings settings = presetSettings("seed");
        const glm::dmat4 camera = computeCameraFrame(settings.camera, 16.0 / 9.0, scene.bounds()).viewProjection;
        LightSettings light;
        const auto shadowMatrix = [&](double d) {
            light.position = glm::normalize(glm::dvec3(-2, 4, -1)) * d;
            const FittedLight fit = fitLight(light, fitObjects(scene), camera, 2048);
            return computeLightFrame(light, fit.volume).shadowMatrix;
        };
        const glm::dmat4 reference = shadowMatrix(1.0);
        const glm::dmat4 other = shadowMatrix(distance);
        for (const glm::dvec3& p : scene.bounds().corners()) {
            const glm::dvec4 a = reference * glm::dvec4(p, 1.0), b = other * glm::dvec4(p, 1.0);
            QCOMPARE_LT(glm::length(a - b), 1e-9);
        }
    }

    // The map covers the casters' footprint on what is seen, not every visible receiver: on
    // seed the texel is several times finer than covering the visible ground would give.
    void fitCoversTheCastersNotTheWholeGround()
    {
        const Scene scene = buildScene("seed");
        const Settings settings = presetSettings("seed");
        const glm::dmat4 camera = computeCameraFrame(settings.camera, 16.0 / 9.0, scene.bounds()).viewProjection;
        LightSettings light = settings.light;
        light.stabilize = false;
        const FittedLight fit = fitLight(light, fitObjects(scene), camera, 2048);
        const LightFrame f = computeLightFrame(light, fit.volume);
        // The casters' light-space box, and the map's size around it.
        Bounds casters;
        for (std::size_t i = 1; i < scene.objects.size(); ++i) {
            for (const glm::dvec3& c : scene.worldBounds(scene.objects[i]).corners())
                casters.extend(glm::dvec3(f.view * glm::dvec4(c, 1.0)));
        }
        const double margin = 2048.0 / (2048.0 - 8.0) * (1.0 + 1e-9);
        QCOMPARE_LE(fit.volume.width(), (casters.max.x - casters.min.x) * margin);
        QCOMPARE_LE(fit.volume.height(), (casters.max.y - casters.min.y) * margin);
        QCOMPARE_LT(fit.texelAfter, 0.004);
    }

    void fitKeepsTheClassicVolumeWhenManual()
    {
        const Scene scene = buildScene("seed");
        LightSettings light;
        light.fit = LightFit::Manual;
        const FittedLight fit = fitLight(light, fitObjects(scene), std::nullopt, 2048);
        QVERIFY(fit.volume == manualVolume(light));
        QCOMPARE(fit.volume.width(), 20.0);
        QCOMPARE(fit.volume.nearPlane, 1.0);
        QCOMPARE(fit.volume.farPlane, 7.5);
        QVERIFY(!fit.fitted);
        QCOMPARE(fit.texelAfter, 20.0 / 2048.0);
    }

    // A manual volume that cuts visible receivers says how much and names the plane.
    void manualVolumeThatCutsSaysWhere_data()
    {
        QTest::addColumn<QString>("assignment");
        QTest::addColumn<QString>("key");
        QTest::newRow("short far") << "light.far=4" << "light.far";
        QTest::newRow("deep near") << "light.near=6" << "light.near";
        QTest::newRow("narrow extent") << "light.extent=1" << "light.extent";
        QTest::newRow("narrow cone") << "light.projection=perspective;light.fov=10;light.near=0.1" << "light.fov";
        QTest::newRow("all inside") << "light.extent=100;light.near=-100;light.far=100" << "";
    }

    void manualVolumeThatCutsSaysWhere()
    {
        QFETCH(QString, assignment);
        QFETCH(QString, key);
        const Scene scene = buildScene("seed");
        Settings settings = presetSettings("seed");
        settings.light.fit = LightFit::Manual;
        settings.light.extent = 30.0;
        settings.light.nearPlane = -30.0;
        settings.light.farPlane = 30.0;
        for (const QString& a : assignment.split(';'))
            applyAssignment(settings, a);
        const glm::dmat4 camera = computeCameraFrame(settings.camera, 16.0 / 9.0, scene.bounds()).viewProjection;
        const FittedLight fit = fitLight(settings.light, fitObjects(scene), camera, 2048);
        const std::vector<SettingsIssue> warnings = fitWarnings(fit);
        if (key.isEmpty()) {
            QVERIFY(warnings.empty());
            QCOMPARE_LT(fit.cutShare, 1e-3);
            return;
        }
        QCOMPARE(int(warnings.size()), 1);
        QCOMPARE(warnings[0].key, key);
        QVERIFY(fit.cutShare > 0.01 && fit.cutShare < 1.0);
        QVERIFY2(warnings[0].message.contains("lit without a shadow test"), qPrintable(warnings[0].message));
    }

    void fitWithNothingToCastSkipsTheShadow()
    {
        LightSettings light;
        const Bounds ground{{-5, -0.5, -5}, {5, -0.5, 5}};
        QVERIFY(!fitLight(light, {{ground, false, true, true}}, std::nullopt, 1024).anythingToShadow);
        // A convex caster alone shadows nothing but itself, which it cannot.
        const Bounds box{{50, 0, 50}, {51, 1, 51}};
        QVERIFY(!fitLight(light, {{box, true, true, true}}, std::nullopt, 1024).anythingToShadow);
        QVERIFY(fitLight(light, {{box, true, true, false}}, std::nullopt, 1024).anythingToShadow);
        // A caster beside the receiver, in the light's way: something to shadow.
        const Bounds above{{-1, 1, -1}, {1, 2, 1}};
        QVERIFY(fitLight(light, {{ground, false, true, true}, {above, true, true, true}}, std::nullopt, 1024).anythingToShadow);
    }

    void stabilizedFitIgnoresSmallCameraMoves()
    {
        const Scene scene = buildScene("seed");
        const std::vector<FitObject> objects = fitObjects(scene);
        const CameraSettings camera = presetSettings("seed").camera;
        LightSettings light;
        const auto fitFrom = [&](const CameraSettings& c) {
            return fitLight(light, objects, computeCameraFrame(c, 16.0 / 9.0, scene.bounds()).viewProjection, 2048).volume;
        };
        const LightVolume before = fitFrom(camera);
        int unchanged = 0;
        for (int i = 1; i <= 10; ++i) {
            CameraSettings moved = camera;
            moved.position.x += 0.002 * i;
            unchanged += fitFrom(moved) == before;
        }
        QVERIFY2(unchanged >= 8, qPrintable(QString("%1 of 10 small moves kept the volume").arg(unchanged)));
        // The centre moves in whole texels from the target.
        const glm::dmat4 view = stableLookAlong(light.target, before.direction);
        const glm::dvec3 shift = glm::dvec3(view * glm::dvec4(before.origin, 1.0));
        const double texelX = before.width() / 2048.0, texelY = before.height() / 2048.0;
        QCOMPARE_LT(std::abs(shift.x / texelX - std::round(shift.x / texelX)), 1e-6);
        QCOMPARE_LT(std::abs(shift.y / texelY - std::round(shift.y / texelY)), 1e-6);
    }

    // What flicker measures (the camera walk of `shadowlab report`: 0.37 of a fitted texel a
    // frame) moves a tight map only where the camera's view bounds the fit. From seed's own
    // camera every caster is in view over seen ground, so the casters bound it and the volume
    // stays put to the last bit: flicker 0 there is a fact, not a measurement that missed. From
    // a camera whose view cuts into that, the tight volume slides by a fraction of a texel each
    // frame (shimmer) and the stabilised one does not move.
    void tightFitFollowsTheCameraOnlyWhereTheViewBoundsIt_data()
    {
        QTest::addColumn<glm::dvec3>("position");
        QTest::addColumn<bool>("stabilize");
        QTest::addColumn<bool>("follows");
        const glm::dvec3 seedCamera = presetSettings("seed").camera.position;
        QTest::newRow("seed's camera, tight") << seedCamera << false << false;
        QTest::newRow("seed's camera, stabilised") << seedCamera << true << false;
        QTest::newRow("closer camera, tight") << glm::dvec3(3.0, 2.5, 4.0) << false << true;
        QTest::newRow("closer camera, stabilised") << glm::dvec3(3.0, 2.5, 4.0) << true << false;
    }

    void tightFitFollowsTheCameraOnlyWhereTheViewBoundsIt()
    {
        QFETCH(glm::dvec3, position);
        QFETCH(bool, stabilize);
        QFETCH(bool, follows);
        const Scene scene = buildScene("seed");
        const std::vector<FitObject> objects = fitObjects(scene);
        Settings settings = presetSettings("seed");
        settings.camera.position = position;
        settings.light.stabilize = stabilize;
        const int mapSize = settings.map.size;
        const auto fitFrom = [&](const CameraSettings& c) {
            return fitLight(settings.light, objects, computeCameraFrame(c, 640.0 / 360.0, scene.bounds()).viewProjection, mapSize);
        };
        const FittedLight first = fitFrom(settings.camera);
        QVERIFY(first.fitted && first.anythingToShadow);
        const glm::dmat4 view = stableLookAlong(settings.light.target, first.volume.direction);
        // How far a volume is from the one before: its centre, width and height in texels of the
        // first, and its near and far planes in steps of a 24-bit depth map over its depth.
        const double texelX = first.volume.width() / mapSize, texelY = first.volume.height() / mapSize;
        const double depthStep = (first.volume.farPlane - first.volume.nearPlane) / double(1 << 24);
        const auto texelsMoved = [&](const LightVolume& a, const LightVolume& b) {
            const glm::dvec3 shift = glm::dvec3(view * glm::dvec4(b.origin, 1.0)) - glm::dvec3(view * glm::dvec4(a.origin, 1.0));
            return std::max({std::abs(shift.x) / texelX, std::abs(shift.y) / texelY, std::abs(b.width() - a.width()) / texelX,
                             std::abs(b.height() - a.height()) / texelY});
        };
        const auto depthStepsMoved = [&](const LightVolume& a, const LightVolume& b) {
            return std::max(std::abs(b.nearPlane - a.nearPlane), std::abs(b.farPlane - a.farPlane)) / depthStep;
        };
        const std::vector<CameraSettings> walk = cameraPath(settings.camera, 8, first.texelAfter * 0.37);
        // Rounding may touch the last bits of a volume that stays put: a millionth of a texel
        // (or of a depth step) counts as still.
        const double still = 1e-6;
        int moved = 0;
        double least = 1e300, most = 0.0;
        LightVolume previous = first.volume;
        for (std::size_t i = 1; i < walk.size(); ++i) {
            const LightVolume volume = fitFrom(walk[i]).volume;
            const double texels = texelsMoved(previous, volume);
            moved += std::max(texels, depthStepsMoved(previous, volume)) > still;
            least = std::min(least, texels);
            most = std::max(most, texels);
            previous = volume;
        }
        const QString numbers = QString("%1 of %2 steps moved the volume, by %3 to %4 texels")
                                    .arg(moved).arg(walk.size() - 1).arg(least, 0, 'g', 3).arg(most, 0, 'g', 3);
        if (follows) {
            QVERIFY2(moved == int(walk.size()) - 1, qPrintable(numbers));
            QVERIFY2(most < 1.0, qPrintable(numbers));
        } else {
            QVERIFY2(moved == 0, qPrintable(numbers));
        }
        qInfo().noquote() << numbers;
    }

    void reversedDepthIsOneMinusConventional()
    {
        for (const bool perspective : {false, true}) {
            LightSettings light;
            light.projection = perspective ? LightProjection::Perspective : LightProjection::Ortho;
            light.nearPlane = 0.5;
            light.farPlane = 20.0;
            const LightFrame f = computeLightFrame(light, true);
            QVERIFY(f.reversedDepth);
            for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(1, -0.5, 2), glm::dvec3(-3, 1, 0.5)}) {
                const glm::dvec4 a = f.shadowMatrix * glm::dvec4(p, 1.0);
                const glm::dvec4 b = f.depthShadowMatrix * glm::dvec4(p, 1.0);
                QCOMPARE_LT(std::abs(b.z / b.w - (1.0 - a.z / a.w)), 1e-12);
                // Zero-to-one clip depth: stored depth is clip z / w itself.
                const glm::dvec4 c = f.depthViewProjection * glm::dvec4(p, 1.0);
                QCOMPARE_LT(std::abs(c.z / c.w - b.z / b.w), 1e-12);
            }
        }
    }

    void cameraEnclosesTheScene()
    {
        Bounds scene;
        scene.extend(glm::dvec3(-25.0, -0.5, -25.0));
        scene.extend(glm::dvec3(25.0, 2.0, 25.0));
        CameraSettings camera;
        const CameraFrame f = computeCameraFrame(camera, 16.0 / 9.0, scene);
        QVERIFY(isFinite(f.viewProjection));
        for (const glm::dvec3& c : scene.corners())
            QVERIFY(glm::length(c - camera.position) < f.farPlane);
        QVERIFY(f.nearPlane > 0.0 && f.nearPlane < 1.0);
    }

    void frustumCulling()
    {
        LightSettings light;
        light.position = {0.0, 10.0, 0.0};
        light.extent = 2.0;
        light.nearPlane = 1.0;
        light.farPlane = 20.0;
        const LightFrame f = computeLightFrame(light);
        Bounds inside{{-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}};
        Bounds beside{{5.0, 0.0, 5.0}, {6.0, 1.0, 6.0}};
        Bounds aboveNear{{-0.5, 9.5, -0.5}, {0.5, 9.8, 0.5}}; // between the light and its near plane
        QVERIFY(!isOutsideFrustum(f.viewProjection, inside, false));
        QVERIFY(isOutsideFrustum(f.viewProjection, beside, false));
        QVERIFY(isOutsideFrustum(f.viewProjection, aboveNear, false));
        QVERIFY(!isOutsideFrustum(f.viewProjection, aboveNear, true));
        QVERIFY(isOutsideFrustum(f.viewProjection, Bounds{}, true));
    }

    // The reach of a light straight above a ground with one cube: the cube's column, grown by
    // the filter's taps; the ground straddles it, a box off to the side is out of it, and the
    // culled ground itself casts nothing from above but does from below.
    void reachIsTheCastersColumns()
    {
        Settings s = presetSettings("seed");
        s.light.position = {0.0, 10.0, 0.0};
        s.light.target = {0.0, 0.0, 0.0};
        s.light.extent = 5.0;
        s.light.nearPlane = 1.0;
        s.light.farPlane = 20.0;
        const LightFrame light = computeLightFrame(s.light);
        CameraSettings cameraSettings;
        cameraSettings.position = {0.0, 6.0, 8.0};
        cameraSettings.target = {0.0, 0.0, 0.0};
        const Bounds scene{{-5.0, -1.0, -5.0}, {5.0, 2.0, 5.0}};
        const CameraFrame camera = computeCameraFrame(cameraSettings, 16.0 / 9.0, scene);
        const Bounds groundBounds{{-5.0, 0.0, -5.0}, {5.0, 0.0, 5.0}};
        std::vector<ReachObject> objects{
            {.bounds = groundBounds, .box = std::nullopt, .casts = true, .receives = true, .plane = WorldPlane{glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0)}, .frontFacesCulled = true},
            {.bounds = Bounds{{-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}}, .box = std::nullopt, .casts = true, .receives = true, .plane = std::nullopt, .frontFacesCulled = false},
            {.bounds = Bounds{{3.0, 0.0, 3.0}, {4.0, 0.5, 4.0}}, .box = std::nullopt, .casts = false, .receives = true, .plane = std::nullopt, .frontFacesCulled = false},
        };
        const ShadowReach reach = shadowReach(s, {light}, 1024, objects, objects, camera);
        QCOMPARE(int(reach.boxes.size()), 1);
        const ReachBox& box = reach.boxes.front();
        const double texel = 1.0 / 1024.0;
        const double grown = *tapReachTexels(s) * texel;
        // The cube spans 0.1 of the 10-unit map square around its centre.
        QVERIFY(std::abs((box.uvMax.x - box.uvMin.x) - (0.1 + 2.0 * grown)) < 1e-9);
        QVERIFY(box.depthMin > 0.0);                       // from the cube's top, not the near plane
        QCOMPARE(reach.objects[0], Reach::Partly);
        QCOMPARE(reach.objects[1], Reach::Inside);
        QCOMPARE(reach.objects[2], Reach::Outside);
        QVERIFY(reach.screenShare > 0.0 && reach.screenShare < 0.2);
        // The ground straddles the column and is flat: its mask is the piece of its plane in
        // the column, the cube's footprint grown by the taps, and not the column seen whole.
        QCOMPARE(int(reach.mask.size()), 1);
        Bounds piece;
        for (const glm::dvec3& p : reach.mask.front())
            piece.extend(p);
        QVERIFY(std::abs(piece.max.y) < 1e-6 && std::abs(piece.min.y) < 1e-6);
        QVERIFY(std::abs((piece.max.x - piece.min.x) - 10.0 * (box.uvMax.x - box.uvMin.x)) < 1e-3);
        QVERIFY(std::abs((piece.max.z - piece.min.z) - 10.0 * (box.uvMax.y - box.uvMin.y)) < 1e-3);
        QVERIFY(std::abs(piece.center().x) < 1e-6 && std::abs(piece.center().z) < 1e-6);
        // A receiver that is not flat and straddles too: the column's faces join the mask.
        std::vector<ReachObject> withRock = objects;
        withRock.push_back({.bounds = Bounds{{0.3, 0.0, 0.3}, {1.5, 0.2, 1.5}}, .box = std::nullopt, .casts = false, .receives = true, .plane = std::nullopt,
                            .frontFacesCulled = false});
        const ShadowReach rock = shadowReach(s, {light}, 1024, objects, withRock, camera);
        QCOMPARE(rock.objects[3], Reach::Partly);
        QCOMPARE(int(rock.mask.size()), 1 + 6);
        QVERIFY(rock.screenShare > reach.screenShare);
        // Seen edge-on from the camera, the plane's piece would be a line: the column stands in.
        CameraSettings level = cameraSettings;
        level.position = {0.0, 1e-4, 8.0};
        const ShadowReach edgeOn = shadowReach(s, {light}, 1024, objects, objects, computeCameraFrame(level, 16.0 / 9.0, scene));
        QCOMPARE(int(edgeOn.mask.size()), 6);

        // A light below sees the ground's back: it is drawn and reaches everything on it.
        s.light.position = {0.0, -10.0, 0.1};
        const ShadowReach below = shadowReach(s, {computeLightFrame(s.light)}, 1024, objects, objects, camera);
        QCOMPARE(int(below.boxes.size()), 1);
        QVERIFY(below.boxes.front().uvMax.x - below.boxes.front().uvMin.x > 0.99);

        // Wider taps reach further; pcss and mipmapped moments may read anywhere.
        Settings wide = s;
        wide.filter.mode = FilterMode::Pcf;
        wide.filter.kernel = 9;
        QVERIFY(*tapReachTexels(wide) > *tapReachTexels(s));
        wide.filter.mode = FilterMode::Pcss;
        QVERIFY(!tapReachTexels(wide));
        wide.filter.mode = FilterMode::Vsm;
        wide.moments.mipmaps = true;
        QVERIFY(!tapReachTexels(wide));
        // A receiver-plane tap may compare deeper than the receiver: no depth cut then.
        wide.filter.mode = FilterMode::Pcf;
        wide.bias.receiverPlane = true;
        QVERIFY(!referencesStayNearer(wide));
        wide.bias.receiverPlane = false;
        QVERIFY(referencesStayNearer(wide));
    }

    // A caster turned against the light's axes reaches only the hull of its box's image: a cube
    // turned 45 degrees under a light from above shadows a diamond, half its bounding square,
    // and a receiver in the square's corner beside it is out of reach. Ortho and spot lights.
    void reachOfATurnedCasterIsItsHull_data()
    {
        QTest::addColumn<bool>("spot");
        QTest::newRow("directional") << false;
        QTest::newRow("spot") << true;
    }

    void reachOfATurnedCasterIsItsHull()
    {
        QFETCH(bool, spot);
        Settings s;
        s.light.position = {0.0, 10.0, 0.0};
        s.light.target = {0.0, 0.0, 0.0};
        s.light.extent = 5.0;
        s.light.nearPlane = 1.0;
        s.light.farPlane = 20.0;
        if (spot) {
            s.light.type = LightType::Spot;
            s.light.projection = LightProjection::Perspective;
        }
        const LightFrame light = computeLightFrame(s.light);
        CameraSettings cameraSettings;
        cameraSettings.position = {0.0, 6.0, 8.0};
        cameraSettings.target = {0.0, 0.0, 0.0};
        const CameraFrame camera = computeCameraFrame(cameraSettings, 16.0 / 9.0, Bounds{{-5.0, -1.0, -5.0}, {5.0, 2.0, 5.0}});
        const glm::dmat4 turned = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.5, 0.0)), glm::radians(45.0), glm::dvec3(0.0, 1.0, 0.0));
        std::array<glm::dvec3, 8> cube = Bounds{glm::dvec3(-0.5), glm::dvec3(0.5)}.corners();
        for (glm::dvec3& c : cube)
            c = glm::dvec3(turned * glm::dvec4(c, 1.0));
        const Bounds cubeBounds = Bounds{glm::dvec3(-0.5), glm::dvec3(0.5)}.transformed(turned);
        const auto scene = [&](std::optional<std::array<glm::dvec3, 8>> box) {
            return std::vector<ReachObject>{
                {.bounds = Bounds{{-5.0, 0.0, -5.0}, {5.0, 0.0, 5.0}}, .box = std::nullopt, .casts = true, .receives = true,
                 .plane = WorldPlane{glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0)}, .frontFacesCulled = true},
                {.bounds = cubeBounds, .box = box, .casts = true, .receives = true, .plane = std::nullopt, .frontFacesCulled = false},
                {.bounds = Bounds{{0.56, 0.0, 0.56}, {0.62, 0.05, 0.62}}, .box = std::nullopt, .casts = false, .receives = true, .plane = std::nullopt,
                 .frontFacesCulled = false},
            };
        };
        const ShadowReach hull = shadowReach(s, {light}, 1024, scene(cube), scene(cube), camera);
        const ShadowReach square = shadowReach(s, {light}, 1024, scene(std::nullopt), scene(std::nullopt), camera);
        QCOMPARE(int(hull.boxes.size()), 1);
        QVERIFY(!hull.boxes.front().uvEdges.empty());
        QVERIFY(square.boxes.front().uvEdges.empty() || square.boxes.front().uvEdges.size() == 4);
        QCOMPARE(hull.objects[0], Reach::Partly);
        QCOMPARE(hull.objects[1], Reach::Inside);           // the cube is its own receiver, looked up everywhere
        QCOMPARE(hull.objects[2], Reach::Outside);          // beside the diamond
        QCOMPARE(square.objects[2], Reach::Inside);         // within the bounding square: looked up
        QCOMPARE(int(hull.mask.size()), 1);
        QCOMPARE(int(square.mask.size()), 1);
        const double hullArea = convex::area(hull.mask), squareArea = convex::area(square.mask);
        // The cube's shadow on the ground: its top corners seen from the light (the spot's
        // rays spread them by 10 / 9), which the piece must hold.
        const double spread = spot ? 10.0 / 9.0 : 1.0;
        const double radius = std::sqrt(0.5) * spread;
        // Both grow by the taps' reach, a few texels: the diamond's piece stays near half the square's.
        QVERIFY2(hullArea > 2.0 * radius * radius, qPrintable(QStringLiteral("hull %1, diamond %2").arg(hullArea).arg(2.0 * radius * radius)));
        QVERIFY2(hullArea < 0.6 * squareArea, qPrintable(QStringLiteral("hull %1, square %2").arg(hullArea).arg(squareArea)));
        const convex::Polygon& piece = hull.mask.front();
        for (const glm::dvec3& corner : {glm::dvec3(radius, 0.0, 0.0), glm::dvec3(-radius, 0.0, 0.0), glm::dvec3(0.0, 0.0, radius), glm::dvec3(0.0, 0.0, -radius)}) {
            // Inside a convex polygon: on the same side of every edge as its centre.
            glm::dvec3 centre(0.0);
            for (const glm::dvec3& p : piece)
                centre += p / double(piece.size());
            for (std::size_t i = 0; i < piece.size(); ++i) {
                const glm::dvec3 a = piece[i], b = piece[(i + 1) % piece.size()];
                const double side = glm::cross(b - a, corner - a).y * glm::cross(b - a, centre - a).y;
                QVERIFY2(side >= 0.0, qPrintable(QStringLiteral("the shadow's corner %1, %2 lies outside the mask").arg(corner.x).arg(corner.z)));
            }
        }
        // The column's faces, for receivers that are not flat: a prism over the hull.
        const std::vector<convex::Polygon> faces = hull.boxes.front().worldFaces();
        QVERIFY(faces.size() >= 6);
        const double prism = convex::area(faces), box = convex::area(convex::hexahedronFaces(hull.boxes.front().worldCorners()));
        QVERIFY2(prism < 0.8 * box, qPrintable(QStringLiteral("prism %1, box %2").arg(prism).arg(box)));
    }

    // A box clipped to frusta: whole where it lies inside (the fit's fast path, as a scene of
    // thousands of boxes mostly does), cut at the side it crosses, and cut by the second frustum
    // where only that one crosses it.
    void boxesAreClippedToFrusta()
    {
        const glm::dmat4 camera = glm::perspective(glm::radians(60.0), 1.5, 0.5, 100.0)
            * glm::lookAt(glm::dvec3(0.0, 0.0, 10.0), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
        const glm::dmat4 slab = glm::ortho(-20.0, 20.0, -20.0, 20.0, -20.0, 20.0) * glm::lookAt(glm::dvec3(0.0), glm::dvec3(0.0, -1.0, 0.0), glm::dvec3(0.0, 0.0, 1.0));
        const auto boundsOf = [](const std::vector<glm::dvec3>& points) {
            Bounds b;
            for (const glm::dvec3& p : points)
                b.extend(p);
            return b;
        };
        const Bounds inside{{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}};
        const Bounds whole = boundsOf(clipBoxToFrusta(inside, {camera, slab}));
        QVERIFY(glm::all(glm::equal(whole.min, inside.min)) && glm::all(glm::equal(whole.max, inside.max)));
        QCOMPARE(int(clipBoxToFrusta(inside, {camera}).size()), 8);         // its eight corners, uncut
        // Past the near plane (z = 9.5 along the view, 0.5 from the camera at z = 10).
        const Bounds across{{-0.2, -0.2, 8.0}, {0.2, 0.2, 12.0}};
        const Bounds cut = boundsOf(clipBoxToFrusta(across, {camera, slab}));
        QVERIFY2(std::abs(cut.max.z - 9.5) < 1e-6, qPrintable(QString::number(cut.max.z)));
        QVERIFY(std::abs(cut.min.z - 8.0) < 1e-9);
        // Reaching below the slab's bottom at y = -20 and out of the camera's sides: cut at
        // both, whichever frustum comes first.
        const Bounds deep{{-0.5, -30.0, -0.5}, {0.5, 0.5, 0.5}};
        const Bounds bySlab = boundsOf(clipBoxToFrusta(deep, {slab}));
        QVERIFY(std::abs(bySlab.min.y + 20.0) < 1e-9 && bySlab.max.y == 0.5);
        const Bounds both = boundsOf(clipBoxToFrusta(deep, {camera, slab})), swapped = boundsOf(clipBoxToFrusta(deep, {slab, camera}));
        QVERIFY(both.min.y > -20.0 && both.min.y < -5.0);
        QVERIFY(glm::length(both.min - swapped.min) < 1e-9 && glm::length(both.max - swapped.max) < 1e-9);
    }

    // The fit's clipper of many boxes (FrustaClip, which keeps each frustum's hull and its
    // buffers from box to box) finds exactly the points of intersecting the hulls one frustum
    // after another, in their order, for boxes inside, across, outside and flat, and for one,
    // two and three frusta; a box outside one of them is nothing.
    void frustaClipIsTheHullsIntersected()
    {
        const glm::dmat4 camera = glm::perspective(glm::radians(60.0), 1.5, 0.5, 40.0)
            * glm::lookAt(glm::dvec3(0.0, 2.0, 10.0), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
        const glm::dmat4 slab = glm::ortho(-6.0, 6.0, -5.0, 7.0, -20.0, 20.0) * glm::lookAt(glm::dvec3(0.0), glm::dvec3(0.3, -1.0, 0.2), glm::dvec3(0.0, 0.0, 1.0));
        const glm::dmat4 cone = glm::perspective(glm::radians(50.0), 1.0, 1.0, 30.0) * glm::lookAt(glm::dvec3(4.0, 8.0, 4.0), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
        const std::vector<std::vector<glm::dmat4>> sets{{camera}, {camera, slab}, {slab, camera, cone}};
        const auto byHulls = [](const Bounds& box, const std::vector<glm::dmat4>& frusta) {
            convex::Hull hull = convex::boxHull(box);
            for (const glm::dmat4& m : frusta)
                hull = convex::intersect(hull, convex::frustumHull(m));
            std::vector<glm::dvec3> points;
            for (const convex::Polygon& face : hull.faces)
                points.insert(points.end(), face.begin(), face.end());
            return points;
        };
        std::uint32_t state = 12345u;
        const auto next = [&state] {
            state = state * 1664525u + 1013904223u;
            return double(state >> 8) / double(1u << 24);
        };
        for (const std::vector<glm::dmat4>& frusta : sets) {
            FrustaClip clip(frusta);
            int inside = 0, across = 0, outside = 0;
            for (int k = 0; k < 400; ++k) {
                const double spread = k % 2 == 0 ? 4.0 : 16.0;     // half near the middle, half anywhere
                const glm::dvec3 centre((next() - 0.5) * spread, (next() - 0.4) * spread * 0.5, (next() - 0.5) * spread);
                glm::dvec3 half(next(), next(), next());
                half *= k % 3 == 0 ? 3.0 : 0.8;
                if (k % 7 == 0)
                    half.y = 0.0;       // a flat one, as a floor
                const Bounds box{centre - half, centre + half};
                const std::vector<glm::dvec3> got = clip(box);
                const bool out = std::any_of(frusta.begin(), frusta.end(), [&](const glm::dmat4& m) { return isOutsideFrustum(m, box, false); });
                if (out) {
                    QVERIFY(got.empty());
                    ++outside;
                    continue;
                }
                const std::vector<glm::dvec3> expected = byHulls(box, frusta);
                if (got.size() == 8 && expected.size() == 24) {
                    // Well inside every frustum: its corners, where the hulls give each corner three times.
                    for (const glm::dvec3& p : expected)
                        QVERIFY(std::find(got.begin(), got.end(), p) != got.end());
                    ++inside;
                    continue;
                }
                QCOMPARE(got.size(), expected.size());
                for (std::size_t i = 0; i < got.size(); ++i)
                    QVERIFY2(got[i] == expected[i], qPrintable(QStringLiteral("box %1, point %2").arg(k).arg(i)));
                ++across;
            }
            QVERIFY2(inside > 10 && across > 10 && outside > 10, qPrintable(QStringLiteral("%1 inside, %2 across, %3 outside").arg(inside).arg(across).arg(outside)));
        }
        // A whole box's range of each coordinate through a matrix is exactly its corners' least
        // and greatest, as the fit's bounds were from the corners one by one.
        for (const std::vector<glm::dmat4>& frusta : sets) {
            for (int k = 0; k < 200; ++k) {
                const glm::dvec3 centre((next() - 0.5) * 40.0, (next() - 0.5) * 40.0, (next() - 0.5) * 40.0);
                const Bounds box{centre - glm::dvec3(next(), next() * 5.0, 0.0), centre + glm::dvec3(next() * 3.0, next(), next())};
                for (int i = 0; i < 4; ++i) {
                    double least = 1e300, greatest = -1e300;
                    for (const glm::dvec3& c : box.corners()) {
                        least = std::min(least, (frusta.back() * glm::dvec4(c, 1.0))[i]);
                        greatest = std::max(greatest, (frusta.back() * glm::dvec4(c, 1.0))[i]);
                    }
                    const auto [low, high] = coordinateRange(frusta.back(), i, box);
                    QVERIFY2(low == least && high == greatest, qPrintable(QStringLiteral("coordinate %1: %2, %3 against %4, %5").arg(i).arg(low, 0, 'g', 17).arg(high, 0, 'g', 17).arg(least, 0, 'g', 17).arg(greatest, 0, 'g', 17)));
                }
            }
        }
    }

    // Nothing casts: no box, and every receiver is out of reach.
    void reachOfNothingIsEmpty()
    {
        Settings s = presetSettings("seed");
        const LightFrame light = computeLightFrame(s.light);
        const CameraFrame camera = computeCameraFrame(s.camera, 1.5, Bounds{{-5.0, -1.0, -5.0}, {5.0, 2.0, 5.0}});
        const std::vector<ReachObject> objects{{.bounds = Bounds{{-1.0, 0.0, -1.0}, {1.0, 1.0, 1.0}}, .box = std::nullopt, .casts = false, .receives = true, .plane = {}, .frontFacesCulled = false}};
        const ShadowReach reach = shadowReach(s, {light}, 2048, objects, objects, camera);
        QVERIFY(reach.boxes.empty());
        QCOMPARE(reach.objects.front(), Reach::Outside);
    }
};

QTEST_APPLESS_MAIN(TestLightMath)
#include "tst_LightMath.moc"
