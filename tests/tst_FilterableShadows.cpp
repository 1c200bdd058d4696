// The moment techniques (vsm, evsm2, evsm4, msm, esm), checked against the Embree references at
// exactly the rendered pixels: what the ray tracer says is shadowed is dark (up to a stated
// allowance for light bleeding, their known failure), what it says is lit stays lit, the blur
// widens the penumbra, 16- and 32-bit moments both work, nothing is NaN at extreme depth
// ranges, the shadow-map cache covers the moments pass and blur, and bad settings are refused.
#include "Application.h"
#include "HeadlessTestMain.h"
#include "HeadlessRenderer.h"
#include "MomentMath.h"
#include "Measurement.h"
#include "MomentsBlurPass.h"
#include "RayTracer.h"
#include "RenderProbe.h"
#include "SceneLibrary.h"
#include "SceneNames.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowReference.h"
#include "ShadowTechnique.h"

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace shadowlab;

namespace {

const QSize kSize(200, 112);

Settings with(const QString& scene, const QStringList& assignments)
{
    Settings s = presetSettings(scene);
    for (const QString& a : assignments)
        applyAssignment(s, a);
    return s;
}

QStringList momentTechniques()
{
    QStringList keys;
    for (const ShadowTechnique& t : shadowTechniques()) {
        if (t.map == ShadowMapKind::Moments)
            keys << t.key;
    }
    return keys;
}

// Receiver pixels facing the light, against the hard reference.
struct Agreement {
    int counted = 0;
    int referenceShadowed = 0;
    int referenceLit = 0;
    int falseShadow = 0;
    int falseLight = 0;
    int notFinite = 0;
    QString text() const
    {
        return QString("%1 counted, %2 shadowed in the reference, %3 false shadow, %4 false light, %5 not finite")
            .arg(counted).arg(referenceShadowed).arg(falseShadow).arg(falseLight).arg(notFinite);
    }
};

Agreement agreement(Renderer& renderer, const Settings& settings, QSize size = kSize)
{
    const VisibilityBuffer buffer = renderer.renderVisibility(settings, size);
    const RayTracer tracer(*renderer.scene(), buffer.cameraPosition);
    ReferenceOptions options;
    options.area = false;
    const ReferenceVisibility reference = traceReference(tracer, buffer, renderer.lightFrame(), options);
    Agreement a;
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        const float v = buffer.visibility(i);
        if (!std::isfinite(v) || v < 0.0f || v > 1.0f) {
            ++a.notFinite;
            continue;
        }
        if (buffer.mask(i) != VisibilityBuffer::FacingLight)
            continue;
        const float e = reference.hard[std::size_t(i)];
        ++a.counted;
        a.referenceShadowed += e < 0.5f;
        a.referenceLit += e >= 0.5f;
        a.falseShadow += v < e - 0.5f;
        a.falseLight += v > e + 0.5f;
    }
    return a;
}

// Pixels in a penumbra: neither lit nor shadowed.
int penumbraPixels(const VisibilityBuffer& buffer)
{
    int n = 0;
    for (int i = 0; i < buffer.pixelCount(); ++i)
        n += buffer.mask(i) == VisibilityBuffer::FacingLight && buffer.visibility(i) > 0.1f && buffer.visibility(i) < 0.9f;
    return n;
}

} // namespace

