// The wide filters (pcf N×N, pcf-optimized, poisson, pcss, dpcf) and their options (receiver-plane
// bias, penumbra-only filtering), checked against the Embree references at exactly the rendered
// pixels, the way a user checks a soft shadow: what the ray tracer says is shadowed is dark,
// what it says is lit stays lit however wide the kernel, PCSS's penumbra grows with the light's
// size and with the distance from blocker to receiver (so does dpcf's) and is closer to the area light than a
// fixed kernel, and skipping the taps outside penumbrae does not change the image.
#include "Application.h"
#include "HeadlessTestMain.h"
#include "HeadlessRenderer.h"
#include "RayTracer.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"
#include "ShadowReference.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <QtTest>

#include <cmath>

using namespace shadowlab;

namespace {

const QSize kSize(240, 135);

struct Measured {
    VisibilityBuffer buffer;
    ReferenceVisibility reference;
};

Measured measure(Renderer& renderer, const Settings& settings, bool area, QSize size = kSize)
{
    Measured m{renderer.renderVisibility(settings, size), {}};
    const RayTracer tracer(*renderer.scene(), m.buffer.cameraPosition);
    ReferenceOptions options;
    options.area = area;
    options.lightRadius = settings.reference.lightRadius;
    options.samplesPerAxis = 8;
    m.reference = traceReference(tracer, m.buffer, renderer.lightFrame(), options);
    return m;
}

Settings with(const QString& scene, const QStringList& assignments)
{
    Settings s = presetSettings(scene);
    for (const QString& a : assignments)
        applyAssignment(s, a);
    return s;
}

// Receiver pixels (facing the light) that disagree with `expected` by more than half.
struct Agreement {
    int counted = 0;
    int referenceShadowed = 0;
    int falseShadow = 0;
    int falseLight = 0;
    double meanAbsoluteError = 0.0;
    QString text() const
    {
        return QString("%1 counted, %2 shadowed in the reference, %3 false shadow, %4 false light, MAE %5")
            .arg(counted).arg(referenceShadowed).arg(falseShadow).arg(falseLight).arg(meanAbsoluteError, 0, 'f', 4);
    }
};

Agreement agreement(const VisibilityBuffer& buffer, const std::vector<float>& expected)
{
    Agreement a;
    double sum = 0.0;
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        if (buffer.mask(i) != VisibilityBuffer::FacingLight)
            continue;
        const float measured = buffer.visibility(i);
        const float e = expected[std::size_t(i)];
        ++a.counted;
        a.referenceShadowed += e < 0.5f;
        a.falseShadow += measured < e - 0.5f;
        a.falseLight += measured > e + 0.5f;
        sum += std::abs(double(measured) - double(e));
    }
    a.meanAbsoluteError = a.counted ? sum / a.counted : 0.0;
    return a;
}

// Share of receiver pixels strictly between shadow and light.
double penumbraShare(const VisibilityBuffer& buffer)
{
    int counted = 0, between = 0;
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        if (buffer.mask(i) != VisibilityBuffer::FacingLight)
            continue;
        ++counted;
        between += buffer.visibility(i) > 0.05f && buffer.visibility(i) < 0.95f;
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

// The occluder scene with its board lifted to `height` above the plane (1 in the preset).
Scene occluderAt(double height)
{
    Scene scene = buildScene(QStringLiteral("occluder"));
    scene.objects[1].model = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, height - 1.0, 0.0)) * scene.objects[1].model;
    return scene;
}

const QStringList kScenes{"seed", "torus", "cubes", "occluder"};

} // namespace

