// The frame's pure half without GL: the scene's layout (every object drawn once, batches that
// keep every vertex and the winding of mirrored placements) and the update (a fit only when an
// input changed, the cameras it fits to, the reach kept with it, a virtual map's one view), and
// the frame plan its settings resolve into (the rasteriser profile's optimisations included).
#include "CasterTexels.h"
#include "FramePlan.h"
#include "FrameUpdate.h"
#include "MomentMath.h"
#include "SceneLayout.h"
#include "SceneLibrary.h"
#include "SceneNames.h"
#include "SettingsKeys.h"
#include "ShadowCache.h"
#include "VirtualPages.h"
#include "WrittenTexels.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <algorithm>
#include <functional>
#include <set>

using namespace shadowlab;

namespace {

Settings with(const QString& scene, std::initializer_list<const char*> assignments = {})
{
    Settings s = presetSettings(scene);
    for (const char* a : assignments)
        applyAssignment(s, QString::fromLatin1(a));
    ensureValid(s);
    return s;
}

bool contains(const Bounds& outer, const Bounds& inner, double slack)
{
    return glm::all(glm::lessThanEqual(outer.min - slack, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max + slack));
}

// A hundred small cubes on a grid, every third one mirrored in x: enough to be batched.
Scene mirroredCubes()
{
    Scene s;
    s.name = QStringLiteral("mirrored cubes");
    s.meshes.push_back(meshes::cube());
    for (int i = 0; i < 100; ++i) {
        glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(3.0 * (i % 10), 0.5, 3.0 * (i / 10)));
        m = glm::rotate(m, glm::radians(17.0 * i), glm::dvec3(0.0, 1.0, 0.0));
        m = glm::scale(m, glm::dvec3(i % 3 == 0 ? -0.4 : 0.4, 0.4, 0.4));
        s.objects.push_back({QStringLiteral("cube %1").arg(i), 0, m, TextureKind::Wood, true});
    }
    return s;
}

struct Update {
    Scene scene;
    SceneLayout layout;
    FrameUpdate update;
    explicit Update(Scene built) : scene(std::move(built)), layout(scene) {}

    // One frame: returns whether it fitted again.
    bool frame(const Settings& s, QSize size = QSize(320, 180), int sceneGeneration = 1, std::optional<CameraSettings> fitCamera = {},
               FrameUpdate::FitSources sources = {})
    {
        const FrameUpdate::Frame f = update.begin({sceneGeneration, 0, s, fitCamera, size, false}, layout.bounds());
        update.fit(f, scene, layout, sources);
        return f.refit;
    }
};

} // namespace

class TestFrameUpdate : public QObject {
    Q_OBJECT

private slots:
    void layoutDrawsEveryObjectOnce_data()
    {
        QTest::addColumn<QString>("scene");
        for (const QString& name : sceneNames())
            QTest::newRow(qPrintable(name)) << name;
        QTest::newRow("city:500") << QStringLiteral("city:500");
        QTest::newRow("city:8000") << QStringLiteral("city:8000");
    }
    void layoutDrawsEveryObjectOnce()
    {
        QFETCH(QString, scene);
        const Scene built = buildScene(scene);
        const SceneLayout layout(built);
        std::vector<int> drawn(built.objects.size(), 0);
        int batches = 0, smoothItems = 0;
        for (const DrawItem& item : layout.drawItems()) {
            QVERIFY(!item.objects.empty());
            for (std::size_t i : item.objects) {
                ++drawn.at(i);
                QVERIFY2(contains(item.bounds, layout.objectBounds(i), 1e-9), qPrintable(built.objects[i].name));
                QCOMPARE(item.castsShadow, built.objects[i].castsShadow);
                QCOMPARE(item.receivesShadow, built.objects[i].receivesShadow);
            }
            // An item's facets shadow themselves (OWN_FACETS) where a member is smooth-shaded.
            smoothItems += item.smoothShaded;
            QCOMPARE(item.smoothShaded, std::any_of(item.objects.begin(), item.objects.end(), [&](std::size_t i) {
                         return smoothShaded(built.meshes.at(std::size_t(built.objects[i].mesh)));
                     }));
            if (item.batch)
                QCOMPARE(item.mesh, batches++);
            QVERIFY(contains(layout.bounds(), item.bounds, 1e-9));
        }
        QCOMPARE(batches, layout.batchCount());
        // The city's boxes are flat-shaded: its lit pass compiles no facet test; the torus is not.
        if (scene.startsWith(QStringLiteral("city")))
            QCOMPARE(smoothItems, 0);
        if (scene == u"torus")
            QVERIFY(smoothItems > 0);
        for (std::size_t i = 0; i < drawn.size(); ++i)
            QVERIFY2(drawn[i] == 1, qPrintable(QStringLiteral("%1 is drawn %2 times").arg(built.objects[i].name).arg(drawn[i])));
        // Draw calls do not grow with the objects: a city's are a fraction of its buildings.
        if (built.objects.size() >= 500)
            QVERIFY2(layout.drawItems().size() * 4 < built.objects.size(),
                     qPrintable(QStringLiteral("%1 items for %2 objects").arg(layout.drawItems().size()).arg(built.objects.size())));
        else if (built.objects.size() < 64)
            QCOMPARE(layout.drawItems().size(), built.objects.size());
    }

