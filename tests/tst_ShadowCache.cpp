// shadow.cache against drawing every caster each frame: static and pages give the same frames
// as off while casters move, under every light type, rig and storage, and draw less to do it;
// every-n and on-demand are stale between their redraws, and say so; a moving light, a changed
// setting or a new fit draws every view again.
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "ReferenceAgreement.h"
#include "SceneLibrary.h"
#include "VirtualPages.h"
#include "SettingsError.h"
#include "SettingsKeys.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <map>

using namespace shadowlab;

namespace {

const QSize kSize(320, 180);

// Still boxes and a floor, with casters moving through some views and not others.
const QByteArray kTraffic = R"({ "shapes": [
    { "shape": "ground", "height": 0, "size": 14 },
    { "name": "still 1", "shape": "cube", "position": [2.5, 0.5, -1.5], "scale": 0.5 },
    { "name": "still 2", "shape": "pyramid", "position": [-3, 0.8, 2], "scale": [0.6, 0.8, 0.6] },
    { "name": "still 3", "shape": "cube", "position": [0.5, 1.5, 3], "scale": [1.5, 0.1, 0.5] },
    { "name": "spinner", "shape": "cube", "position": [0, 1.2, 0], "scale": [1.5, 0.08, 0.3], "motion": { "type": "spin", "period": 4 } },
    { "name": "orbiter", "shape": "sphere", "position": [2, 0.9, 0], "scale": 0.35, "motion": { "type": "orbit", "centre": [0, 0, 0], "speed": -45 } },
    { "name": "bobber", "shape": "torus", "position": [-2, 1.2, -2], "scale": 0.5, "motion": { "type": "bob", "amplitude": 0.6, "period": 3 } }
  ],
  "light.position": [-4, 8, 3], "light.target": [0, 0, 0],
  "camera.position": [0, 6, 9], "camera.target": [0, 0.3, 0] })";

int count(const std::vector<ViewCause>& causes, ViewCause cause)
{
    return int(std::count(causes.begin(), causes.end(), cause));
}

// Pixels of `a` and `b` that differ by more than 1/255 in a channel fail the test; those that
// differ by 1/255 are counted.
int differingPixels(const QImage& a, const QImage& b)
{
    int differing = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int most = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)), std::abs(qBlue(p) - qBlue(q))});
            if (most > 1)
                return 1 << 30;
            differing += most > 0;
        }
    }
    return differing;
}

std::vector<std::uint64_t> pageKeys(const std::vector<VirtualPage>& pages)
{
    std::vector<std::uint64_t> keys;
    for (const VirtualPage& page : pages)
        keys.push_back(page.key());
    std::sort(keys.begin(), keys.end());
    return keys;
}

// Each resident page's slot and depths, read from the pool.
std::map<std::uint64_t, std::pair<int, std::vector<float>>> pageDepths(HeadlessRenderer& headless)
{
    headless.makeCurrent();
    GlFunctions* gl = headless.functions();
    const Renderer& r = headless.renderer();
    std::map<std::uint64_t, std::pair<int, std::vector<float>>> pages;
    const int side = r.virtualMap()->cache().poolSide();
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, r.shadowMap().framebuffer());
    for (const auto& [page, slot] : r.virtualMap()->cache().residentPages()) {
        std::vector<float> depths(std::size_t(kVirtualSlotTexels * kVirtualSlotTexels));
        gl->glReadPixels((slot % side) * kVirtualSlotTexels, (slot / side) * kVirtualSlotTexels, kVirtualSlotTexels, kVirtualSlotTexels,
                         GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
        pages.emplace(page.key(), std::pair{slot, std::move(depths)});
    }
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return pages;
}

// How many pages `a` and `b` both hold in the same slot, all with the same depths; -1 when one
// differs. (A page drawn into another slot is rasterised at other window coordinates, which
// round differently: only pages in the same slot compare exactly.)
int samePages(HeadlessRenderer& a, HeadlessRenderer& b)
{
    const auto pagesA = pageDepths(a), pagesB = pageDepths(b);
    int compared = 0;
    for (const auto& [key, page] : pagesB) {
        const auto other = pagesA.find(key);
        if (other == pagesA.end() || other->second.first != page.first)
            continue;
        if (other->second.second != page.second)
            return -1;
        ++compared;
    }
    return compared;
}

} // namespace