class TestSoftShadows : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private Q_SLOTS:
    void initTestCase() { m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase() { m_headless.reset(); }
    void cleanup() { m_headless->renderer().setScene(std::nullopt); }

    // Dark where the reference is shadowed, lit where it is lit: PCSS against the area light it
    // imitates, the fixed kernels against the hard reference.
    void agreesWithTheReference_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        const std::pair<const char*, QStringList> configurations[] = {
            {"poisson 16 r2.5", {"filter.mode=poisson"}},
            {"poisson 64 r16", {"filter.mode=poisson", "filter.taps=64", "filter.radius=16"}},
            {"poisson 8 r0.5", {"filter.mode=poisson", "filter.taps=8", "filter.radius=0.5"}},
            {"poisson receiver plane", {"filter.mode=poisson", "filter.radius=8", "bias.receiver_plane=true"}},
            {"pcf 7 receiver plane", {"filter.mode=pcf", "filter.kernel=7", "bias.receiver_plane=true"}},
            {"pcss 16", {"filter.mode=pcss"}},
            {"pcss 32 radius 0.5", {"filter.mode=pcss", "filter.taps=32", "light.radius=0.5"}},
            {"pcss perspective", {"filter.mode=pcss", "light.projection=perspective"}},
            {"pcss depth32f", {"filter.mode=pcss", "map.format=depth32f"}},
            {"pcss receiver plane", {"filter.mode=pcss", "bias.receiver_plane=true"}},
            {"pcf-optimized 3x3", {"filter.mode=pcf-optimized", "filter.kernel=3"}},
            {"pcf-optimized 5x5", {"filter.mode=pcf-optimized", "filter.kernel=5"}},
            {"pcf-optimized 7x7 receiver plane", {"filter.mode=pcf-optimized", "filter.kernel=7", "bias.receiver_plane=true"}},
            {"pcf-optimized 7x7 perspective", {"filter.mode=pcf-optimized", "filter.kernel=7", "light.projection=perspective"}},
            {"dpcf 16", {"filter.mode=dpcf"}},
            {"dpcf 32 radius 0.5", {"filter.mode=dpcf", "filter.taps=32", "light.radius=0.5"}},
            {"dpcf perspective", {"filter.mode=dpcf", "light.projection=perspective"}},
            {"dpcf receiver plane", {"filter.mode=dpcf", "bias.receiver_plane=true"}},
        };
        for (const QString& scene : kScenes) {
            for (const auto& [name, assignments] : configurations)
                QTest::newRow(qPrintable(QString("%1, %2").arg(scene, name))) << scene << assignments;
        }
    }

    void agreesWithTheReference()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        const Settings s = with(scene, assignments);
        const bool soft = s.filter.mode == FilterMode::Pcss || s.filter.mode == FilterMode::Dpcf;
        const Measured m = measure(m_headless->renderer(), s, soft);
        const Agreement a = agreement(m.buffer, soft ? m.reference.area : m.reference.hard);
        qInfo().noquote() << a.text();
        QVERIFY2(a.counted > 500, qPrintable(a.text()));
        QVERIFY2(a.referenceShadowed > 20, qPrintable(a.text()));
        QVERIFY2(a.falseLight <= 0.02 * a.referenceShadowed + 0.002 * a.counted, qPrintable(a.text()));
        QVERIFY2(a.falseShadow <= 0.005 * a.counted, qPrintable(a.text()));
    }

    // A wide Poisson disk with the default (small) bias keeps what the reference says is lit at
    // full light away from the shadow's edges: the bias grows with each tap's distance.
    void widePoissonKeepsLitReceiversLit_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("radius");
        for (const QString& scene : kScenes) {
            for (const double radius : {8.0, 32.0})
                QTest::newRow(qPrintable(QString("%1, radius %2").arg(scene).arg(radius))) << scene << radius;
        }
    }

    void widePoissonKeepsLitReceiversLit()
    {
        QFETCH(QString, scene);
        QFETCH(double, radius);
        const Settings s = with(scene, {"filter.mode=poisson", "filter.taps=64", QString("filter.radius=%1").arg(radius)});
        const Measured m = measure(m_headless->renderer(), s, false);
        int lit = 0, darkened = 0;
        double sum = 0.0;
        for (int i = 0; i < m.buffer.pixelCount(); ++i) {
            if (m.buffer.mask(i) != VisibilityBuffer::FacingLight || m.reference.hard[std::size_t(i)] < 0.5f)
                continue;
            ++lit;
            darkened += m.buffer.visibility(i) < 0.5f;
            sum += m.buffer.visibility(i);
        }
        const QString numbers = QString("%1 lit pixels, %2 below half light, mean visibility %3").arg(lit).arg(darkened).arg(sum / lit, 0, 'f', 4);
        qInfo().noquote() << numbers;
        QVERIFY2(lit > 500, qPrintable(numbers));
        QVERIFY2(darkened <= 0.005 * lit, qPrintable(numbers));
        QVERIFY2(sum / lit > 0.96, qPrintable(numbers));   // only the rims of shadows are in between
    }

    void pcssPenumbraWidensWithTheLightRadius()
    {
        double previous = 0.0, first = 0.0;
        for (const double radius : {0.05, 0.15, 0.45}) {
            const Settings s = with("occluder", {"filter.mode=pcss", "filter.taps=32", QString("light.radius=%1").arg(radius)});
            const double share = penumbraShare(m_headless->renderer().renderVisibility(s, QSize(320, 180)));
            qInfo("light.radius %.2f: %.2f%% of receiver pixels in penumbra", radius, 100.0 * share);
            QVERIFY2(share > 1.3 * previous, qPrintable(QString("radius %1: %2 after %3").arg(radius).arg(share).arg(previous)));
            if (first == 0.0)
                first = share;
            previous = share;
        }
        QVERIFY(first > 0.0);
        QVERIFY(previous > 3.0 * first);
    }

    void pcssPenumbraWidensWithTheBlockerDistance()
    {
        auto shareAt = [this](double height, const QStringList& assignments) {
            m_headless->renderer().setScene(occluderAt(height));
            return penumbraShare(m_headless->renderer().renderVisibility(with("occluder", assignments), QSize(320, 180)));
        };
        const QStringList pcss{"filter.mode=pcss", "filter.taps=32", "light.radius=0.2"};
        double previous = 0.0;
        std::vector<double> shares;
        for (const double height : {0.5, 1.0, 2.0}) {
            const double share = shareAt(height, pcss);
            qInfo("pcss, board %.1f above the plane: %.2f%% of receiver pixels in penumbra", height, 100.0 * share);
            QVERIFY2(share > 1.3 * previous, qPrintable(QString("height %1: %2 after %3").arg(height).arg(share).arg(previous)));
            shares.push_back(share);
            previous = share;
        }
        // A fixed kernel's penumbra does not follow the blocker (its rim only changes with the
        // shadow's outline in the image).
        const double fixedLow = shareAt(0.5, {"filter.mode=poisson"});
        const double fixedHigh = shareAt(2.0, {"filter.mode=poisson"});
        qInfo("poisson, board 0.5 and 2.0 above the plane: %.3f%% and %.3f%%", 100.0 * fixedLow, 100.0 * fixedHigh);
        QVERIFY(shares.back() / shares.front() > 2.0 * fixedHigh / fixedLow);
    }

    // Contact hardening without a second pass: dpcf's penumbra follows the blocker's distance
    // as pcss's does, where a fixed kernel's does not.
    void dpcfPenumbraWidensWithTheBlockerDistance()
    {
        auto shareAt = [this](double height, const QStringList& assignments) {
            m_headless->renderer().setScene(occluderAt(height));
            return penumbraShare(m_headless->renderer().renderVisibility(with("occluder", assignments), QSize(320, 180)));
        };
        const QStringList dpcf{"filter.mode=dpcf", "filter.taps=32", "light.radius=0.2"};
        std::vector<double> shares;
        for (const double height : {0.25, 1.0, 2.0}) {
            shares.push_back(shareAt(height, dpcf));
            qInfo("dpcf, board %.2f above the plane: %.2f%% of receiver pixels in penumbra", height, 100.0 * shares.back());
            if (shares.size() > 1)
                QVERIFY2(shares.back() > 1.2 * shares[shares.size() - 2], qPrintable(QString("height %1: %2 after %3").arg(height).arg(shares.back()).arg(shares[shares.size() - 2])));
        }
        const double fixedLow = shareAt(0.25, {"filter.mode=poisson"});
        const double fixedHigh = shareAt(2.0, {"filter.mode=poisson"});
        QVERIFY(shares.back() / shares.front() > 2.0 * fixedHigh / fixedLow);
    }

    // A wider pcf-optimized kernel is a wider penumbra, with no pixel of the hard shadow's
    // inside or outside turned over.
    void pcfOptimizedPenumbraWidensWithTheKernel_data()
    {
        QTest::addColumn<QString>("scene");
        for (const QString& scene : kScenes)
            QTest::newRow(qPrintable(scene)) << scene;
    }

    void pcfOptimizedPenumbraWidensWithTheKernel()
    {
        QFETCH(QString, scene);
        double previous = 0.0;
        for (const char* kernel : {"3", "5", "7"}) {
            const double share = penumbraShare(m_headless->renderer().renderVisibility(
                with(scene, {"filter.mode=pcf-optimized", QString("filter.kernel=%1").arg(kernel)}), QSize(320, 180)));
            qInfo("pcf-optimized %sx%s: %.2f%% of receiver pixels in penumbra", kernel, kernel, 100.0 * share);
            QVERIFY2(share > previous, qPrintable(QString("kernel %1: %2 after %3").arg(kernel).arg(share).arg(previous)));
            previous = share;
        }
    }

    // What PCSS is for: closer to the area light than fixed kernels at the same light radius.
    void pcssIsCloserToTheAreaLightThanFixedKernels_data()
    {
        QTest::addColumn<QString>("scene");
        for (const QString& scene : kScenes)
            QTest::newRow(qPrintable(scene)) << scene;
    }

    void pcssIsCloserToTheAreaLightThanFixedKernels()
    {
        QFETCH(QString, scene);
        Renderer& r = m_headless->renderer();
        const Measured pcss = measure(r, with(scene, {"filter.mode=pcss", "filter.taps=32"}), true);
        const double pcssError = agreement(pcss.buffer, pcss.reference.area).meanAbsoluteError;
        // Same camera, light and size: the same area reference.
        const double pcfError = agreement(r.renderVisibility(with(scene, {"filter.mode=pcf", "filter.kernel=3"}), kSize), pcss.reference.area)
                                    .meanAbsoluteError;
        const double poissonError = agreement(r.renderVisibility(with(scene, {"filter.mode=poisson", "filter.taps=32"}), kSize),
                                              pcss.reference.area).meanAbsoluteError;
        const double dpcfError = agreement(r.renderVisibility(with(scene, {"filter.mode=dpcf", "filter.taps=32"}), kSize), pcss.reference.area)
                                     .meanAbsoluteError;
        qInfo("MAE against the area reference: pcss %.4f, dpcf %.4f, pcf 3x3 %.4f, poisson %.4f", pcssError, dpcfError, pcfError, poissonError);
        QVERIFY(pcssError < pcfError);
        QVERIFY(pcssError < poissonError);
        // dpcf trades some of that for half the lookups: still nearer than a fixed kernel.
        QVERIFY(dpcfError < std::max(pcfError, poissonError));
    }

    // The blockers a disk light's receiver can have lie between the light and the receiver, and
    // the near plane only bounds them. Where it lies far in front of every caster (a point light
    // inside a model's bounds fits it at 1e-4 of the far plane), the search region it gives
    // spans half the map; the blocker search narrows it to the nearest depth the map holds
    // there (blocker_search.glsl), so the soft shadow stays what it is with the near plane as
    // fitted. Before, dpcf's error against the area light grew 2-3 times.
    void blockerSearchFollowsTheBlockersNotTheNearPlane_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("light");
        QTest::addColumn<QString>("filter");
        for (const QString& scene : kScenes) {
            for (const QString light : {"spot", "point"}) {
                for (const QString filter : {"pcss", "dpcf"})
                    QTest::newRow(qPrintable(scene + " " + light + " " + filter)) << scene << QString(light) << QString(filter);
            }
        }
    }

    void blockerSearchFollowsTheBlockersNotTheNearPlane()
    {
        QFETCH(QString, scene);
        QFETCH(QString, light);
        QFETCH(QString, filter);
        Renderer& r = m_headless->renderer();
        Settings fitted = with(scene, {"light.type=" + light, "filter.mode=" + filter});
        const Measured asFitted = measure(r, fitted, true);
        const double fittedError = agreement(asFitted.buffer, asFitted.reference.area).meanAbsoluteError;
        // The same volume (a point light's faces: from the nearest near plane to the farthest
        // far one), its near plane 30 times nearer the light: the same caster depths.
        double nearest = r.lightFrame().volume.nearPlane, farthest = r.lightFrame().volume.farPlane;
        for (const LightFrame& face : r.shadowViews().frames) {
            nearest = std::min(nearest, face.volume.nearPlane);
            farthest = std::max(farthest, face.volume.farPlane);
        }
        Settings closer = fitted;
        applyAssignment(closer, "light.fit=manual");
        closer.light.nearPlane = nearest / 30.0;
        closer.light.farPlane = farthest;
        if (light == u"spot") {
            const LightVolume& v = r.lightFrame().volume;
            closer.light.fov = 2.0 * glm::degrees(std::atan(std::max({v.right, -v.left, v.top, -v.bottom})));
        }
        const Measured nearer = measure(r, closer, true);
        const double closerError = agreement(nearer.buffer, nearer.reference.area).meanAbsoluteError;
        qInfo("MAE against the area light: %.4f with the near plane fitted (%.3g), %.4f at a 30th of it", fittedError, nearest, closerError);
        QVERIFY(fittedError > 0.0);
        QCOMPARE_LE(closerError, 1.3 * fittedError + 0.002);
    }

    // Every texel of the min/max depth mip bounds the map texels under it, including the odd
    // leftovers of sizes that are not powers of two.
    void depthRangeBoundsTheMap_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<bool>("moving");       // six frames with the light walking around the target
        QTest::addColumn<bool>("partial");      // level 0 rebuilt only where the map was written
        for (const int size : {2048, 1000, 333, 17})
            QTest::newRow(qPrintable(QString::number(size))) << QStringList{QString("map.size=%1").arg(size)} << false << false;
        // Several views side by side: a 2 x 2 and a 3 x 2 map of tiles.
        QTest::newRow("4 cascades of 500") << QStringList{"map.size=500", "shadow.cascades=4"} << false << false;
        QTest::newRow("2 cascades of 300") << QStringList{"map.size=300", "shadow.cascades=2"} << false << false;
        QTest::newRow("3 cascades of 256") << QStringList{"map.size=256", "shadow.cascades=3"} << false << false;
        QTest::newRow("cube of 256") << QStringList{"map.size=256", "light.type=point", "light.projection=perspective"} << false << false;
        // The software profile redraws level 0 only where the map's passes wrote, now and at the
        // last build (RasteriserTuning::rangesWrittenTexels): with the light walking, what the
        // casters left behind is rebuilt too. pcss reads the mip without filter.early_out; pcf's
        // plain map is drawn in slices (map.slices) over its whole tile, so rebuilt whole.
        QTest::newRow("light moving, 2048") << QStringList{} << true << false;
        QTest::newRow("light moving, pcss") << QStringList{"filter.mode=pcss", "filter.early_out=false"} << true << true;
        QTest::newRow("light moving, cube of 256") << QStringList{"map.size=256", "light.type=point"} << true << true;
        QTest::newRow("light moving, 3 cascades of 256") << QStringList{"map.size=256", "shadow.cascades=3"} << true << true;
    }

    void depthRangeBoundsTheMap()
    {
        QFETCH(QStringList, assignments);
        QFETCH(bool, moving);
        QFETCH(bool, partial);
        Renderer& r = m_headless->renderer();
        // The software profile's partial rebuild, whatever the driver.
        Settings s = with("seed", QStringList{"filter.mode=pcf", "filter.early_out=true", "rasteriser.profile=software"} + assignments);
        const glm::dvec3 start = s.light.position;
        for (int frame = 0; frame < (moving ? 6 : 1); ++frame) {
            // Around the target, a sixth of a turn a frame, lower and higher.
            const double angle = frame * glm::pi<double>() / 3.0;
            const glm::dvec3 offset = start - s.light.target;
            const double across = std::hypot(offset.x, offset.z);
            s.light.position = s.light.target + glm::dvec3(across * std::cos(angle), offset.y * (1.0 + 0.3 * std::sin(angle)), across * std::sin(angle));
            m_headless->renderFrame(s, kSize);
        }
        QVERIFY(r.depthRange());
        if (partial)
            QVERIFY2(r.depthRange()->levelZeroTexelsDrawn() < qint64(r.depthRange()->levelSize(0).width()) * r.depthRange()->levelSize(0).height(),
                     "the software profile rebuilt the whole level");
        m_headless->makeCurrent();
        GlFunctions* gl = m_headless->functions();
        const int width = r.shadowMap().width(), height = r.shadowMap().height();
        std::vector<float> depth(std::size_t(width) * std::size_t(height));
        gl->glBindTexture(GL_TEXTURE_2D, r.shadowMap().texture());
        gl->glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        // The atlas holds every level side by side (DepthRangePass.h).
        gl->glBindTexture(GL_TEXTURE_2D, r.depthRange()->texture());
        GLint atlasWidth = 0, atlasHeight = 0;
        gl->glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &atlasWidth);
        gl->glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &atlasHeight);
        QCOMPARE(r.depthRange()->levelSize(0), QSize((width + 3) / 4, (height + 3) / 4));
        QCOMPARE(r.depthRange()->levelSize(r.depthRange()->levels() - 1), QSize(1, 1));
        std::vector<glm::vec2> atlas(std::size_t(atlasWidth) * std::size_t(atlasHeight));
        gl->glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_FLOAT, atlas.data());
        int bad = 0;
        std::vector<QRect> placed;
        for (int level = 0; level < r.depthRange()->levels(); ++level) {
            const QSize size = r.depthRange()->levelSize(level);
            const QPoint origin = r.depthRange()->levelOrigin(level);
            const QRect rect(origin, size);
            QVERIFY(QRect(0, 0, atlasWidth, atlasHeight).contains(rect));
            for (const QRect& other : placed)
                QVERIFY2(!other.intersects(rect), qPrintable(QString("level %1 overlaps another").arg(level)));
            placed.push_back(rect);
            const int cover = 4 << level;   // map texels per texel side
            for (int y = 0; y < height; ++y) {
                for (int x = 0; x < width; ++x) {
                    const int tx = std::min(x / cover, size.width() - 1), ty = std::min(y / cover, size.height() - 1);
                    const glm::vec2 r2 = atlas[std::size_t(origin.y() + ty) * std::size_t(atlasWidth) + std::size_t(origin.x() + tx)];
                    const float d = float(r.shadowMap().slice().depth(depth[std::size_t(y) * std::size_t(width) + std::size_t(x)]));
                    // The read-back converts 24-bit depth to float on its own path: one ulp apart.
                    if ((d < r2.x - 1e-6f || d > r2.y + 1e-6f) && bad++ < 5)
                        qWarning("level %d texel %d,%d (%f, %f) misses map texel %d,%d depth %f", level, tx, ty, r2.x, r2.y, x, y, d);
                }
            }
        }
        gl->glBindTexture(GL_TEXTURE_2D, 0);
        QCOMPARE(bad, 0);
    }

    // Penumbra-only filtering skips taps only where their result is known: the same image.
    void earlyOutGivesTheSameImage_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        const std::pair<const char*, QStringList> configurations[] = {
            {"pcf 3x3", {"filter.mode=pcf", "filter.kernel=3"}},
            {"pcf 7x7", {"filter.mode=pcf", "filter.kernel=7"}},
            {"pcf 9x9 receiver plane", {"filter.mode=pcf", "filter.kernel=9", "bias.receiver_plane=true"}},
            {"poisson 16 r2.5", {"filter.mode=poisson"}},
            {"poisson 64 r32", {"filter.mode=poisson", "filter.taps=64", "filter.radius=32"}},
            {"poisson 24 r6, 1000 map", {"filter.mode=poisson", "filter.taps=24", "filter.radius=6", "map.size=1000"}},
            {"poisson depth32f", {"filter.mode=poisson", "map.format=depth32f"}},
            {"pcf 5x5 perspective", {"filter.mode=pcf", "filter.kernel=5", "light.projection=perspective"}},
            // PCSS decides per pixel how wide its footprint is, so pixels side by side read
            // different levels of the mip.
            {"pcss 16", {"filter.mode=pcss"}},
            {"pcss 32, light radius 0.5", {"filter.mode=pcss", "filter.taps=32", "light.radius=0.5"}},
            {"pcss 16, light radius 0.01", {"filter.mode=pcss", "light.radius=0.01"}},
            {"pcss 16 receiver plane", {"filter.mode=pcss", "bias.receiver_plane=true"}},
            {"pcss 24 perspective", {"filter.mode=pcss", "filter.taps=24", "light.projection=perspective"}},
            {"pcss 16, 777 map", {"filter.mode=pcss", "map.size=777"}},
            // Several views in one map: each pixel's footprint in its own view's tile.
            {"pcf 5x5, 4 cascades", {"filter.mode=pcf", "filter.kernel=5", "shadow.cascades=4"}},
            {"pcss 16, 3 cascades of 500", {"filter.mode=pcss", "shadow.cascades=3", "map.size=500"}},
            {"pcf 7x7, point light", {"filter.mode=pcf", "filter.kernel=7", "light.type=point"}},
            {"pcss 16, point light", {"filter.mode=pcss", "light.type=point"}},
            {"pcf-optimized 3x3", {"filter.mode=pcf-optimized", "filter.kernel=3"}},
            {"pcf-optimized 7x7 receiver plane", {"filter.mode=pcf-optimized", "filter.kernel=7", "bias.receiver_plane=true"}},
            {"pcf-optimized 5x5, 777 map", {"filter.mode=pcf-optimized", "filter.kernel=5", "map.size=777"}},
            {"pcf-optimized 5x5, 4 cascades", {"filter.mode=pcf-optimized", "filter.kernel=5", "shadow.cascades=4"}},
            {"pcf-optimized 7x7, point light", {"filter.mode=pcf-optimized", "filter.kernel=7", "light.type=point"}},
            {"dpcf 16", {"filter.mode=dpcf"}},
            {"dpcf 24 perspective", {"filter.mode=dpcf", "filter.taps=24", "light.projection=perspective"}},
            {"dpcf 16, point light", {"filter.mode=dpcf", "light.type=point"}},
        };
        for (const QString& scene : kScenes) {
            for (const auto& [name, assignments] : configurations)
                QTest::newRow(qPrintable(QString("%1, %2").arg(scene, name))) << scene << assignments;
        }
    }

    void earlyOutGivesTheSameImage()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        Renderer& r = m_headless->renderer();
        const VisibilityBuffer skipping = r.renderVisibility(with(scene, assignments + QStringList{"filter.early_out=true"}), kSize);
        const VisibilityBuffer everyTap = r.renderVisibility(with(scene, assignments + QStringList{"filter.early_out=false"}), kSize);
        QCOMPARE_LE(maxChannelDifference(skipping.image, everyTap.image), 1);
        float worst = 0.0f;
        for (int i = 0; i < skipping.pixelCount(); ++i)
            worst = std::max(worst, std::abs(skipping.visibility(i) - everyTap.visibility(i)));
        QCOMPARE_LE(worst, 1.0f / 255.0f);
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(TestSoftShadows)
#include "tst_SoftShadows.moc"