    // Merged vertices are the members' in world space, and a mirrored member's triangles still
    // face the way their normals say (front faces counter-clockwise).
    void batchesKeepVerticesAndWinding()
    {
        const Scene scene = mirroredCubes();
        const SceneLayout layout(scene);
        int batched = 0;
        for (const DrawItem& item : layout.drawItems()) {
            if (!item.batch)
                continue;
            const BatchGeometry g = SceneLayout::batchGeometry(scene, item);
            std::size_t vertices = 0, indices = 0;
            for (std::size_t i : item.objects) {
                vertices += scene.meshes[std::size_t(scene.objects[i].mesh)].vertices.size();
                indices += scene.meshes[std::size_t(scene.objects[i].mesh)].indices.size();
            }
            QCOMPARE(g.vertices.size(), vertices);
            QCOMPARE(g.indices.size(), indices);
            const glm::dvec3 origin(item.model[3]);
            for (const BatchVertex& v : g.vertices) {
                const glm::dvec3 world = glm::dvec3(v.vertex.position) + origin;
                QVERIFY(glm::all(glm::lessThanEqual(item.bounds.min - 1e-4, world)) && glm::all(glm::lessThanEqual(world, item.bounds.max + 1e-4)));
                QVERIFY(std::abs(glm::length(v.vertex.normal) - 1.0f) < 1e-4f);
            }
            for (std::size_t k = 0; k + 2 < g.indices.size(); k += 3) {
                const BatchVertex& a = g.vertices[g.indices[k]];
                const BatchVertex& b = g.vertices[g.indices[k + 1]];
                const BatchVertex& c = g.vertices[g.indices[k + 2]];
                const glm::vec3 face = glm::cross(b.vertex.position - a.vertex.position, c.vertex.position - a.vertex.position);
                QVERIFY2(glm::dot(face, a.vertex.normal + b.vertex.normal + c.vertex.normal) > 0.0f, "a batched triangle faces away from its normal");
            }
            batched += int(item.objects.size());
        }
        QVERIFY2(batched > 50, "the test scene should be batched");
    }

    // The fit runs when one of its inputs changes and never on a still frame.
    // A floor (flat, everything else on the side it faces) shadows nothing from that side, so
    // the shadow pass leaves it out; from below it is a caster like any other. A wall with
    // something behind it is no floor; nor is anything but a plane.
    void floorsShadowNothingFromAbove()
    {
        const Scene seed = buildScene(QStringLiteral("seed"));
        const SceneLayout layout(seed);
        int floors = 0;
        for (const DrawItem& item : layout.drawItems()) {
            const SceneObject& o = seed.objects.at(item.objects.front());
            QCOMPARE(item.floor.has_value(), o.name == u"ground");
            floors += item.floor.has_value();
            LightFrame light;
            light.perspective = true;
            light.position = {1.0, 8.0, 2.0};
            QCOMPARE(shadowsNothing(item, light), item.floor.has_value());
            light.position.y = -8.0;        // under the ground: it shadows all above it
            QVERIFY(!shadowsNothing(item, light));
            light.perspective = false;
            light.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
            QCOMPARE(shadowsNothing(item, light), item.floor.has_value());
        }
        QCOMPARE(floors, 1);

        // The ground turned into a wall at x = 0 facing +x, with the cubes on both sides of it.
        Scene walled = seed;
        for (SceneObject& o : walled.objects) {
            if (o.name == u"ground")
                o.model = glm::rotate(glm::dmat4(1.0), glm::radians(-90.0), glm::dvec3(0.0, 0.0, 1.0));
        }
        const SceneLayout walledLayout(walled);
        QVERIFY(std::none_of(walledLayout.drawItems().begin(), walledLayout.drawItems().end(), [](const DrawItem& i) { return i.floor.has_value(); }));
    }

