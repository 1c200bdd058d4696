// The light rig without GL: light types and their settings, cascade splits, and the views a
// light fits (cascades covering the whole shadow distance, cube faces covering every direction).
#include "LightFitting.h"
#include "LightMath.h"
#include "LightWarp.h"
#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowViews.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <cmath>

using namespace shadowlab;

namespace {

std::vector<FitObject> fitObjects(const Scene& scene)
{
    std::vector<FitObject> objects;
    for (const SceneObject& object : scene.objects)
        objects.push_back({scene.worldBounds(object), object.castsShadow, object.receivesShadow, scene.meshes.at(std::size_t(object.mesh)).convex});
    return objects;
}

bool hasError(const Settings& s, const QString& key)
{
    for (const SettingsIssue& issue : validate(s)) {
        if (issue.severity == SettingsIssue::Severity::Error && issue.key == key)
            return true;
    }
    return false;
}

} // namespace

class TestLightRig : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void typeAndProjectionFollowEachOther()
    {
        Settings s;
        QVERIFY(s.light.type == LightType::Directional);
        applySetting(s, "light.type", "point");
        QVERIFY(s.light.projection == LightProjection::Perspective);
        applySetting(s, "light.type", "directional");
        QVERIFY(s.light.projection == LightProjection::Ortho);
        // An older file names only the projection: perspective means a spot light.
        applySetting(s, "light.projection", "perspective");
        QVERIFY(s.light.type == LightType::Spot);
        // A point light stays one when its (already perspective) projection is set again.
        applySetting(s, "light.type", "point");
        applySetting(s, "light.projection", "perspective");
        QVERIFY(s.light.type == LightType::Point);
        applySetting(s, "light.projection", "ortho");
        QVERIFY(s.light.type == LightType::Directional);
        QVERIFY(validate(s).empty());
        // Both keys in one file, in any order, load to what the file says.
        Settings fromFile = settingsFromJson(QJsonObject{{"light.type", "point"}, {"light.projection", "perspective"}}, Settings());
        QVERIFY(fromFile.light.type == LightType::Point);
        fromFile = settingsFromJson(QJsonObject{{"light.projection", "perspective"}}, Settings());
        QVERIFY(fromFile.light.type == LightType::Spot);
        // A saved file loads back to the same light.
        for (const char* type : {"directional", "spot", "point"}) {
            Settings original;
            applySetting(original, "light.type", type);
            QCOMPARE(settingsFromJson(settingsToJson(original), Settings()), original);
        }
    }

    void impossibleCombinationsAreRefused()
    {
        Settings s;
        s.light.type = LightType::Point;    // filled in by code, projection left ortho
        QVERIFY(hasError(s, "light.projection"));
        s.light.projection = LightProjection::Perspective;
        QVERIFY(validate(s).empty());
        s.shadow.cascades = 3;
        QVERIFY(hasError(s, "shadow.cascades"));
        Settings d;
        d.shadow.cascades = 2;
        d.light.fit = LightFit::Manual;
        QVERIFY(hasError(d, "shadow.cascades"));
        d.light.fit = LightFit::Scene;
        d.filter.earlyOut = true;     // penumbra-only filtering reads every view's tile of the one map
        QVERIFY(validate(d).empty());
        QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(d, "shadow.cascades", "5"));
        QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(d, "shadow.cascades", "0"));
        QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(d, "shadow.distance", "0"));
        QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(d, "shadow.distance", "nan"));
        QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(d, "shadow.split_lambda", "1.5"));
        QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(d, "shadow.blend", "0.6"));
        QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(d, "light.falloff", "-0.1"));
        QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(d, "light.type", "area"));
    }

    void splitsCoverTheDistance_data()
    {
        QTest::addColumn<int>("scheme");
        QTest::addColumn<double>("lambda");
        QTest::addColumn<double>("nearPlane");
        QTest::addColumn<double>("farPlane");
        for (int scheme = 0; scheme < 3; ++scheme) {
            for (double lambda : {0.0, 0.5, 1.0}) {
                for (auto [n, f] : {std::pair{0.1, 100.0}, std::pair{1e-3, 1e5}, std::pair{0.5, 0.5000001}, std::pair{1e-3, 1e7}}) {
                    QTest::newRow(qPrintable(QString("scheme %1 lambda %2 %3..%4").arg(scheme).arg(lambda).arg(n).arg(f)))
                        << scheme << lambda << n << f;
                }
            }
        }
    }

    void splitsCoverTheDistance()
    {
        QFETCH(int, scheme);
        QFETCH(double, lambda);
        QFETCH(double, nearPlane);
        QFETCH(double, farPlane);
        for (int count = 1; count <= kMaxCascades; ++count) {
            const std::vector<double> splits = cascadeSplits(CascadeSplit(scheme), lambda, nearPlane, farPlane, count);
            QCOMPARE(int(splits.size()), count + 1);
            QCOMPARE(splits.front(), nearPlane);
            QCOMPARE(splits.back(), farPlane);
            for (std::size_t i = 1; i < splits.size(); ++i) {
                QVERIFY(std::isfinite(splits[i]));
                QVERIFY2(splits[i] > splits[i - 1], qPrintable(QString("split %1: %2 after %3").arg(i).arg(splits[i]).arg(splits[i - 1])));
            }
        }
        // Logarithmic splits are equal ratios, uniform ones equal steps.
        const std::vector<double> log = cascadeSplits(CascadeSplit::Logarithmic, 0.0, nearPlane, farPlane, 4);
        const std::vector<double> uni = cascadeSplits(CascadeSplit::Uniform, 1.0, nearPlane, farPlane, 4);
        QVERIFY(std::abs(log[2] / log[1] - log[1] / log[0]) <= 1e-9 * log[1] / log[0]);
        QVERIFY(std::abs((uni[2] - uni[1]) - (uni[1] - uni[0])) <= 1e-9 * farPlane);
    }

    void degenerateSplitInputsStayFinite()
    {
        for (auto [n, f] : {std::pair{0.0, 10.0}, std::pair{-1.0, 10.0}, std::pair{5.0, 1.0}, std::pair{double(NAN), double(INFINITY)}}) {
            const std::vector<double> splits = cascadeSplits(CascadeSplit::Practical, 0.5, n, f, 4);
            for (std::size_t i = 0; i < splits.size(); ++i) {
                QVERIFY(std::isfinite(splits[i]) && splits[i] > 0.0);
                if (i > 0)
                    QVERIFY(splits[i] > splits[i - 1]);
            }
        }
    }

    // shadow.depth_fit = sdsm splits the drawn range, padded, within the distance's; without a
    // usable range it splits the distance's, as shadow.depth_fit = distance always does.
    void sdsmSplitsTheDrawnRange_data()
    {
        QTest::addColumn<double>("nearest");
        QTest::addColumn<double>("farthest");
        QTest::addColumn<double>("low");      // the expected range; 0: the distance's
        QTest::addColumn<double>("high");
        const double pad = kSdsmPadding;
        QTest::newRow("inside") << 5.0 << 40.0 << 5.0 * (1.0 - pad) << 40.0 * (1.0 + pad);
        QTest::newRow("beyond the distance") << 5.0 << 400.0 << 5.0 * (1.0 - pad) << 100.0;
        QTest::newRow("nearer than the near plane") << 0.01 << 40.0 << 0.1 << 40.0 * (1.0 + pad);
        QTest::newRow("one depth") << 10.0 << 10.0 << 10.0 * (1.0 - pad) << 10.0 * (1.0 + pad);
        QTest::newRow("all beyond the distance") << 200.0 << 300.0 << 0.0 << 0.0;
        QTest::newRow("NaN") << double(NAN) << 40.0 << 0.0 << 0.0;
        QTest::newRow("infinite") << 5.0 << double(INFINITY) << 0.0 << 0.0;
        QTest::newRow("reversed") << 40.0 << 5.0 << 0.0 << 0.0;
    }

    void sdsmSplitsTheDrawnRange()
    {
        QFETCH(double, nearest);
        QFETCH(double, farthest);
        QFETCH(double, low);
        QFETCH(double, high);
        Settings s = presetSettings("seed");
        s.shadow.cascades = 4;
        s.shadow.distance = 100.0;
        CameraFrame camera = computeCameraFrame(s.camera, 16.0 / 9.0, Bounds{{-10, -1, -10}, {10, 5, 10}});
        camera.nearPlane = 0.1;
        camera.farPlane = 1000.0;
        const VisibleDepthRange visible{nearest, farthest};
        const auto [distanceLow, distanceHigh] = cascadeDepthRange(s, camera, visible);
        QCOMPARE(distanceLow, 0.1);
        QCOMPARE(distanceHigh, 100.0);
        s.shadow.depthFit = DepthFit::Sdsm;
        const auto [sdsmLow, sdsmHigh] = cascadeDepthRange(s, camera, visible);
        QVERIFY(std::isfinite(sdsmLow) && std::isfinite(sdsmHigh) && sdsmLow < sdsmHigh);
        QCOMPARE(sdsmLow, low > 0.0 ? low : 0.1);
        QCOMPARE(sdsmHigh, high > 0.0 ? high : 100.0);
        QCOMPARE(cascadeDepthRange(s, camera, std::nullopt), (std::pair{0.1, 100.0}));
        // The cascades the set fits split exactly that range.
        std::vector<FitObject> objects{{Bounds{{-10, -1, -10}, {10, 5, 10}}, true, true, false}};
        const ShadowViewSet set = fitShadowViews(s, objects, camera, 16.0 / 9.0, visible);
        QCOMPARE(int(set.views.size()), 4);
        QCOMPARE(set.views.front().splitNear, sdsmLow);
        QCOMPARE(set.views.back().splitFar, sdsmHigh);
    }

    // Each cascade's fitted volume covers its whole slice of the view (what the camera can see
    // of every receiver between its split distances), and consecutive slices meet: no gap at a
    // seam, at any shadow distance up to 10⁵, stabilised or not.
    void cascadesCoverTheirSlices_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("cascades");
        QTest::addColumn<double>("distance");
        QTest::addColumn<bool>("stabilize");
        for (const QString& scene : sceneNames()) {
            for (int cascades : {2, 3, 4}) {
                for (double distance : {5.0, 30.0, 1e5}) {
                    for (bool stabilize : {false, true})
                        QTest::newRow(qPrintable(QString("%1 %2 cascades to %3 %4").arg(scene).arg(cascades).arg(distance).arg(stabilize ? "stabilised" : "tight")))
                            << scene << cascades << distance << stabilize;
                }
            }
        }
    }

    void cascadesCoverTheirSlices()
    {
        QFETCH(QString, scene);
        QFETCH(int, cascades);
        QFETCH(double, distance);
        QFETCH(bool, stabilize);
        Settings s = presetSettings(scene);
        s.shadow.cascades = cascades;
        s.shadow.distance = distance;
        s.light.stabilize = stabilize;
        QVERIFY(validate(s).empty());
        const Scene built = buildScene(scene);
        const std::vector<FitObject> objects = fitObjects(built);
        const double aspect = 16.0 / 9.0;
        const CameraFrame camera = computeCameraFrame(s.camera, aspect, built.bounds());
        const ShadowViewSet set = fitShadowViews(s, objects, camera, aspect);
        QCOMPARE(int(set.views.size()), cascades);
        QVERIFY(set.cascaded);
        QCOMPARE(set.views.front().splitNear, camera.nearPlane);
        QCOMPARE(set.views.back().splitFar, std::min(distance, camera.farPlane));
        for (int i = 0; i < cascades; ++i) {
            const ShadowView& view = set.views[std::size_t(i)];
            QVERIFY(std::isfinite(view.splitNear) && std::isfinite(view.splitFar) && view.splitFar > view.splitNear);
            if (i > 0)
                QCOMPARE(view.splitNear, set.views[std::size_t(i) - 1].splitFar);
            if (!view.fit.anythingToShadow)
                continue;
            const LightFrame frame = computeLightFrame(s.light, view.fit.volume);
            QVERIFY(isFinite(frame.shadowMatrix));
            // Every visible receiver point in the slice lies inside the cascade's map, in x and y
            // (depth: casters before near are clamped, receivers beyond far cannot be shadowed
            // by anything the fit saw).
            const glm::dmat4 slice = glm::perspective(glm::radians(s.camera.fov), aspect, view.splitNear, view.splitFar) * camera.view;
            int inside = 0, outside = 0;
            for (std::size_t k = 0; k < objects.size(); ++k) {
                if (!objects[k].receives)
                    continue;
                for (const glm::dvec3& p : clipBoxToFrusta(objects[k].bounds, {slice})) {
                    const glm::dvec4 t = frame.shadowMatrix * glm::dvec4(p, 1.0);
                    const bool in = t.x >= -1e-6 && t.x <= 1.0 + 1e-6 && t.y >= -1e-6 && t.y <= 1.0 + 1e-6;
                    (in ? inside : outside) += 1;
                }
            }
            // A tight fit covers only where casters can shadow; the sphere covers the slice whole.
            if (stabilize)
                QVERIFY2(outside == 0, qPrintable(QString("cascade %1: %2 of %3 slice corners outside its map").arg(i).arg(outside).arg(inside + outside)));
        }
    }

    // The city: the asked-for number of buildings, of varied size, over more than a square
    // kilometre, the same on every build; bad counts are refused with the key named.
    void cityIsSeededAndSized_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("buildings");
        QTest::newRow("city") << "city" << 2000;
        QTest::newRow("city:500") << "city:500" << 500;
        QTest::newRow("city:8000") << "city:8000" << 8000;
    }

    void cityIsSeededAndSized()
    {
        QFETCH(QString, name);
        QFETCH(int, buildings);
        const Scene city = buildScene(name);
        QCOMPARE(int(city.objects.size()), buildings + 1);  // and the ground
        Bounds all;
        double lowest = 1e9, highest = 0.0, narrowest = 1e9, widest = 0.0;
        for (std::size_t i = 1; i < city.objects.size(); ++i) {
            const Bounds b = city.worldBounds(city.objects[i]);
            all.extend(b);
            lowest = std::min(lowest, b.max.y - b.min.y);
            highest = std::max(highest, b.max.y - b.min.y);
            narrowest = std::min(narrowest, b.max.x - b.min.x);
            widest = std::max(widest, b.max.x - b.min.x);
            QVERIFY(b.min.y >= -1e-9);
        }
        QVERIFY2((all.max.x - all.min.x) * (all.max.z - all.min.z) >= 1e6, "the buildings cover at least a square kilometre");
        QVERIFY(highest > 5.0 * lowest);
        QVERIFY(widest > 1.3 * narrowest);
        // Seeded: the same city again.
        const Scene again = buildScene(name);
        for (std::size_t i = 0; i < city.objects.size(); ++i)
            QVERIFY(city.objects[i].model == again.objects[i].model);
        // The street-level camera stands on the ground, in a street, and sees buildings.
        const Settings s = presetSettings(name);
        QVERIFY(validate(s).empty());
        QVERIFY(s.camera.position.y > 1.0 && s.camera.position.y < 3.0);
        for (std::size_t i = 1; i < city.objects.size(); ++i) {
            const Bounds b = city.worldBounds(city.objects[i]);
            const glm::dvec3 p = s.camera.position;
            QVERIFY(!(p.x > b.min.x && p.x < b.max.x && p.z > b.min.z && p.z < b.max.z));
        }
    }

    void cityCountsAreChecked()
    {
        Settings s;
        for (const char* bad : {"city:0", "city:-3", "city:20001", "city:many", "city:"})
            QVERIFY_THROWS_EXCEPTION(SettingsError, applySetting(s, "scene", bad));
        applySetting(s, "scene", "city:123");
        QCOMPARE(s.scene, QString("city:123"));
    }

    // A point light's six faces, each a little over 90°, leave no direction uncovered.
    void cubeFacesCoverEveryDirection()
    {
        Settings s = presetSettings("seed");
        applySetting(s, "light.type", "point");
        s.light.fit = LightFit::Manual;
        s.light.nearPlane = 0.05;
        s.light.farPlane = 100.0;
        const Scene built = buildScene("seed");
        const CameraFrame camera = computeCameraFrame(s.camera, 1.0, built.bounds());
        const ShadowViewSet set = fitShadowViews(s, fitObjects(built), camera, 1.0);
        QVERIFY(set.cube);
        QCOMPARE(int(set.views.size()), 6);
        QVERIFY(cubeFaceFov(s.map.size) > 90.0 && cubeFaceFov(s.map.size) < 91.0);
        // Directions on a fine grid of the sphere, including the face seams and corners.
        for (int a = 0; a <= 48; ++a) {
            for (int b = 0; b < 96; ++b) {
                const double theta = M_PI * a / 48.0, phi = 2.0 * M_PI * b / 96.0;
                const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
                const glm::dvec3 p = s.light.position + d * 3.0;
                // The face the shader picks: the major axis of the direction.
                const glm::dvec3 m = glm::abs(d);
                const int face = m.x >= m.y && m.x >= m.z ? (d.x >= 0 ? 0 : 1) : m.y >= m.z ? (d.y >= 0 ? 2 : 3) : (d.z >= 0 ? 4 : 5);
                const LightFrame frame = computeLightFrame(s.light, set.views[std::size_t(face)].fit.volume);
                const glm::dvec4 t = frame.shadowMatrix * glm::dvec4(p, 1.0);
                QVERIFY(t.w > 0.0);
                const glm::dvec3 uvw = glm::dvec3(t) / t.w;
                QVERIFY2(uvw.x > 0.0 && uvw.x < 1.0 && uvw.y > 0.0 && uvw.y < 1.0 && uvw.z > 0.0 && uvw.z < 1.0,
                         qPrintable(QString("direction %1,%2,%3 on face %4 maps to %5,%6,%7").arg(d.x).arg(d.y).arg(d.z).arg(face).arg(uvw.x).arg(uvw.y).arg(uvw.z)));
            }
        }
    }

    // light.warp = lispsm: for lights and cameras all around, the warped map covers the whole
    // fitted box (nothing the fit kept falls off the map), its matrix is finite and keeps float
    // precision, and it gives the receivers at the camera finer texels than the unwarped map,
    // growing away from it; where the camera looks along the light there is no warp.
    void lispsmCoversTheBox_data()
    {
        QTest::addColumn<double>("lightElevation");
        QTest::addColumn<double>("lightAzimuth");
        QTest::addColumn<double>("viewPitch");     // degrees below the horizon
        QTest::addColumn<double>("viewYaw");
        QTest::addColumn<double>("scale");
        for (double elevation : {5.0, 30.0, 60.0, 89.5, 90.0}) {
            for (double azimuth : {0.0, 135.0}) {
                for (double pitch : {-20.0, 0.0, 25.0, 60.0, 89.9}) {
                    for (double yaw : {10.0, 100.0, 190.0}) {
                        for (double scale : {0.1, 1.0, 10.0})
                            QTest::addRow("light %g/%g, view %g/%g, scale %g", elevation, azimuth, pitch, yaw, scale)
                                << elevation << azimuth << pitch << yaw << scale;
                    }
                }
            }
        }
    }

    void lispsmCoversTheBox()
    {
        QFETCH(double, lightElevation);
        QFETCH(double, lightAzimuth);
        QFETCH(double, viewPitch);
        QFETCH(double, viewYaw);
        QFETCH(double, scale);
        LightSettings light;
        light.target = glm::dvec3(0.0);
        light.position = lightPosition(light.target, {lightAzimuth, lightElevation, 10.0});
        CameraSettings cameraSettings;
        cameraSettings.position = glm::dvec3(1.0, 2.0, -1.0);
        const double pitch = glm::radians(viewPitch), yaw = glm::radians(viewYaw);
        cameraSettings.target = cameraSettings.position + glm::dvec3(std::cos(pitch) * std::sin(yaw), -std::sin(pitch), std::cos(pitch) * std::cos(yaw));
        const CameraFrame camera = computeCameraFrame(cameraSettings, 16.0 / 9.0, Bounds{glm::dvec3(-30.0), glm::dvec3(30.0)});
        // A box of 40 x 32 x 12 wu in front of the camera, its y along the view, as a fit for
        // the warp leaves it; or in the light's stable axes where the camera looks along it.
        LightVolume box = manualVolume(light);
        box.up = warpAxis(camera, light.target - light.position);
        box.origin = cameraSettings.position;
        box.left = -20.0;
        box.right = 20.0;
        box.bottom = -2.0;
        box.top = 30.0;
        box.nearPlane = -6.0;
        box.farPlane = 6.0;
        WarpShape shape;
        // The receivers the camera sees, narrow at the camera and wide far away, as the fit
        // outlines them (where the box is along the view).
        std::vector<glm::dvec2> outline;
        if (box.up != glm::dvec3(0.0))
            outline = {{-1.0, -2.0}, {1.0, -2.0}, {20.0, 30.0}, {-20.0, 30.0}};
        const LightVolume warped = lispsmVolume(box, camera, {.nearDepth = 0.5, .farDepth = 40.0, .scale = scale, .outline = outline}, &shape);
        QVERIFY(std::isfinite(shape.sinGamma));
        QCOMPARE(warped.warped, shape.warped);
        if (shape.sinGamma < kWarpFadeStart)
            QVERIFY2(!warped.warped, "no warp where the camera looks along the light");
        if (shape.sinGamma > kWarpFadeEnd && scale <= 1.0)
            QVERIFY2(warped.warped, qPrintable(QString("sin gamma %1: a warp").arg(shape.sinGamma)));
        const LightFrame frame = computeLightFrame(light, warped);
        QVERIFY(isFinite(frame.shadowMatrix));
        const glm::mat4 single(frame.shadowMatrix);
        const int mapSize = 4096;
        const glm::dmat4 inverseView = glm::inverse(frame.view);
        for (int i = 0; i < 27; ++i) {
            // Corners, edge midpoints and the centre of the box, or of the outline's box.
            const glm::dvec3 t(0.5 * (i % 3), 0.5 * ((i / 3) % 3), 0.5 * (i / 9));
            glm::dvec3 local(glm::mix(box.left, box.right, t.x), glm::mix(box.bottom, box.top, t.y), -glm::mix(box.nearPlane, box.farPlane, t.z));
            if (!outline.empty()) {
                // On the outline's edges and inside it: its corners, the midpoints of its sides.
                const glm::dvec2 a = outline[std::size_t(i % 4)], b = outline[std::size_t((i + 1) % 4)];
                local = glm::dvec3(glm::mix(a, b, t.y * 0.5), local.z);
            }
            const glm::dvec3 world(inverseView * glm::dvec4(local, 1.0));
            const glm::dvec4 c = frame.shadowMatrix * glm::dvec4(world, 1.0);
            QVERIFY(c.w > 0.0);
            const glm::dvec3 uvw = glm::dvec3(c) / c.w;
            const double slack = 1e-9;
            QVERIFY2(glm::all(glm::greaterThanEqual(uvw, glm::dvec3(-slack))) && glm::all(glm::lessThanEqual(uvw, glm::dvec3(1.0 + slack))),
                     qPrintable(QString("point %1 of the box maps to %2,%3,%4").arg(i).arg(uvw.x).arg(uvw.y).arg(uvw.z)));
            // What the GPU computes in float lands within a tenth of a texel of a 4096 map.
            const glm::vec4 f = single * glm::vec4(glm::vec3(world), 1.0f);
            const glm::dvec2 fuv = glm::dvec2(f.x / f.w, f.y / f.w);
            QVERIFY2(glm::length(fuv - glm::dvec2(uvw)) * mapSize < 0.1,
                     qPrintable(QString("float is %1 texels off").arg(glm::length(fuv - glm::dvec2(uvw)) * mapSize)));
        }
        if (!warped.warped)
            return;
        // Finer than the unwarped map where the camera is, coarser on the far side.
        const double plain = texelWorldSize(box, mapSize);
        const glm::dvec3 eye(frame.view * glm::dvec4(camera.position, 1.0));
        const double atEye = warpedTexelSize(warped, mapSize, glm::dvec3(eye.x, eye.y, eye.z));
        QVERIFY2(atEye < plain, qPrintable(QString("texel at the camera %1, unwarped %2").arg(atEye).arg(plain)));
        // ... growing away from the camera: the warp spends the far field's texels on the near.
        const double far = warpedTexelSize(warped, mapSize, glm::dvec3(eye.x, box.top, eye.z));
        QVERIFY2(far > atEye, qPrintable(QString("texel far away %1, at the camera %2").arg(far).arg(atEye)));
        QVERIFY(texelWorldSize(warped, mapSize) >= far);
        QVERIFY(shape.nearDistance > 0.0 && shape.nearDistance <= kWarpLongest * shape.depth);
    }

    // Turning the camera toward the light's direction weakens the warp smoothly to none: the
    // warp's near distance only grows, and no texel size jumps on the way.
    void lispsmFadesOutAlongTheLight()
    {
        LightSettings light;
        light.position = lightPosition(light.target, {30.0, 50.0, 10.0});
        const glm::dvec3 toward = glm::normalize(light.target - light.position);
        LightVolume box = manualVolume(light);
        box.left = box.bottom = -10.0;
        box.right = box.top = 10.0;
        box.nearPlane = -5.0;
        box.farPlane = 5.0;
        const glm::dvec3 side = glm::normalize(glm::cross(toward, glm::dvec3(0.0, 1.0, 0.0)));
        double previousNear = 0.0, previousTexel = 0.0;
        bool warpedBefore = true;
        for (int step = 0; step <= 400; ++step) {
            const double angle = glm::radians(20.0) * (1.0 - step / 400.0);     // 20 degrees to 0
            for (double sign : {1.0, -1.0}) {       // looking with the light, and toward it
                CameraSettings c;
                c.position = glm::dvec3(0.0, 1.0, 0.0);
                c.target = c.position + sign * (toward * std::cos(angle) + side * std::sin(angle));
                const CameraFrame camera = computeCameraFrame(c, 1.0, Bounds{glm::dvec3(-20.0), glm::dvec3(20.0)});
                WarpShape shape;
                const LightVolume warped = lispsmVolume(box, camera, {.nearDepth = 0.5, .farDepth = 30.0, .scale = 1.0, .outline = {}}, &shape);
                QVERIFY(isFinite(computeLightFrame(light, warped).shadowMatrix));
                if (sign < 0.0)
                    continue;
                const double texel = texelWorldSize(warped, 2048);
                QVERIFY(std::isfinite(texel) && texel > 0.0);
                if (shape.warped) {
                    QVERIFY2(warpedBefore, "the warp comes back closer to the light's direction");
                    QVERIFY2(shape.nearDistance >= previousNear * (1.0 - 1e-9), qPrintable(QString("step %1: n fell").arg(step)));
                    if (previousTexel > 0.0)
                        QVERIFY2(std::abs(texel / previousTexel - 1.0) < 0.05, qPrintable(QString("step %1: texel %2 after %3").arg(step).arg(texel).arg(previousTexel)));
                    previousNear = shape.nearDistance;
                    previousTexel = texel;
                }
                warpedBefore = shape.warped;
            }
        }
        QVERIFY2(!warpedBefore, "no warp looking along the light");
    }
};

QTEST_GUILESS_MAIN(TestLightRig)
#include "tst_LightRig.moc"