class tst_FilterableShadows : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase()
    {
        m_headless->makeCurrent();
        m_headless.reset();
    }

    void shadowsWhereTheReferenceSays_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<double>("bleedingAllowance");
        // Light bleeding is these techniques' known false light: VSM's most of all, where a
        // receiver sees occluders at different depths (`bleeding`, `cubes`); the exponential
        // warps and MSM bound it far tighter. The allowance is a share of the reference's
        // shadowed pixels.
        const QStringList placements{QString(), "light.position=3,6,2"};
        for (const QString& scene : sceneNames()) {
            // One map over a kilometre of city is not how the city is meant to be shadowed: the
            // exponential warps fail over its depth range (measured in the report); with
            // cascades it is tested below.
            if (cityBuildingCount(scene) > 0)
                continue;
            for (const QString& technique : momentTechniques()) {
                for (const char* bits : {"32", "16"}) {
                    for (const QString& placement : placements) {
                        if (!placement.isEmpty() && QLatin1String(bits) == QLatin1String("16"))
                            continue;
                        QStringList a{"filter.mode=" + technique, QString("moments.format=%1").arg(bits)};
                        if (!placement.isEmpty())
                            a << placement << "light.target=0,0,0";
                        // ESM at 16 bits holds c <= 11.08 only: it leaks near contacts.
                        const double allowance = technique == u"vsm" || (technique == u"esm" && QLatin1String(bits) == QLatin1String("16")) ? 0.25 : 0.08;
                        QTest::addRow("%s %s %s-bit%s", qPrintable(scene), qPrintable(technique), bits, placement.isEmpty() ? "" : " other light")
                            << scene << a << allowance;
                    }
                }
            }
        }
    }

    void shadowsWhereTheReferenceSays()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        QFETCH(double, bleedingAllowance);
        const Agreement a = agreement(m_headless->renderer(), with(scene, assignments));
        const QString why = a.text();
        QVERIFY2(a.notFinite == 0, qPrintable(why));
        QVERIFY2(a.referenceShadowed > 20, qPrintable(why));
        // Shadowed where the reference says so, but for the bleeding allowance.
        QVERIFY2(a.falseLight <= bleedingAllowance * a.referenceShadowed + 0.002 * a.counted, qPrintable(why));
        // Lit where the reference says lit: only a one-texel-wide band at shadow edges may differ.
        QVERIFY2(a.falseShadow <= 0.01 * a.referenceLit, qPrintable(why));
    }

    // Cascades and a point light's faces: one moments tile per view, blurred within its tile.
    // The city, which one map cannot cover, is shadowed where the reference says with cascades.
    void severalViewsShadowWhereTheReferenceSays_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<double>("bleedingAllowance");
        const QStringList views[] = {
            {"shadow.cascades=3", "shadow.distance=100"},
            {"shadow.cascades=4", "shadow.distance=100", "light.stabilize=false"},
            {"light.type=point", "light.position=0.5,2.6,0.8"},
        };
        for (const QString scene : {"city", "seed", "cubes"}) {
            for (const QString& technique : momentTechniques()) {
                for (int v = 0; v < 3; ++v) {
                    const bool point = v == 2;
                    // The city is a directional light's scene; cubes is tried with the point light.
                    if ((point && scene == u"city") || (!point && scene == u"cubes"))
                        continue;
                    QStringList a{"filter.mode=" + technique};
                    a << views[v];
                    if (!point && scene != u"city")
                        a.replaceInStrings("shadow.distance=100", "shadow.distance=12");
                    const double allowance = technique == u"vsm" ? 0.25 : 0.08;
                    QTest::addRow("%s %s %s", qPrintable(scene), qPrintable(technique), qPrintable(views[v].first()))
                        << QString(scene) << a << allowance;
                }
            }
        }
    }

    void severalViewsShadowWhereTheReferenceSays()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, assignments);
        QFETCH(double, bleedingAllowance);
        const Settings s = with(scene, assignments);
        QVERIFY(usesShadowViews(s));
        const Agreement a = agreement(m_headless->renderer(), s, QSize(320, 180));
        const QString why = a.text();
        QVERIFY2(m_headless->renderer().shadowViews().set.views.size() > 1, qPrintable(why));
        QVERIFY2(a.notFinite == 0, qPrintable(why));
        QVERIFY2(a.referenceShadowed > 20, qPrintable(why));
        QVERIFY2(a.falseLight <= bleedingAllowance * a.referenceShadowed + 0.002 * a.counted, qPrintable(why));
        QVERIFY2(a.falseShadow <= 0.01 * a.referenceLit, qPrintable(why));
        qInfo().noquote() << why;
    }

    // Each view's tile is blurred on its own: the blurred atlas is, tile by tile, the unblurred
    // one through the same Gaussian clamped at the tile's edges (not at the atlas's), so no
    // view's moments leak into its neighbour's.
    void blurStaysInsideEachTile_data()
    {
        QTest::addColumn<QStringList>("views");
        QTest::newRow("point light") << QStringList{"light.type=point", "light.position=0.5,2.6,0.8"};
        QTest::newRow("4 cascades") << QStringList{"shadow.cascades=4", "shadow.distance=12"};
    }

    void blurStaysInsideEachTile()
    {
        QFETCH(QStringList, views);
        constexpr int kBlur = 15;
        const QStringList common = QStringList{"filter.mode=vsm", "map.size=128", "moments.format=32"} + views;
        Renderer& r = m_headless->renderer();
        const auto atlas = [&](int blur) {
            m_headless->renderFrame(with("seed", common + QStringList{QString("moments.blur=%1").arg(blur)}), kSize);
            m_headless->makeCurrent();
            const MomentsMap* map = r.momentsMap();
            std::vector<glm::vec4> texels(std::size_t(map->width()) * std::size_t(map->height()));
            GlFunctions* gl = m_headless->functions();
            gl->glBindTexture(GL_TEXTURE_2D, map->texture());
            gl->glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, texels.data());
            gl->glBindTexture(GL_TEXTURE_2D, 0);
            return texels;
        };
        const std::vector<glm::vec4> sharp = atlas(0);
        const std::vector<glm::vec4> blurred = atlas(kBlur);
        const MomentsMap* map = r.momentsMap();
        QVERIFY(map->columns() * map->rows() > 1);
        const int width = map->width(), tile = map->size();
        const std::vector<float> w = MomentsBlurPass::weights(kBlur);
        const int radius = int(w.size()) - 1;
        double worst = 0.0;
        int differing = 0;     // texels the blur changed at all: the test has something to check
        for (int ty = 0; ty < map->rows(); ++ty) {
            for (int tx = 0; tx < map->columns(); ++tx) {
                const int x0 = tx * tile, y0 = ty * tile;
                const auto at = [&](const std::vector<glm::vec4>& t, int x, int y) {
                    return t[std::size_t(std::clamp(y, y0, y0 + tile - 1)) * std::size_t(width) + std::size_t(std::clamp(x, x0, x0 + tile - 1))];
                };
                // Horizontal, then vertical, both clamped to the tile, as the two passes are.
                std::vector<glm::dvec4> rows(std::size_t(tile) * std::size_t(tile));
                for (int y = 0; y < tile; ++y)
                    for (int x = 0; x < tile; ++x) {
                        glm::dvec4 sum(0.0);
                        for (int i = -radius; i <= radius; ++i)
                            sum += double(w[std::size_t(std::abs(i))]) * glm::dvec4(at(sharp, x0 + x + i, y0 + y));
                        rows[std::size_t(y) * std::size_t(tile) + std::size_t(x)] = sum;
                    }
                for (int y = 0; y < tile; ++y)
                    for (int x = 0; x < tile; ++x) {
                        glm::dvec4 sum(0.0);
                        for (int i = -radius; i <= radius; ++i)
                            sum += double(w[std::size_t(std::abs(i))]) * rows[std::size_t(std::clamp(y + i, 0, tile - 1)) * std::size_t(tile) + std::size_t(x)];
                        const glm::vec4 got = at(blurred, x0 + x, y0 + y);
                        worst = std::max(worst, glm::length(glm::dvec2(got) - glm::dvec2(sum)));
                        differing += glm::length(glm::dvec2(got) - glm::dvec2(at(sharp, x0 + x, y0 + y))) > 1e-4;
                    }
            }
        }
        const QString numbers = QString("largest difference from the per-tile blur %1; %2 texels changed by the blur").arg(worst).arg(differing);
        QVERIFY2(differing > 100, qPrintable(numbers));
        QVERIFY2(worst < 1e-4, qPrintable(numbers));
        qInfo().noquote() << numbers;
    }

    // Mips of a map of several views would blend neighbouring views: refused, with the fix named.
    void mipmapsWithSeveralViewsRefused()
    {
        for (const QStringList& views : {QStringList{"shadow.cascades=3"}, QStringList{"light.type=point"}}) {
            Settings s = with("seed", QStringList{"filter.mode=evsm4", "moments.mipmaps=true"} + views);
            try {
                ensureValid(s);
                QFAIL("accepted");
            } catch (const SettingsError& e) {
                QCOMPARE(e.key(), QStringLiteral("moments.mipmaps"));
                QVERIFY2(QString::fromUtf8(e.what()).contains("moments.mipmaps=false"), e.what());
            }
            s.moments.mipmaps = false;
            ensureValid(s);
        }
    }

    void bleedingReductionCutsFalseLight_data()
    {
        QTest::addColumn<QString>("technique");
        for (const QString& t : momentTechniques()) {
            if (usesParameter(with("bleeding", {"filter.mode=" + t}).filter, "filter.bleeding"))
                QTest::newRow(qPrintable(t)) << t;
        }
    }

    void bleedingReductionCutsFalseLight()
    {
        // On the scene built to bleed, the reduction removes false light and never adds it.
        QFETCH(QString, technique);
        int previous = -1;
        for (const char* amount : {"0.6", "0.3", "0"}) {
            const Agreement a = agreement(m_headless->renderer(), with("bleeding", {"filter.mode=" + technique, QString("filter.bleeding=%1").arg(amount),
                                                                               "moments.blur=15", "map.size=512"}));
            QVERIFY2(a.notFinite == 0, qPrintable(a.text()));
            QVERIFY2(a.falseLight >= previous, qPrintable(QString("bleeding %1: %2, less reduction had %3 false light").arg(amount, a.text()).arg(previous)));
            previous = a.falseLight;
        }
    }

    void vsmBleedsMostOnTheBleedingScene()
    {
        // The classic failure, measured: with no reduction and a filter footprint wide enough
        // to span the boards' edges (15 texels of a 512 map), VSM lets more light through stacked
        // occluders than EVSM4 and MSM.
        auto falseLight = [&](const QString& technique) {
            return agreement(m_headless->renderer(), with("bleeding", {"filter.mode=" + technique, "filter.bleeding=0", "moments.blur=15", "map.size=512"}),
                             QSize(320, 180)).falseLight;
        };
        const int vsm = falseLight("vsm");
        const int evsm4 = falseLight("evsm4");
        const int msm = falseLight("msm");
        const int hausdorff = falseLight("msm-hausdorff");
        const QString why = QString("false light: vsm %1, evsm4 %2, msm %3, msm-hausdorff %4").arg(vsm).arg(evsm4).arg(msm).arg(hausdorff);
        qInfo().noquote() << why;
        QVERIFY2(vsm > 0, qPrintable(why));
        QVERIFY2(vsm > 2 * evsm4 && vsm > 2 * msm && vsm > 2 * hausdorff, qPrintable(why));
        // Knowing every depth lies in the light's volume bounds the shadow more tightly.
        QVERIFY2(hausdorff <= msm, qPrintable(why));
    }

    void blurWidensThePenumbra_data()
    {
        QTest::addColumn<QString>("technique");
        QTest::addColumn<QString>("format");
        for (const QString& t : momentTechniques())
            for (const char* bits : {"32", "16"})
                QTest::addRow("%s %s-bit", qPrintable(t), bits) << t << QString(bits);
    }

    void blurWidensThePenumbra()
    {
        QFETCH(QString, technique);
        QFETCH(QString, format);
        Renderer& r = m_headless->renderer();
        int previous = -1;
        for (const char* blur : {"0", "3", "7", "15"}) {
            const Settings s = with("occluder", {"filter.mode=" + technique, "moments.format=" + format, QString("moments.blur=%1").arg(blur),
                                                 "filter.bleeding=0", "map.size=512"});
            const int penumbra = penumbraPixels(r.renderVisibility(s, QSize(320, 180)));
            QVERIFY2(penumbra > previous, qPrintable(QString("blur %1: %2 penumbra pixels, narrower blur had %3").arg(blur).arg(penumbra).arg(previous)));
            previous = penumbra;
        }
    }

    // The blur in the lookup (moments.blur_at=lookup) is the blur pass's kernel read through
    // bilinear pairs, for widths auto leaves to either side, over one view or the tiles of
    // several: with coverage the same frame within the filtering's rounding (a GPU's bilinear
    // weights have 8 bits of fraction, llvmpipe's more); four moments without it (the ground in
    // their map, a reconstruction that rounding moves where it is ill-conditioned) differ in a
    // handful of pixels at most, as do 16-bit moments, which the pass rounds after blurring and
    // the lookup before. Without a blur pass the map holds no texture for its first axis.
    void lookupBlurMatchesTheBlurPass_data()
    {
        QTest::addColumn<QString>("technique");
        QTest::addColumn<int>("blur");
        QTest::addColumn<QStringList>("more");
        for (const QString& t : momentTechniques())
            for (const int blur : {3, 5, 9})
                QTest::addRow("%s blur %d", qPrintable(t), blur) << t << blur << QStringList{};
        QTest::newRow("vsm 16-bit blur 3") << "vsm" << 3 << QStringList{"moments.format=16"};
        QTest::newRow("evsm2 point light blur 5") << "evsm2" << 5 << QStringList{"light.type=point", "light.position=0.5,2.6,0.8"};
        QTest::newRow("esm 4 cascades blur 3") << "esm" << 3 << QStringList{"shadow.cascades=4", "shadow.distance=12"};
        QTest::newRow("msm 4 cascades blur 5") << "msm" << 5 << QStringList{"shadow.cascades=4", "shadow.distance=12"};
    }

    void lookupBlurMatchesTheBlurPass()
    {
        QFETCH(QString, technique);
        QFETCH(int, blur);
        QFETCH(QStringList, more);
        Renderer& r = m_headless->renderer();
        const QStringList common = QStringList{"filter.mode=" + technique, QString("moments.blur=%1").arg(blur), "map.size=256", "filter.bleeding=0"} + more;
        const VisibilityBuffer pass = r.renderVisibility(with("seed", common + QStringList{"moments.blur_at=map"}), kSize);
        QVERIFY(r.lastFrame().counts.blurTexels > 0);
        QVERIFY(r.momentsMap()->scratchTexture() != 0);
        const VisibilityBuffer lookup = r.renderVisibility(with("seed", common + QStringList{"moments.blur_at=lookup"}), kSize);
        QCOMPARE(r.lastFrame().counts.blurTexels, std::int64_t(0));
        QCOMPARE(r.momentsMap()->scratchTexture(), GLuint(0));      // no blur pass: no texture for its first axis
        QCOMPARE(r.lastPlan().tapsPerLookup, (blur + 1) * (blur + 1) / 4);
        const VisibilityBuffer sharp = r.renderVisibility(with("seed", common + QStringList{"moments.blur=0"}), kSize);
        int counted = 0, differing = 0, blurred = 0;
        float worst = 0.0f;
        for (int i = 0; i < pass.pixelCount(); ++i) {
            if (pass.mask(i) != VisibilityBuffer::FacingLight)
                continue;
            const float d = std::abs(pass.visibility(i) - lookup.visibility(i));
            ++counted;
            worst = std::max(worst, d);
            differing += d > 0.02f;
            blurred += std::abs(pass.visibility(i) - sharp.visibility(i)) > 0.05f;
        }
        const QString numbers = QString("%1 of %2 pixels differ by more than 0.02 (largest %3); the blur itself moved %4")
                                    .arg(differing).arg(counted).arg(worst).arg(blurred);
        qInfo().noquote() << numbers;
        QVERIFY2(blurred > 20, qPrintable(numbers));
        const Settings s = with("seed", common);
        if (shadowTechnique(s.filter.mode).coverage && s.moments.format == MomentFormat::Rgba32F)
            QVERIFY2(worst < 0.01f, qPrintable(numbers));
        else
            QVERIFY2(differing <= counted / 500, qPrintable(numbers));
    }

    // vsm, evsm2 and esm store the casters' coverage, so the ground under the seed's casters
    // stays out of their map: far fewer samples drawn, and the same shadows (against the
    // reference, and against the map with the ground in). evsm4 and msm, without a channel for
    // coverage, draw it only around the casters, and everywhere where a mip reads far from them;
    // msm-hausdorff, which reads the far plane near it as shadow, everywhere.
    void coverageLeavesFloorsOut_data()
    {
        QTest::addColumn<QString>("technique");
        for (const QString& t : momentTechniques())
            QTest::newRow(qPrintable(t)) << t;
    }

    void coverageLeavesFloorsOut()
    {
        QFETCH(QString, technique);
        const QStringList common{"filter.mode=" + technique};
        const Settings out = with("seed", common), in = with("seed", common + QStringList{"bias.skip_floors=false"});
        const bool coverage = shadowTechnique(out.filter.mode).coverage;
        countFrames(*m_headless, out, kSize);     // the far plane's moments drawn once, then cleared to their value
        const FrameCounts outCounts = countFrames(*m_headless, out, kSize), inCounts = countFrames(*m_headless, in, kSize);
        const QString samples = QString("%1 samples with floors out, %2 in").arg(outCounts.shadow.samples).arg(inCounts.shadow.samples);
        if (coverage) {
            QVERIFY2(outCounts.shadow.samples * 2 < inCounts.shadow.samples, qPrintable(samples));
        } else if (!shadowTechnique(out.filter.mode).farPlaneReadsLit) {
            QCOMPARE(outCounts.shadow.samples, inCounts.shadow.samples);     // msm-hausdorff: floors everywhere
        } else {
            QVERIFY2(outCounts.shadow.samples * 3 < inCounts.shadow.samples * 2, qPrintable(samples));
            // A floor casts nothing then: under the software profile only the receivers a caster
            // reaches look up, a small share of the ground.
            const QString lookups = QString("%1 lookups with floors around the casters, %2 with floors in")
                                        .arg(outCounts.lookupFragments).arg(inCounts.lookupFragments);
            QVERIFY2(outCounts.lookupFragments * 4 < inCounts.lookupFragments, qPrintable(lookups));
            const QStringList mips{"moments.mipmaps=true"};
            const FrameCounts mipsOut = countFrames(*m_headless, with("seed", common + mips), kSize);
            const FrameCounts mipsIn = countFrames(*m_headless, with("seed", common + mips + QStringList{"bias.skip_floors=false"}), kSize);
            QCOMPARE(mipsOut.shadow.samples, mipsIn.shadow.samples);
        }
        Renderer& r = m_headless->renderer();
        const Agreement a = agreement(r, out), b = agreement(r, in);
        QVERIFY2(a.notFinite == 0 && a.falseLight <= b.falseLight + 0.001 * a.counted && a.falseShadow <= b.falseShadow + 0.001 * a.counted,
                 qPrintable("floors out: " + a.text() + "; in: " + b.text()));
        const VisibilityBuffer x = r.renderVisibility(out, kSize), y = r.renderVisibility(in, kSize);
        int differing = 0;
        for (int i = 0; i < x.pixelCount(); ++i)
            differing += x.mask(i) == VisibilityBuffer::FacingLight && std::abs(x.visibility(i) - y.visibility(i)) > 0.1f;
        QVERIFY2(differing <= a.counted / 200, qPrintable(QString("%1 of %2 pixels differ by more than 0.1; %3").arg(differing).arg(a.counted).arg(samples)));
    }

    void mipmapsAndAnisotropyRender()
    {
        for (const QString& t : momentTechniques()) {
            const Agreement a = agreement(m_headless->renderer(), with("seed", {"filter.mode=" + t, "moments.mipmaps=true", "moments.anisotropy=16"}));
            QVERIFY2(a.notFinite == 0 && a.falseLight <= 0.08 * a.referenceShadowed + 0.002 * a.counted && a.falseShadow <= 0.01 * a.referenceLit,
                     qPrintable(t + ": " + a.text()));
        }
    }

    void finiteAtExtremeDepthRanges_data()
    {
        QTest::addColumn<QStringList>("assignments");
        const QList<QPair<const char*, QStringList>> ranges{
            {"ortho -1e6..1e6", {"light.fit=manual", "light.near=-1e6", "light.far=1e6"}},
            {"ortho 1e-4 thick", {"light.fit=manual", "light.near=4.4", "light.far=4.4001"}},
            {"perspective 1e-3..1e4", {"light.projection=perspective", "light.fit=manual", "light.near=0.001", "light.far=1e4"}},
            {"light 1e6 away", {"light.position=-2e6,4e6,-1e6"}}};
        for (const QString& t : momentTechniques())
            for (const char* bits : {"32", "16"})
                for (const auto& [name, assignments] : ranges)
                    QTest::addRow("%s %s-bit %s", qPrintable(t), bits, name)
                        << (QStringList{"filter.mode=" + t, QString("moments.format=%1").arg(bits)} + assignments);
    }

    void finiteAtExtremeDepthRanges()
    {
        QFETCH(QStringList, assignments);
        const VisibilityBuffer buffer = m_headless->renderer().renderVisibility(with("seed", assignments), QSize(160, 90));
        int bad = 0;
        for (int i = 0; i < buffer.pixelCount(); ++i) {
            const float v = buffer.visibility(i);
            bad += !std::isfinite(v) || v < 0.0f || v > 1.0f;
        }
        QVERIFY2(bad == 0, qPrintable(QString("%1 pixels with a visibility that is NaN or outside [0, 1]").arg(bad)));
    }

    void cacheCoversMomentsAndBlur()
    {
        Renderer& r = m_headless->renderer();
        Settings s = with("seed", {"filter.mode=evsm4"});
        m_headless->renderFrame(s, kSize);
        const int passes = r.shadowPassCount();
        m_headless->renderFrame(s, kSize);
        QCOMPARE(r.shadowPassCount(), passes);  // unchanged light and casters: no pass
        // Lookup-time settings need no new map.
        for (const char* a : {"filter.bleeding=0.5", "filter.moment_bias=0.001", "moments.view=3"}) {
            applyAssignment(s, a);
            m_headless->renderFrame(s, kSize);
            QVERIFY2(r.shadowPassCount() == passes, a);
        }
        // A blur in the lookup leaves a map of coverage as it is.
        Settings coverage = with("seed", {"filter.mode=vsm"});
        m_headless->renderFrame(coverage, kSize);
        const int vsmPasses = r.shadowPassCount();
        applyAssignment(coverage, "moments.blur=5");
        m_headless->renderFrame(coverage, kSize);
        QCOMPARE(r.shadowPassCount(), vsmPasses);
        m_headless->renderFrame(s, kSize);
        QCOMPARE(r.shadowPassCount(), vsmPasses + 1);
        // What the map stores does: how far around the casters its floors go, which follows the
        // lookup's blur and normal offset, and anisotropy, which moves the blur into its own pass
        // over the map.
        int expected = r.shadowPassCount();
        for (const char* a : {"moments.blur=5", "bias.normal=1", "moments.anisotropy=8", "moments.blur=7", "moments.format=16", "moments.mipmaps=true", "filter.exponent_negative=3", "filter.mode=msm"}) {
            applyAssignment(s, a);
            m_headless->renderFrame(s, kSize);
            QVERIFY2(r.shadowPassCount() == ++expected, a);
            m_headless->renderFrame(s, kSize);
            QVERIFY2(r.shadowPassCount() == expected, a);
        }
    }

    void depthViewShowsTheFirstMoment()
    {
        // Overhead light on the board: the view shows depth, so the board (near the light) is
        // darker than the far plane around it, and its square (moment 2) darker still.
        const Settings vsm = with("occluder", {"filter.mode=vsm", "moments.blur=0"});
        for (const QString& t : momentTechniques()) {
            Settings s = with("occluder", {"filter.mode=" + t, "moments.blur=0"});
            m_headless->renderFrame(s, kSize);
            const QImage view = m_headless->renderDepthMap(QSize(128, 128));
            const double board = probe::luminance(view, {64, 64});
            const double outside = probe::luminance(view, {2, 2});
            QVERIFY2(board + 40 < outside, qPrintable(QString("%1: board %2, around it %3").arg(t).arg(board).arg(outside)));
        }
        Settings second = vsm;
        second.moments.view = 2;
        m_headless->renderFrame(vsm, kSize);
        const double first = probe::luminance(m_headless->renderDepthMap(QSize(128, 128)), {64, 64});
        m_headless->renderFrame(second, kSize);
        const double squared = probe::luminance(m_headless->renderDepthMap(QSize(128, 128)), {64, 64});
        QVERIFY2(squared < first, qPrintable(QString("depth %1, its square %2").arg(first).arg(squared)));
    }

    void blurWeightsAreANormalisedGaussian()
    {
        for (int width : {3, 7, 15, 31}) {
            const std::vector<float> w = MomentsBlurPass::weights(width);
            QCOMPARE(int(w.size()), (width + 1) / 2);
            double sum = w[0];
            for (std::size_t i = 1; i < w.size(); ++i) {
                sum += 2.0 * w[i];
                QVERIFY(w[i] < w[i - 1]);
            }
            QVERIFY(std::abs(sum - 1.0) < 1e-5);
        }
        QCOMPARE(int(MomentsBlurPass::weights(0).size()), 1);
    }

    void exponentsClampedToTheFormat()
    {
        Settings s = with("seed", {"filter.mode=evsm4", "moments.format=16", "filter.exponent_positive=40", "filter.exponent_negative=2"});
        const MomentWarp warp = momentWarp(s);
        QVERIFY(std::exp(2.0 * warp.positive) <= 65504.0);
        QVERIFY(warp.positive > 5.5);
        QCOMPARE(warp.negative, 2.0);
        bool warned = false;
        for (const SettingsIssue& issue : validate(s))
            warned |= issue.severity == SettingsIssue::Severity::Warning && issue.key == u"filter.exponent_positive" && issue.message.contains("moments.format=32");
        QVERIFY(warned);
        s.moments.format = MomentFormat::Rgba32F;
        QCOMPARE(momentWarp(s).positive, 40.0);
        QVERIFY(std::exp(maxExponent(FilterMode::Esm, MomentFormat::Rgba32F)) <= double(std::numeric_limits<float>::max()));
    }

    void badSettingsRefused_data()
    {
        QTest::addColumn<QString>("assignment");
        QTest::addColumn<QString>("key");
        QTest::newRow("even blur") << "moments.blur=4" << "moments.blur";
        QTest::newRow("blur too wide") << "moments.blur=33" << "moments.blur";
        QTest::newRow("negative blur") << "moments.blur=-1" << "moments.blur";
        QTest::newRow("format 24") << "moments.format=24" << "moments.format";
        QTest::newRow("anisotropy 0") << "moments.anisotropy=0" << "moments.anisotropy";
        QTest::newRow("view 5") << "moments.view=5" << "moments.view";
        QTest::newRow("bleeding 1") << "filter.bleeding=1" << "filter.bleeding";
        QTest::newRow("bleeding NaN") << "filter.bleeding=nan" << "filter.bleeding";
        QTest::newRow("negative moment bias") << "filter.moment_bias=-1e-4" << "filter.moment_bias";
        QTest::newRow("exponent 81") << "filter.exponent_positive=81" << "filter.exponent_positive";
        QTest::newRow("negative exponent") << "filter.exponent_negative=-1" << "filter.exponent_negative";
    }

    void badSettingsRefused()
    {
        QFETCH(QString, assignment);
        QFETCH(QString, key);
        Settings s = presetSettings("seed");
        const Settings before = s;
        try {
            applyAssignment(s, assignment);
            QFAIL("accepted");
        } catch (const SettingsError& e) {
            QCOMPARE(e.key(), key);
            const QString message = QString::fromUtf8(e.what());
            QVERIFY2(message.contains("allowed") || message.contains("finite number in") || message.contains("use 0"), qPrintable(message));
        }
        QVERIFY(s == before);
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(tst_FilterableShadows)
#include "tst_FilterableShadows.moc"
