// Light and camera math without GL: finite, orthonormal, and mapping the right things to the
// right places for every light direction, including straight above and below.
#include "LightMath.h"
#include "SettingsError.h"

#include <glm/glm.hpp>

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