class TestShadowCache : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QFile file(m_dir.filePath(QStringLiteral("traffic.json")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(kTraffic);
        m_traffic = file.fileName();
        m_off = std::make_unique<HeadlessRenderer>();
        m_cached = std::make_unique<HeadlessRenderer>();
    }
    void cleanupTestCase()
    {
        m_off.reset();
        m_cached.reset();
    }

    void exactPoliciesMatchOff_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        const QString stat = QStringLiteral("shadow.cache=static");
        for (const char* light : {"directional", "spot", "point"})
            QTest::addRow("static, %s", light) << QStringLiteral("traffic") << QStringList{stat, QStringLiteral("light.type=%1").arg(light)};
        QTest::addRow("static, 3 cascades") << QStringLiteral("traffic") << QStringList{stat, QStringLiteral("shadow.cascades=3")};
        QTest::addRow("static, 4 cascades, sdsm") << QStringLiteral("traffic")
                                                  << QStringList{stat, QStringLiteral("shadow.cascades=4"), QStringLiteral("shadow.depth_fit=sdsm")};
        QTest::addRow("static, lispsm") << QStringLiteral("traffic") << QStringList{stat, QStringLiteral("light.warp=lispsm")};
        QTest::addRow("static, depth32f reversed") << QStringLiteral("traffic") << QStringList{stat, QStringLiteral("map.format=depth32f")};
        QTest::addRow("static, pcf 5x5, cull front") << QStringLiteral("traffic")
                                                     << QStringList{stat, QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=5"),
                                                                    QStringLiteral("bias.cull_front=true")};
        QTest::addRow("static, pcss") << QStringLiteral("traffic") << QStringList{stat, QStringLiteral("filter.mode=pcss")};
        QTest::addRow("static, vsm") << QStringLiteral("traffic") << QStringList{stat, QStringLiteral("filter.mode=vsm")};
        QTest::addRow("static, evsm4, point") << QStringLiteral("traffic")
                                              << QStringList{stat, QStringLiteral("filter.mode=evsm4"), QStringLiteral("light.type=point")};
        QTest::addRow("static, msm, 2 cascades") << QStringLiteral("traffic")
                                                 << QStringList{stat, QStringLiteral("filter.mode=msm"), QStringLiteral("shadow.cascades=2")};
        QTest::addRow("static, swing") << QStringLiteral("swing") << QStringList{stat};
        QTest::addRow("static, city traffic, 4 cascades")
            << QStringLiteral("city:600+60")
            << QStringList{stat, QStringLiteral("shadow.cascades=4"), QStringLiteral("camera.position=-3,8,45"), QStringLiteral("camera.target=0,0,-20")};
        // Real models whose node animations move some of their parts.
        const QString models = QStringLiteral("/usr/share/assimp/models/");
        QTest::addRow("static, motion capture (ASE)") << models + QStringLiteral("ASE/MotionCaptureROM.ase") << QStringList{stat};
        QTest::addRow("static, 64 turning parts (COLLADA), point") << models + QStringLiteral("Collada/anims_with_full_rotations_between_keys.DAE")
                                                                  << QStringList{stat, QStringLiteral("light.type=point")};
        QTest::addRow("static, turning cube (3DS), vsm, spot") << models + QStringLiteral("3DS/RotatingCube.3DS")
                                                              << QStringList{stat, QStringLiteral("filter.mode=vsm"), QStringLiteral("light.type=spot")};
        QTest::addRow("pages, motion capture (ASE)") << models + QStringLiteral("ASE/MotionCaptureROM.ase")
                                                     << QStringList{QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.cache=pages")};
        QTest::addRow("pages, virtual") << QStringLiteral("traffic") << QStringList{QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.cache=pages")};
        QTest::addRow("pages, virtual, hardware profile")
            << QStringLiteral("traffic")
            << QStringList{QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.cache=pages"), QStringLiteral("rasteriser.profile=hardware")};
        QTest::addRow("pages, city traffic")
            << QStringLiteral("city:600+60")
            << QStringList{QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.cache=pages"), QStringLiteral("camera.position=-3,8,45"),
                           QStringLiteral("camera.target=0,0,-20")};
    }
    // Frame by frame at 30 frames a second, the cached renderer draws the same pixels as one
    // that draws every caster, and draws fewer casters to do it.
    void exactPoliciesMatchOff()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        Settings cached = presetSettings(scene == u"traffic" ? m_traffic : scene);
        if (scene == u"traffic")
            cached.scene = m_traffic;
        for (const QString& a : assignments)
            applyAssignment(cached, a);
        Settings off = cached;
        off.shadow.cache = ShadowCachePolicy::Off;
        int cachedDraws = 0, offDraws = 0, kept = 0, byCasters = 0, samePagesCompared = 0;
        qint64 cachedRequestPixels = 0, offRequestPixels = 0;
        for (int frame = 0; frame < 8; ++frame) {
            off.animation.time = cached.animation.time = 0.7 + frame / 30.0;
            const QImage expected = m_off->renderScene(off, kSize);
            const QImage image = m_cached->renderScene(cached, kSize);
            if (cached.shadow.virtualMap) {
                // A page kept where it was drawn may sit in another slot of the pool than off's
                // page drawn again this frame, and a slot's texels round differently (1/255 at a
                // handful of pixels): the depths of the pages in the same slot are the exact check.
                // The same pages asked for, moving receivers' included.
                QVERIFY2(pageKeys(m_cached->renderer().virtualMap()->requests()) == pageKeys(m_off->renderer().virtualMap()->requests()),
                         qPrintable(QStringLiteral("frame %1: other pages asked for than with shadow.cache=off").arg(frame)));
                if (frame > 0) {
                    cachedRequestPixels += m_cached->renderer().virtualMap()->requestPixels();
                    offRequestPixels += m_off->renderer().virtualMap()->requestPixels();
                }
                const int same = samePages(*m_cached, *m_off);
                QVERIFY2(same >= 0, qPrintable(QStringLiteral("frame %1: a page's depths differ from shadow.cache=off").arg(frame)));
                samePagesCompared += same;
                const int differing = differingPixels(image, expected);
                QVERIFY2(differing <= image.width() * image.height() / 2000,
                         qPrintable(QStringLiteral("frame %1: %2 pixels differ from shadow.cache=off").arg(frame).arg(differing)));
            } else {
                QVERIFY2(image == expected, qPrintable(QStringLiteral("frame %1 differs from shadow.cache=off").arg(frame)));
            }
            const FrameStats& stats = m_cached->renderer().lastFrame();
            if (frame == 0)
                continue;       // the first frame draws everything for both
            cachedDraws += stats.shadowDraws;
            offDraws += m_off->renderer().lastFrame().shadowDraws;
            const int cachedCount = count(stats.viewCauses, ViewCause::Cached)
                                    + int(std::count_if(stats.pageCauses.begin(), stats.pageCauses.end(), [](auto& p) { return p.second == ViewCause::Cached; }));
            const int casterCount = count(stats.viewCauses, ViewCause::Casters)
                                    + int(std::count_if(stats.pageCauses.begin(), stats.pageCauses.end(), [](auto& p) { return p.second == ViewCause::Casters; }));
            kept += cachedCount;
            byCasters += casterCount;
            QCOMPARE(count(stats.viewCauses, ViewCause::Stale), 0);
        }
        qInfo("%s: %d casters drawn against %d with shadow.cache=off; %d views or pages kept, %d drawn for moving casters; %d pages compared",
              qPrintable(QTest::currentDataTag()), cachedDraws, offDraws, kept, byCasters, samePagesCompared);
        QVERIFY2(byCasters > 0, "no view was drawn for its moving casters");
        QVERIFY2(!cached.shadow.virtualMap || samePagesCompared > 0, "no page sat in the same slot with and without the cache");
        // Only the pixels where moving objects were and are ask for their pages again.
        QVERIFY2(!cached.shadow.virtualMap || cachedRequestPixels < offRequestPixels, qPrintable(QStringLiteral("%1 pixels asked again, against %2 with shadow.cache=off")
                                                                      .arg(cachedRequestPixels).arg(offRequestPixels)));
        // Fewer casters drawn where some stand still (more than a ground), and never more.
        const Scene built = buildScene(cached.scene);
        const auto still = std::count_if(built.objects.begin(), built.objects.end(), [](const SceneObject& o) { return o.castsShadow && !o.motion; });
        const QString drawn = QStringLiteral("%1 casters drawn, against %2 without a cache").arg(cachedDraws).arg(offDraws);
        QVERIFY2(cachedDraws <= offDraws, qPrintable(drawn));
        QVERIFY2(still <= 1 || cachedDraws < offDraws, qPrintable(drawn));
    }

    // Where a view holds no moving caster, it is kept: on the city's cascades some view is.
    void viewsWithoutMovingCastersAreKept()
    {
        Settings s = presetSettings(QStringLiteral("city:600+20"));
        applyAssignment(s, QStringLiteral("shadow.cascades=4"));
        applyAssignment(s, QStringLiteral("shadow.cache=static"));
        s.animation.time = 1.0;
        m_cached->renderScene(s, kSize);
        QCOMPARE(count(m_cached->renderer().lastFrame().viewCauses, ViewCause::New), 4);
        s.animation.time += 1.0 / 60.0;
        m_cached->renderScene(s, kSize);
        const std::vector<ViewCause> causes = m_cached->renderer().lastFrame().viewCauses;
        QCOMPARE(int(causes.size()), 4);
        QVERIFY(count(causes, ViewCause::Casters) >= 1);
        QCOMPARE(count(causes, ViewCause::New) + count(causes, ViewCause::Light), 0);
        QVERIFY(m_cached->renderer().lastFrame().cacheBytes > 0);
    }

    // A moving light draws every view again from its still casters: the copies are the old light's.
    void aMovingLightDrawsEverything()
    {
        auto [s, off] = traffic({QStringLiteral("shadow.cascades=3"), QStringLiteral("shadow.cache=static")});
        for (Settings* settings : {&s, &off})
            settings->animation.time = 0.5;
        m_cached->renderScene(s, kSize);
        m_off->renderScene(off, kSize);
        for (Settings* settings : {&s, &off}) {
            settings->light.position += glm::dvec3(0.7, 0.0, -0.4);
            settings->animation.time = 0.55;
        }
        const QImage image = m_cached->renderScene(s, kSize);
        QCOMPARE(image, m_off->renderScene(off, kSize));
        // Every view with something to shadow is drawn again; one without stays read lit.
        const FrameStats& stats = m_cached->renderer().lastFrame();
        QCOMPARE(int(stats.viewCauses.size()), 3);
        QVERIFY(count(stats.viewCauses, ViewCause::Light) >= 2);
        for (std::size_t i = 0; i < stats.viewCauses.size(); ++i) {
            QVERIFY(stats.viewCauses[i] == ViewCause::Light || stats.viewCauses[i] == ViewCause::Cached);
            if (stats.viewCauses[i] == ViewCause::Cached)
                QVERIFY(!m_cached->renderer().shadowViews().set.views[i].fit.anythingToShadow || stats.viewDraws[i] == 0);
        }
    }

    // shadow.force_invalidate, a moving sun: every view drawn every frame, the same pixels.
    void aMovingSunDrawsEveryViewEveryFrame()
    {
        auto [s, off] = traffic({QStringLiteral("shadow.cascades=2"), QStringLiteral("shadow.cache=static"),
                                 QStringLiteral("shadow.force_invalidate=true")});
        for (int frame = 0; frame < 3; ++frame) {
            off.animation.time = s.animation.time = 2.0;    // nothing moves: only the invalidation draws
            const QImage image = m_cached->renderScene(s, kSize);
            QCOMPARE(image, m_off->renderScene(off, kSize));
            QVERIFY(m_cached->renderer().lastFrame().shadowPassRendered);
            if (frame > 0)
                QCOMPARE(count(m_cached->renderer().lastFrame().viewCauses, ViewCause::Light), 2);
        }
    }

    // Casters that moved while shadows were off are where they are when shadows come back, for
    // a map of views and for a virtual map's pages.
    void movesWhileShadowsAreOffAreNotLost_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("static, 2 cascades") << QStringList{QStringLiteral("shadow.cache=static"), QStringLiteral("shadow.cascades=2")};
        QTest::newRow("pages") << QStringList{QStringLiteral("shadow.virtual=true"), QStringLiteral("shadow.cache=pages")};
    }
    void movesWhileShadowsAreOffAreNotLost()
    {
        QFETCH(QStringList, assignments);
        auto [s, off] = traffic(assignments);
        off.animation.time = s.animation.time = 0.5;
        m_cached->renderScene(s, kSize);
        for (const double t : {1.5, 2.5}) {
            s.animation.time = t;
            s.shadow.enabled = false;
            m_cached->renderScene(s, kSize);
        }
        s.shadow.enabled = true;
        off.animation.time = s.animation.time;
        const QImage image = m_cached->renderScene(s, kSize), expected = m_off->renderScene(off, kSize);
        if (s.shadow.virtualMap) {
            const int same = samePages(*m_cached, *m_off), differing = differingPixels(image, expected);
            QVERIFY(same >= 0);
            QVERIFY(differing <= image.width() * image.height() / 2000);
        } else {
            QCOMPARE(image, expected);
        }
    }

    // every-n: the moving casters' shadows are those of the last redraw until the n-th frame,
    // which draws what off draws; the views in between are marked stale.
    void everyNIsStaleBetweenRedraws()
    {
        auto [s, off] = traffic({QStringLiteral("shadow.cache=every-n"), QStringLiteral("shadow.cache_interval=3")});
        int stale = 0, same = 0, different = 0;
        for (int frame = 0; frame < 7; ++frame) {
            off.animation.time = s.animation.time = 1.0 + frame / 10.0;
            const QImage image = m_cached->renderScene(s, kSize);
            const QImage expected = m_off->renderScene(off, kSize);
            const std::vector<ViewCause>& causes = m_cached->renderer().lastFrame().viewCauses;
            const bool drawn = frame == 0 || frame % 3 == 0;
            QCOMPARE(count(causes, ViewCause::Stale), drawn ? 0 : 1);
            if (drawn)
                QVERIFY2(image == expected, qPrintable(QStringLiteral("frame %1 is a redraw, yet differs from off").arg(frame)));
            stale += !drawn;
            same += !drawn && image == expected;
            different += !drawn && image != expected;
        }
        QCOMPARE(stale, 4);
        QVERIFY2(different >= 3, qPrintable(QStringLiteral("only %1 of the stale frames differ from off").arg(different)));
    }

    // on-demand: stale until asked, then the same as off.
    void onDemandWaitsUntilAsked()
    {
        auto [s, off] = traffic({QStringLiteral("light.type=point"), QStringLiteral("shadow.cache=on-demand")});
        s.animation.time = 0.2;
        m_cached->renderScene(s, kSize);
        off.animation.time = s.animation.time = 1.4;
        const QImage stale = m_cached->renderScene(s, kSize);
        const QImage expected = m_off->renderScene(off, kSize);
        QVERIFY(stale != expected);
        QVERIFY(count(m_cached->renderer().lastFrame().viewCauses, ViewCause::Stale) >= 1);
        m_cached->renderer().requestShadowRedraw();
        QCOMPARE(m_cached->renderScene(s, kSize), expected);
        QCOMPARE(count(m_cached->renderer().lastFrame().viewCauses, ViewCause::Stale), 0);
        // Asked once: still stale frames after it while the casters go on moving.
        s.animation.time = 2.0;
        m_cached->renderScene(s, kSize);
        QVERIFY(count(m_cached->renderer().lastFrame().viewCauses, ViewCause::Stale) >= 1);
    }

    // Nothing moves: a cache draws nothing after its first frame, and the frame is the same.
    void aStillSceneCostsNothing()
    {
        Settings s = presetSettings(QStringLiteral("seed"));
        applyAssignment(s, QStringLiteral("shadow.cache=static"));
        const QImage first = m_cached->renderScene(s, kSize);
        const int passes = m_cached->renderer().shadowPassCount();
        QCOMPARE(m_cached->renderScene(s, kSize), first);
        QCOMPARE(m_cached->renderer().shadowPassCount(), passes);
        Settings off = s;
        off.shadow.cache = ShadowCachePolicy::Off;
        off.map.slices = 1;
        QCOMPARE(first, m_off->renderScene(off, kSize));
    }

    void movesOutOfSightWaitUntilSeen_data()
    {
        // A volume fitted to what the camera sees leaves such casters out of its views
        // already; a volume as set (light.fit=manual), the cube's faces and a cascade's
        // stabilised square keep them in.
        QTest::addColumn<QStringList>("assignments");
        const QString manual = QStringLiteral("light.fit=manual");
        for (const char* light : {"directional", "spot", "point"})
            QTest::addRow("%s, volume as set", light) << QStringList{QStringLiteral("light.type=%1").arg(light), manual};
        QTest::addRow("3 cascades") << QStringList{QStringLiteral("shadow.cascades=3")};
        QTest::addRow("pcf 5x5, normal offset") << QStringList{manual, QStringLiteral("filter.mode=pcf"), QStringLiteral("filter.kernel=5"),
                                                               QStringLiteral("bias.normal=1.5")};
    }
    // A caster that moves where no pixel of the frame can read its shadow draws nothing (the
    // view stays, marked out of sight); when the camera turns to it, the view is repaired, and
    // every frame is off's.
    void movesOutOfSightWaitUntilSeen()
    {
        QFETCH(QStringList, assignments);
        assignments << QStringLiteral("shadow.cache=static");
        auto [s, off] = traffic(assignments);
        // Into the corner toward the light, away from every moving caster and its shadow.
        for (Settings* settings : {&s, &off}) {
            settings->camera.position = glm::dvec3(-3.0, 1.5, 4.0);
            settings->camera.target = glm::dvec3(-6.5, 0.0, 6.5);
        }
        int unseen = 0, awayDraws = 0;
        for (int frame = 0; frame < 6; ++frame) {
            off.animation.time = s.animation.time = 0.5 + frame / 30.0;
            QVERIFY2(m_cached->renderScene(s, kSize) == m_off->renderScene(off, kSize), qPrintable(QStringLiteral("frame %1 differs from off").arg(frame)));
            if (frame == 0)
                continue;
            unseen += count(m_cached->renderer().lastFrame().viewCauses, ViewCause::Unseen);
            awayDraws += m_cached->renderer().lastFrame().shadowDraws;
        }
        QVERIFY2(unseen > 0, "no view was left out of sight");
        QCOMPARE(awayDraws, 0);
        // Back to the whole scene: the views the casters left are drawn where they are now.
        int byCasters = 0;
        for (int frame = 0; frame < 3; ++frame) {
            for (Settings* settings : {&s, &off}) {
                settings->camera.position = glm::dvec3(0.0, 6.0, 9.0);
                settings->camera.target = glm::dvec3(0.0, 0.3, 0.0);
                settings->animation.time = 0.8 + frame / 30.0;
            }
            QVERIFY2(m_cached->renderScene(s, kSize) == m_off->renderScene(off, kSize),
                     qPrintable(QStringLiteral("frame %1 after the turn differs from off").arg(frame)));
            const std::vector<ViewCause>& causes = m_cached->renderer().lastFrame().viewCauses;
            QCOMPARE(count(causes, ViewCause::Unseen), 0);
            byCasters += count(causes, ViewCause::Casters) + count(causes, ViewCause::Light);
        }
        QVERIFY(byCasters > 0);
    }

    // A cache the map cannot keep is refused, naming the key and the way out.
    void policiesTheMapCannotKeepAreRefused()
    {
        Settings s = presetSettings(QStringLiteral("seed"));
        applyAssignment(s, QStringLiteral("shadow.cache=pages"));
        try {
            m_cached->renderScene(s, kSize);
            QFAIL("pages on a map of views was drawn");
        } catch (const SettingsError& e) {
            QCOMPARE(e.key(), QStringLiteral("shadow.cache"));
            QVERIFY(QString::fromUtf8(e.what()).contains(QStringLiteral("shadow.virtual=true")));
        }
        applyAssignment(s, QStringLiteral("shadow.cache=static"));
        applyAssignment(s, QStringLiteral("shadow.virtual=true"));
        try {
            m_cached->renderScene(s, kSize);
            QFAIL("static on a virtual map was drawn");
        } catch (const SettingsError& e) {
            QCOMPARE(e.key(), QStringLiteral("shadow.cache"));
            QVERIFY(QString::fromUtf8(e.what()).contains(QStringLiteral("shadow.cache=pages")));
        }
    }

private:
    // The traffic scene with `assignments`, and the same with shadow.cache=off.
    std::pair<Settings, Settings> traffic(const QStringList& assignments) const
    {
        Settings cached = presetSettings(m_traffic);
        for (const QString& a : assignments)
            applyAssignment(cached, a);
        Settings off = cached;
        off.shadow.cache = ShadowCachePolicy::Off;
        return {cached, off};
    }

    QTemporaryDir m_dir;
    QString m_traffic;
    std::unique_ptr<HeadlessRenderer> m_off;
    std::unique_ptr<HeadlessRenderer> m_cached;
};

SHADOWLAB_TEST_MAIN(TestShadowCache)
#include "tst_ShadowCache.moc"
