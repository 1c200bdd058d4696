// Light and camera math without GL: finite, orthonormal, and mapping the right things to the
// right places for every light direction, including straight above and below.
#include "LightFitting.h"
#include "LightMath.h"
#include "SceneLibrary.h"
#include "SettingsError.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

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

} // namespace

class TestLightMath : public QObject {
    Q_OBJECT

private Q_SLOTS:
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
    // finite, orthonormal, never coarser than the volume as set, and covering every visible
    // receiver point (inside the map and between near and far).
    void fitIsFiniteAndContainsWhatIsSeen_data()
    {
        QTest::addColumn<glm::dvec3>("position");
        QTest::addColumn<glm::dvec3>("target");
        QTest::addColumn<bool>("perspective");
        QTest::addColumn<double>("nearPlane");
        QTest::addColumn<double>("farPlane");
        QTest::addColumn<double>("offset");
        const struct {
            const char* name;
            glm::dvec3 position, target;
            bool perspective;
            double nearPlane, farPlane, offset;
        } cases[] = {
            {"seed", {-2, 4, -1}, {0, 0, 0}, false, 1.0, 7.5, 0.0},
            {"seed perspective", {-2, 4, -1}, {0, 0, 0}, true, 1.0, 7.5, 0.0},
            {"straight above", {0, 6, 0}, {0, 0, 0}, false, 1.0, 10.0, 0.0},
            {"straight below", {0, -6, 0}, {0, 0, 0}, false, 1.0, 10.0, 0.0},
            {"straight above perspective", {0, 6, 0}, {0, 0, 0}, true, 1.0, 10.0, 0.0},
            {"grazing N.L = 1e-3", {10, -0.49, 0}, {0, -0.5, 0}, false, 0.5, 30.0, 0.0},
            {"N.L = 0", {10, -0.5, 0}, {0, -0.5, 0}, false, 0.5, 30.0, 0.0},
            {"perspective 1e-3 / 1e5", {-2, 4, -1}, {0, 0, 0}, true, 1e-3, 1e5, 0.0},
            {"ortho near 0", {-2, 4, -1}, {0, 0, 0}, false, 0.0, 7.5, 0.0},
            {"offset 1e5", {-2, 4, -1}, {0, 0, 0}, false, 1.0, 7.5, 1e5},
            {"offset 1e6", {-2, 4, -1}, {0, 0, 0}, false, 1.0, 7.5, 1e6},
            {"offset 1e6 perspective", {-2, 4, -1}, {0, 0, 0}, true, 1.0, 7.5, 1e6},
        };
        for (const auto& c : cases)
            QTest::newRow(c.name) << c.position << c.target << c.perspective << c.nearPlane << c.farPlane << c.offset;
    }

    void fitIsFiniteAndContainsWhatIsSeen()
    {
        QFETCH(glm::dvec3, position);
        QFETCH(glm::dvec3, target);
        QFETCH(bool, perspective);
        QFETCH(double, nearPlane);
        QFETCH(double, farPlane);
        QFETCH(double, offset);
        const glm::dvec3 shift(offset, 0.5 * offset, -offset);
        const Scene scene = buildScene("seed");
        std::vector<Bounds> boxes;
        for (const SceneObject& o : scene.objects)
            boxes.push_back(scene.worldBounds(o).transformed(glm::translate(glm::dmat4(1.0), shift)));
        Settings settings = presetSettings("seed");
        settings.camera.position += shift;
        settings.camera.target += shift;
        LightSettings light;
        light.position = position + shift;
        light.target = target + shift;
        light.projection = perspective ? LightProjection::Perspective : LightProjection::Ortho;
        light.nearPlane = nearPlane;
        light.farPlane = farPlane;
        Bounds all;
        for (const Bounds& b : boxes)
            all.extend(b);
        const glm::dmat4 camera = computeCameraFrame(settings.camera, 16.0 / 9.0, all).viewProjection;
        const LightFrame manual = computeLightFrame(light);

        for (const bool withCamera : {false, true}) {
            for (const bool stabilize : {false, true}) {
                light.stabilize = stabilize;
                const FittedLight fit = fitLight(light, boxes, boxes, withCamera ? std::optional(camera) : std::nullopt, 2048);
                const LightFrame f = computeLightFrame(fit.light, true);
                QVERIFY(isFinite(f.view) && isFinite(f.shadowMatrix) && isFinite(f.depthShadowMatrix));
                QVERIFY(isOrthonormal(f.view));
                QVERIFY(std::isfinite(fit.texelAfter) && fit.texelAfter > 0.0);
                QVERIFY(fit.texelAfter <= fit.texelBefore * (1.0 + 1e-12));
                QCOMPARE_LT(glm::length(f.direction - manual.direction), 1e-12);
                std::vector<glm::dmat4> seen{manual.viewProjection};
                if (withCamera)
                    seen.push_back(camera);
                for (const Bounds& b : boxes) {
                    for (const glm::dvec3& p : clipBoxToFrusta(b, seen)) {
                        const glm::dvec3 t = toShadowSpace(f, p);
                        const double tolerance = 1e-6;
                        QVERIFY2(t.x > -tolerance && t.x < 1.0 + tolerance && t.y > -tolerance && t.y < 1.0 + tolerance,
                                 qPrintable(QString("(%1, %2) outside the map").arg(t.x).arg(t.y)));
                        QVERIFY2(t.z > -tolerance && t.z < 1.0 + tolerance, qPrintable(QString("depth %1").arg(t.z)));
                    }
                }
            }
        }
    }