    void fitsOnlyWhenAnInputChanges()
    {
        Update u(buildScene(QStringLiteral("seed")));
        const Settings s = with(QStringLiteral("seed"));
        QVERIFY(u.frame(s));
        QCOMPARE(u.update.fitCount(), 1);
        QVERIFY(!u.frame(s));
        QVERIFY(!u.frame(s));
        QCOMPARE(u.update.fitCount(), 1);

        Settings moved = s;
        moved.camera.position += glm::dvec3(0.5, 0.0, 0.0);
        QVERIFY(u.frame(moved));
        QVERIFY(u.frame(moved, QSize(640, 360)));
        QVERIFY(u.frame(moved, QSize(640, 360), 2));
        QVERIFY(!u.frame(moved, QSize(640, 360), 2));
        Settings light = moved;
        light.light.position.x += 0.25;
        QVERIFY(u.frame(light, QSize(640, 360), 2));
        QCOMPARE(u.update.fitCount(), 5);
    }

    // The light is fitted to the fitting camera while the frame's camera still draws.
    void fitsToTheFittingCamera()
    {
        Update u(buildScene(QStringLiteral("city")));
        const Settings s = with(QStringLiteral("city"), {"shadow.cascades=4"});
        u.frame(s);
        const glm::dvec3 before = u.update.views().set.views.front().fit.volume.origin;
        CameraSettings away = s.camera;
        away.position += glm::dvec3(200.0, 0.0, 0.0);
        away.target += glm::dvec3(200.0, 0.0, 0.0);
        QVERIFY(u.frame(s, QSize(320, 180), 1, away));
        const CameraFrame expected = computeCameraFrame(away, 320.0 / 180.0, u.layout.bounds());
        QCOMPARE(u.update.views().camera.position, expected.position);
        QCOMPARE(u.update.views().set.views.size(), std::size_t(4));
        // The nearest cascade moved with the fitting camera.
        QVERIFY(glm::length(u.update.views().set.views.front().fit.volume.origin - before) > 50.0);
        QVERIFY(!u.frame(s, QSize(320, 180), 1, away));
    }