    void fitKeepsTheClassicVolumeWhenManual()
    {
        const Scene scene = buildScene("seed");
        std::vector<Bounds> boxes;
        for (const SceneObject& o : scene.objects)
            boxes.push_back(scene.worldBounds(o));
        LightSettings light;
        light.fit = LightFit::Manual;
        const FittedLight fit = fitLight(light, boxes, boxes, std::nullopt, 2048);
        QVERIFY(fit.light == light);
        QCOMPARE(fit.light.extent, 10.0);
        QCOMPARE(fit.light.nearPlane, 1.0);
        QCOMPARE(fit.light.farPlane, 7.5);
        QVERIFY(!fit.fitted);
        QCOMPARE(fit.texelAfter, 20.0 / 2048.0);
    }

    void fitWithNothingToCastSkipsTheShadow()
    {
        LightSettings light;
        Bounds ground{{-5, -0.5, -5}, {5, -0.5, 5}};
        QVERIFY(!fitLight(light, {}, {ground}, std::nullopt, 1024).anythingToShadow);
        Bounds beside{{50, 0, 50}, {51, 1, 51}}; // outside the volume as set
        QVERIFY(!fitLight(light, {beside}, {beside}, std::nullopt, 1024).anythingToShadow);
        QVERIFY(fitLight(light, {ground}, {ground}, std::nullopt, 1024).anythingToShadow);
    }

    void stabilizedFitIgnoresSmallCameraMoves()
    {
        const Scene scene = buildScene("seed");
        std::vector<Bounds> boxes;
        for (const SceneObject& o : scene.objects)
            boxes.push_back(scene.worldBounds(o));
        CameraSettings camera;
        LightSettings light;
        const auto fitFrom = [&](const CameraSettings& c) {
            return fitLight(light, boxes, boxes, computeCameraFrame(c, 16.0 / 9.0, scene.bounds()).viewProjection, 2048).light;
        };
        const LightSettings before = fitFrom(camera);
        int unchanged = 0;
        for (int i = 1; i <= 10; ++i) {
            CameraSettings moved = camera;
            moved.position.x += 0.002 * i;
            unchanged += fitFrom(moved) == before;
        }
        QVERIFY2(unchanged >= 8, qPrintable(QString("%1 of 10 small moves kept the volume").arg(unchanged)));
        // The centre moves in whole texels.
        const LightFrame f = computeLightFrame(before);
        const LightFrame m = computeLightFrame(LightSettings{});
        const glm::dvec3 shift = glm::dvec3(m.view * glm::dvec4(before.target, 1.0));
        const double texel = 2.0 * before.extent / 2048.0;
        QCOMPARE_LT(std::abs(shift.x / texel - std::round(shift.x / texel)), 1e-6);
        QCOMPARE_LT(std::abs(shift.y / texel - std::round(shift.y / texel)), 1e-6);
        QVERIFY(isFinite(f.shadowMatrix));
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
};

QTEST_APPLESS_MAIN(TestLightMath)
#include "tst_LightMath.moc"