    // The reach follows each fit: one entry per draw item, and none with shadows off.
    void reachIsKeptWithTheFit_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("seed") << QStringLiteral("seed") << QStringList{};
        QTest::newRow("seed, front faces culled") << QStringLiteral("seed") << QStringList{QStringLiteral("bias.cull_front=true")};
        QTest::newRow("seed, spot") << QStringLiteral("seed") << QStringList{QStringLiteral("light.type=spot")};
        QTest::newRow("seed, point") << QStringLiteral("seed") << QStringList{QStringLiteral("light.type=point")};
        QTest::newRow("cubes, pcf 7") << QStringLiteral("cubes") << QStringList{QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=7")};
        QTest::newRow("city, 3 cascades") << QStringLiteral("city") << QStringList{QStringLiteral("shadow.cascades=3")};
    }
    void reachIsKeptWithTheFit()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        Update u(buildScene(scene));
        Settings s = presetSettings(scene);
        for (const QString& a : assignments)
            applyAssignment(s, a);
        ensureValid(s);
        u.frame(s);
        const ShadowReach& reach = u.update.reach();
        QCOMPARE(reach.objects.size(), u.layout.drawItems().size());
        QVERIFY(!reach.boxes.empty());
        // Something in every built-in scene is shadowed, so some receiver needs a lookup.
        QVERIFY(std::any_of(reach.objects.begin(), reach.objects.end(), [](Reach r) { return r != Reach::Outside; }));
        const int generation = reach.generation;
        u.frame(s);
        QCOMPARE(u.update.reach().generation, generation);
        Settings off = s;
        off.shadow.enabled = false;
        u.frame(off);
        QVERIFY(u.update.reach().objects.empty());
        QCOMPARE(u.update.reach().generation, generation + 1);
    }

    // What the update keeps between fits (the casters, the still casters' texels, the reach's
    // boxes of the casters) follows every input it was found from: after each change in a walk
    // of settings, culling and camera, the reach and the texels are a fresh update's.
    void keptPartsFollowTheirInputs()
    {
        Settings s = presetSettings(QStringLiteral("seed"));
        ensureValid(s);
        struct Step {
            QStringList assignments;
            bool cullsFrontFaces = false;
            bool floorsLeftOut = false;
        };
        const std::vector<Step> walk{
            {{QStringLiteral("bias.cull_front=false"), QStringLiteral("bias.skip_floors=false")}, false, false},
            {{QStringLiteral("camera.position=5.4,4.6,8.2")}, false, false},           // the views may stay
            {{QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=7")}, false, false},   // the taps reach farther
            {{QStringLiteral("bias.normal=2")}, false, false},
            {{QStringLiteral("map.size=512")}, false, false},
            {{QStringLiteral("bias.cull_front=true")}, true, false},      // the storage's culling follows the settings
            {{QStringLiteral("bias.skip_floors=true")}, true, true},
            {{QStringLiteral("shadow.enabled=false")}, true, true},
            {{QStringLiteral("shadow.enabled=true"), QStringLiteral("light.type=point")}, true, true},
            {{QStringLiteral("light.type=directional"), QStringLiteral("shadow.cascades=3"), QStringLiteral("bias.cull_front=false"),
              QStringLiteral("bias.skip_floors=false")},
             false, false},
        };
        Update walked(buildScene(QStringLiteral("seed")));
        for (std::size_t k = 0; k < walk.size(); ++k) {
            for (const QString& a : walk[k].assignments)
                applyAssignment(s, a);
            ensureValid(s);
            FrameUpdate::FitSources sources;
            sources.cullsFrontFaces = walk[k].cullsFrontFaces;
            sources.floorsLeftOut = walk[k].floorsLeftOut;
            walked.frame(s, QSize(320, 180), 1, {}, sources);
            Update fresh(buildScene(QStringLiteral("seed")));
            fresh.frame(s, QSize(320, 180), 1, {}, sources);
            const QString step = QStringLiteral("step %1").arg(k);
            const ShadowReach &a = walked.update.reach(), &b = fresh.update.reach();
            QVERIFY2(a.objects == b.objects && a.boxes.size() == b.boxes.size() && a.screenRects == b.screenRects, qPrintable(step));
            for (std::size_t i = 0; i < a.boxes.size(); ++i)
                QVERIFY2(a.boxes[i].uvMin == b.boxes[i].uvMin && a.boxes[i].uvMax == b.boxes[i].uvMax && a.boxes[i].depthMin == b.boxes[i].depthMin
                             && a.boxes[i].uvEdges == b.boxes[i].uvEdges,
                         qPrintable(step));
            const std::vector<CasterTexels> &ta = walked.update.casterTexels(), &tb = fresh.update.casterTexels();
            QVERIFY2(ta.size() == tb.size(), qPrintable(step));
            for (std::size_t v = 0; v < ta.size(); ++v)
                QVERIFY2(ta[v].drawn == tb[v].drawn && ta[v].pieces == tb[v].pieces, qPrintable(step));
        }
    }

    // A virtual map is one view, its coarsest level, whatever the fit would have made.
    void virtualMapIsOneView()
    {
        Update u(buildScene(QStringLiteral("city")));
        const Settings s = with(QStringLiteral("city"), {"shadow.virtual=true"});
        FrameUpdate::FitSources sources;
        sources.virtualLayout = virtualLayout(s.light, u.layout.bounds(), s.shadow.virtualLevels);
        u.frame(s, QSize(320, 180), 1, {}, sources);
        QCOMPARE(u.update.views().set.views.size(), std::size_t(1));
        QCOMPARE(u.update.views().frames.size(), std::size_t(1));
        QVERIFY(u.update.fitted().volume == sources.virtualLayout->coarsest);
        QCOMPARE(u.update.fitted().texelAfter, sources.virtualLayout->finestTexel);
        QVERIFY(u.update.fitted().anythingToShadow);
    }

    // The fit's statistics say how a warp went.
    void describesTheWarp()
    {
        Update u(buildScene(QStringLiteral("city")));
        const Settings s = with(QStringLiteral("city"), {"light.warp=lispsm"});
        u.frame(s);
        FrameStats stats;
        u.update.describe(planFrame(s, true, true), stats);
        QCOMPARE(stats.warpViews, 1);
        QVERIFY(stats.warpedViews == 1 || stats.warpDeclined != FrameStats::WarpDeclined::No);
        QVERIFY(stats.texelWorldSize > 0.0);
        QVERIFY(stats.lightFitted);
    }
    // A frame's decisions, resolved once: the profile turns on every software rasteriser's
    // optimisation or none, auto follows the driver, and each decision is the settings'.
    void plansTheFrame_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<bool>("softwareDriver");
        QTest::addColumn<bool>("tuned");            // the software profile's optimisations are on
        QTest::addColumn<int>("slices");
        QTest::addColumn<int>("columns");
        QTest::addColumn<int>("rows");
        QTest::addColumn<bool>("reversed");
        QTest::addColumn<bool>("moments");
        QTest::addColumn<bool>("depthRange");
        QTest::addRow("auto on llvmpipe") << "seed" << QStringList{} << true << true << 4 << 1 << 1 << false << false << false;
        QTest::addRow("auto on a GPU") << "seed" << QStringList{} << false << false << 1 << 1 << 1 << false << false << false;
        QTest::addRow("software forced on a GPU") << "seed" << QStringList{"rasteriser.profile=software", "map.slices=6"} << false << true << 6 << 1 << 1
                                                << false << false << false;
        QTest::addRow("hardware forced on llvmpipe") << "seed" << QStringList{"rasteriser.profile=hardware"} << true << false << 1 << 1 << 1 << false
                                                   << false << false;
        QTest::addRow("perspective: never sliced") << "seed" << QStringList{"light.projection=perspective"} << true << true << 1 << 1 << 1 << false
                                                  << false << false;
        QTest::addRow("warped: never sliced") << "city" << QStringList{"light.warp=lispsm"} << true << true << 1 << 1 << 1 << false << false << false;
        QTest::addRow("3 cascades in 2 x 2") << "city" << QStringList{"shadow.cascades=3"} << true << true << 1 << 2 << 2 << false << false << false;
        QTest::addRow("point: 3 x 2 faces, sliced") << "seed" << QStringList{"light.type=point"} << true << true << 4 << 3 << 2 << false << false << false;
        QTest::addRow("virtual: a slot per page") << "city" << QStringList{"shadow.virtual=true", "shadow.virtual_pool=12"} << false << false << 1 << 12
                                                 << 12 << false << false << false;
        QTest::addRow("depth32f reversed") << "seed" << QStringList{"map.format=depth32f"} << true << true << 4 << 1 << 1 << true << false << false;
        QTest::addRow("moments keep conventional depth") << "seed" << QStringList{"map.format=depth32f", "filter.mode=evsm4"} << true << true << 4 << 1
                                                        << 1 << false << true << false;
        QTest::addRow("penumbra-only pcf") << "seed" << QStringList{"filter.mode=pcf", "filter.early_out=true"} << false << false << 1 << 1 << 1 << false
                                          << false << true;
        QTest::addRow("shadows off") << "seed" << QStringList{"shadow.enabled=false", "filter.mode=pcf", "filter.early_out=true"} << true << true << 4
                                    << 1 << 1 << false << false << false;
        QTest::addRow("cached: never sliced") << "seed" << QStringList{"shadow.cache=static"} << true << true << 1 << 1 << 1 << false << false << false;
    }

    void plansTheFrame()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        QFETCH(bool, softwareDriver);
        QFETCH(bool, tuned);
        QFETCH(int, slices);
        QFETCH(int, columns);
        QFETCH(int, rows);
        QFETCH(bool, reversed);
        QFETCH(bool, moments);
        QFETCH(bool, depthRange);
        Settings s = presetSettings(scene);
        for (const QString& a : assignments)
            applyAssignment(s, a);
        ensureValid(s);
        const FramePlan plan = planFrame(s, softwareDriver, true);
        const RasteriserTuning& t = plan.tuning;
        QCOMPARE(t.software, tuned);
        // All or nothing: each optimisation is the profile's.
        for (const bool on : {t.skipsOutOfReach, t.depthSlices, t.wideTwoChannelMoments, t.clearsWrittenMoments, t.cpuVirtualRequests, t.rangesWrittenTexels})
            QCOMPARE(on, tuned);
        QCOMPARE(plan.slices, slices);
        QCOMPARE(plan.grid.columns, columns);
        QCOMPARE(plan.grid.rows, rows);
        QCOMPARE(plan.tileSize, plan.virtualMap ? kVirtualSlotTexels : s.map.size);
        QCOMPARE(plan.reversedDepth, reversed);
        QCOMPARE(plan.moments, moments);
        QCOMPARE(plan.depthRange, depthRange);
        QVERIFY(plan.technique->mode == s.filter.mode);
        // A blur in the lookup reads (r + 1)² bilinear taps (shaders/moments_common.glsl).
        const int radius = plan.moments ? lookupBlurRadius(s) : 0;
        QCOMPARE(plan.tapsPerLookup, !s.shadow.enabled ? 0 : radius > 0 ? (radius + 1) * (radius + 1) : plan.technique->taps(s.filter));
        // A driver without clip control: asked for, not given.
        const FramePlan without = planFrame(s, softwareDriver, false);
        QCOMPARE(without.reversedDepthWanted, reversed);
        QVERIFY(!without.reversedDepth);
        QVERIFY(plan.cache == (s.shadow.enabled ? s.shadow.cache : ShadowCachePolicy::Off));
    }

    // What each view does under each policy, from why it would be drawn: three views, a moving
    // caster in the second. No context: the decisions are the cache's, the draws the storages'.
    void cacheDecidesPerView()
    {
        using Work = ShadowCache::Work;
        const LightVolume volume;
        LightVolume moved = volume;
        moved.left -= 1.0;
        ShadowCache::Frame frame;
        frame.policy = ShadowCachePolicy::Static;
        frame.wanted = {volume, volume, std::nullopt};
        const QRect there(10, 10, 5, 5);
        const std::vector<QRect> none;
        frame.movingTexels = {none, {there}, none};
        ShadowCache cache;
        const auto run = [&](ShadowCache::Frame f) {
            const std::vector<ShadowCache::Decision> d = cache.decide(f);
            for (std::size_t i = 0; i < d.size(); ++i)
                cache.done(i, d[i], f.wanted[i], d[i].work != Work::Clear ? f.movingTexels[i] : std::vector<QRect>());
            return d;
        };
        // The first frame draws every view with something to shadow, keeping a copy.
        std::vector<ShadowCache::Decision> d = run(frame);
        QVERIFY(d[0].work == Work::Refresh && d[0].cause == ViewCause::New);
        QVERIFY(d[1].work == Work::Refresh);
        QVERIFY(d[2].work == Work::Clear);
        // A caster moves in the second view: only it comes back from its copy.
        frame.castersMoved = true;
        d = run(frame);
        QVERIFY(d[0].work == Work::Keep && d[0].cause == ViewCause::Cached);
        QVERIFY(d[1].work == Work::Restore && d[1].cause == ViewCause::Casters);
        QVERIFY(d[1].areas == std::vector<QRect>{there});
        QVERIFY(d[2].work == Work::Keep);
        // It leaves for the first: both are drawn (where it was, where it is).
        const QRect here(40, 40, 6, 6);
        frame.movingTexels = {{here}, none, none};
        d = run(frame);
        QVERIFY(d[0].work == Work::Restore && d[1].work == Work::Restore);
        QVERIFY(d[0].areas == std::vector<QRect>{here});
        QVERIFY(d[1].areas == std::vector<QRect>{there});
        // Where it was and is, overlapping: one rectangle; and another caster apart: two.
        frame.movingTexels = {{here.translated(2, 0), there}, none, none};
        d = run(frame);
        QVERIFY(d[0].work == Work::Restore && d[1].work == Work::Keep);
        QCOMPARE(int(d[0].areas.size()), 2);
        QVERIFY(std::find(d[0].areas.begin(), d[0].areas.end(), here | here.translated(2, 0)) != d[0].areas.end());
        // Where no pixel reads, a move changes nothing: the view stays, out of sight, until a
        // pixel reads where its casters were or are, even after they stop.
        const QRect far(500, 500, 8, 8);
        frame.readTexels = {QRect(0, 0, 100, 100), QRect(0, 0, 100, 100), QRect()};
        frame.movingTexels = {{far}, none, none};
        d = run(frame);
        QVERIFY(d[0].work == Work::Restore);        // it left the texels read
        frame.movingTexels = {{far.translated(4, 0)}, none, none};
        d = run(frame);
        QVERIFY(d[0].work == Work::Keep && d[0].cause == ViewCause::Unseen && d[0].areas.empty());
        frame.castersMoved = false;
        d = run(frame);
        QVERIFY(d[0].cause == ViewCause::Unseen);
        frame.readTexels[0] = QRect(0, 0, 1000, 1000);
        d = run(frame);
        QVERIFY(d[0].work == Work::Restore && d[0].cause == ViewCause::Casters);
        QVERIFY(d[0].areas == std::vector<QRect>{far | far.translated(4, 0)});
        d = run(frame);
        QVERIFY(d[0].work == Work::Keep && d[0].cause == ViewCause::Cached);
        // on-demand: a redraw asked for while out of sight is owed until a pixel reads there.
        frame.policy = ShadowCachePolicy::OnDemand;
        frame.castersMoved = true;
        frame.readTexels[0] = QRect(0, 0, 100, 100);
        frame.movingTexels = {{far.translated(8, 0)}, none, none};
        frame.requested = true;
        d = run(frame);
        QVERIFY(d[0].work == Work::Keep && d[0].cause == ViewCause::Unseen);
        frame.requested = false;
        frame.castersMoved = false;
        frame.readTexels[0] = QRect(0, 0, 1000, 1000);
        d = run(frame);
        QVERIFY(d[0].work == Work::Restore && d[0].cause == ViewCause::Casters);
        frame.policy = ShadowCachePolicy::Static;
        frame.castersMoved = true;
        frame.readTexels.clear();
        // The light moves: every view with a new volume is drawn from its still casters again.
        frame.wanted = {moved, moved, std::nullopt};
        d = run(frame);
        QVERIFY(d[0].work == Work::Refresh && d[0].cause == ViewCause::Light);
        QVERIFY(d[1].work == Work::Refresh && d[1].cause == ViewCause::Light);
        // Off draws every caster where it draws, and keeps no copy.
        frame.policy = ShadowCachePolicy::Off;
        frame.fresh = true;
        frame.freshCause = ViewCause::Casters;
        d = run(frame);
        QVERIFY(d[0].work == Work::Draw && d[0].cause == ViewCause::Casters);
        // every-n with n = 3: stale twice, then drawn.
        frame.policy = ShadowCachePolicy::EveryN;
        frame.interval = 3;
        frame.freshCause = ViewCause::New;
        run(frame);
        frame.fresh = false;
        for (int i = 0; i < 2; ++i) {
            d = run(frame);
            QVERIFY(d[0].work == Work::Keep && d[0].cause == ViewCause::Stale);
        }
        d = run(frame);
        QVERIFY(d[0].work == Work::Restore && d[0].cause == ViewCause::Casters);
        // on-demand: stale until asked, though the casters stop.
        frame.policy = ShadowCachePolicy::OnDemand;
        d = run(frame);
        QVERIFY(d[0].cause == ViewCause::Stale);
        frame.castersMoved = false;
        d = run(frame);
        QVERIFY(d[0].work == Work::Keep && d[0].cause == ViewCause::Stale);
        frame.requested = true;
        d = run(frame);
        QVERIFY(d[0].work == Work::Restore);
        frame.requested = false;
        d = run(frame);
        QVERIFY(d[0].work == Work::Keep && d[0].cause == ViewCause::Cached);
    }

    // A caster's square across the light overlaps the pages it can shadow, and no others.
    // The texels a frame's pixels may read: the image of what the camera sees of the receivers,
    // grown by how far a lookup reads, what lies past the map's square included (a lookup moved
    // off a receiver outside the map may land inside it). Where a move is read, a cache draws it.
    void readTexelsCoverWhatTheCameraSees()
    {
        LightSettings light;
        light.position = {0.0, 10.0, 0.0};
        light.target = {0.0, 0.0, 0.0};
        LightVolume volume;
        volume.origin = {0.0, 10.0, 0.0};
        volume.left = volume.bottom = -2.0;
        volume.right = volume.top = 2.0;
        volume.farPlane = 20.0;
        const LightFrame view = computeLightFrame(light, volume);
        Bounds receivers;
        receivers.min = {-10.0, 0.0, -10.0};
        receivers.max = {10.0, 1.0, 10.0};
        const int size = 256;   // 64 texels a world unit
        const auto seen = [&](glm::dvec3 position, glm::dvec3 target, double margin) {
            return readTexels(view, size, computeCameraFrame({.position = position, .target = target, .fov = 30.0}, 16.0 / 9.0, receivers), receivers,
                              margin);
        };
        // Looking down at the middle: part of the square, and more with a wider margin.
        const QRect middle = seen({0.0, 6.0, 0.1}, {0.0, 0.0, 0.0}, 3.0);
        QVERIFY(!middle.isEmpty() && middle != QRect(0, 0, size, size));
        const QRect wider = seen({0.0, 6.0, 0.1}, {0.0, 0.0, 0.0}, 20.0);
        QVERIFY(wider.contains(middle) && wider != middle);
        // Looking at ground a world unit or more past the square's side: nothing read, until
        // the margin reaches over.
        const glm::dvec3 away(3.5, 2.0, 0.0), there(3.5, 0.0, 0.0);
        QVERIFY(seen(away, there, 3.0).isEmpty());
        const QRect edge = seen(away, there, 200.0);
        QVERIFY(!edge.isEmpty());
        QVERIFY(edge.left() == 0 || edge.top() == 0 || edge.right() == size - 1 || edge.bottom() == size - 1);
        // Behind the camera nothing is read.
        QVERIFY(seen({0.0, 0.5, 30.0}, {0.0, 0.5, 60.0}, 3.0).isEmpty());
    }

    // Floors drawn only around the casters (evsm4, msm): each caster's rectangle grown, cut to the
    // tile, those that overlap joined, so that no floor texel is drawn twice and none near a
    // caster is missed; past a few pieces, their bounds.
    void floorsGoAroundEachCaster()
    {
        CasterTexels texels;
        for (const QRect& r : {QRect(10, 10, 20, 20), QRect(40, 12, 10, 10), QRect(200, 200, 30, 30), QRect(250, 0, 6, 6)})
            texels.add({.drawn = r, .pieces = {r}});
        const QRect tile(0, 0, 256, 256);
        const std::vector<QRect> pieces = aroundCasters(texels, 8, tile, 8);
        // The first two are 10 texels apart: grown by 8 each, they join.
        QCOMPARE(int(pieces.size()), 3);
        std::int64_t area = 0;
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            QVERIFY(tile.contains(pieces[i]));
            area += std::int64_t(pieces[i].width()) * pieces[i].height();
            for (std::size_t j = i + 1; j < pieces.size(); ++j)
                QVERIFY(!pieces[i].intersects(pieces[j]));
        }
        for (const QRect& piece : texels.pieces) {
            const QRect grown = piece.adjusted(-8, -8, 8, 8) & tile;
            QVERIFY(std::any_of(pieces.begin(), pieces.end(), [&](const QRect& p) { return p.contains(grown); }));
        }
        const QRect bounds = texels.drawn.adjusted(-8, -8, 8, 8) & tile;
        QVERIFY(area * 3 < std::int64_t(bounds.width()) * bounds.height());
        // A grown piece that bridges two joined ones joins them all.
        CasterTexels chain = texels;
        chain.add({.drawn = QRect(30, 30, 170, 170), .pieces = {QRect(30, 30, 170, 170)}});
        QCOMPARE(int(aroundCasters(chain, 8, tile, 8).size()), 2);
        // Too many pieces: one rectangle, their bounds.
        QCOMPARE(aroundCasters(texels, 8, tile, 2), std::vector<QRect>{bounds});
        QVERIFY(aroundCasters(CasterTexels{}, 8, tile, 8).empty());
    }

    // A moments map cleared in pieces: what was drawn since the last clear, and what is about to
    // be, each cleared once and apart; a new texture, whole.
    void writtenTexelsClearInPieces()
    {
        const QRect tile(256, 0, 256, 256);     // the second of two tiles
        const QRect a(260, 10, 20, 20), b(400, 200, 30, 30), c(270, 20, 20, 20), far(300, 100, 10, 10);
        WrittenTexels written;
        written.reset(256, 2, 1);
        QCOMPARE(written.piecesToClear(tile, {a}, 8), std::vector<QRect>{tile});
        written.clearedPieces(tile);
        QVERIFY(written.written(tile).isEmpty());
        QVERIFY(written.piecesToClear(tile, {}, 8).empty());
        written.drew(a);
        written.drew(b);
        QCOMPARE(written.written(tile), a | b);
        // c overlaps a: joined; far lies apart from both.
        const std::vector<QRect> pieces = written.piecesToClear(tile, {c, far}, 8);
        QCOMPARE(int(pieces.size()), 3);
        for (const QRect& r : {a, b, c, far})
            QVERIFY(std::any_of(pieces.begin(), pieces.end(), [&](const QRect& p) { return p.contains(r); }));
        std::int64_t area = 0;
        for (const QRect& p : pieces)
            area += std::int64_t(p.width()) * p.height();
        const QRect bounds = a | b | c | far;
        QVERIFY(area * 10 < std::int64_t(bounds.width()) * bounds.height());
        // At most `most`: their bounds.
        QCOMPARE(written.piecesToClear(tile, {c, far}, 2), std::vector<QRect>{bounds});
        // The other tile is untouched, and a clear of all the pieces leaves this one clean.
        QCOMPARE(written.written(QRect(0, 0, 256, 256)), QRect(0, 0, 256, 256));
        written.clearedPieces(tile);
        QVERIFY(written.piecesToClear(tile, {}, 8).empty());
        // Many small draws: still every texel they wrote is cleared.
        for (int i = 0; i < 40; ++i)
            written.drew(QRect(256 + 6 * i, 6 * i, 2, 2));
        const std::vector<QRect> many = written.piecesToClear(tile, {}, 8);
        for (int i = 0; i < 40; ++i)
            QVERIFY(std::any_of(many.begin(), many.end(), [&](const QRect& p) { return p.contains(QRect(256 + 6 * i, 6 * i, 2, 2)); }));
    }

    void movedCastersTouchTheirPages()
    {
        LightSettings light;
        light.position = {-4.0, 8.0, 3.0};
        light.target = {0.0, 0.0, 0.0};
        Bounds scene;
        scene.min = {-10.0, 0.0, -10.0};
        scene.max = {10.0, 4.0, 10.0};
        const VirtualLayout layout = virtualLayout(light, scene, 8);
        Bounds caster;
        caster.min = {0.9, 0.0, 0.9};
        caster.max = {1.1, 0.4, 1.1};
        const AcrossLight area = acrossLight(layout, caster);
        int touched = 0, pages = 0;
        for (int level = 0; level < 3; ++level) {
            for (int x = -20; x < 20; ++x) {
                for (int y = -20; y < 20; ++y) {
                    const VirtualPage page{level, x, y};
                    ++pages;
                    if (!pageOverlaps(layout, page, area))
                        continue;
                    ++touched;
                    // The page's volume holds a corner of the caster, or the caster covers it.
                    const LightFrame frame = computeLightFrame(light, virtualPageVolume(layout, page));
                    QVERIFY(!isOutsideFrustum(frame.viewProjection, caster, true));
                }
            }
        }
        QVERIFY(touched >= 3);          // at least one page a level
        QVERIFY(touched < pages / 100);
    }
};

QTEST_GUILESS_MAIN(TestFrameUpdate)
#include "tst_FrameUpdate.moc"
