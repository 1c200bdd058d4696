// Contact shadows (contact.*): the march over the camera's depth of the casters, checked
// against the Embree reference at exactly the rendered pixels. With a bias large enough to lift
// shadows off their casters, it gives back the shadow at the contacts without darkening what
// the reference says is lit; it only ever darkens; and a frame that changed nothing the camera
// sees keeps the camera's depth instead of drawing it again.
#include "Application.h"
#include "HeadlessTestMain.h"
#include "HeadlessRenderer.h"
#include "RayTracer.h"
#include "SceneLibrary.h"
#include "SettingsKeys.h"
#include "ShadowReference.h"

#include <QtTest>

using namespace shadowlab;

namespace {

const QSize kSize(320, 180);
// A march as long as the gap a bias of 0.8 world units opens under a resting cube.
const QStringList kContact{"contact.enabled=true", "contact.length=1", "contact.steps=16", "contact.thickness=2"};

Settings with(const QString& scene, const QStringList& assignments)
{
    Settings s = presetSettings(scene);
    for (const QString& a : assignments)
        applyAssignment(s, a);
    return s;
}

// Receiver pixels facing the light that disagree with the hard reference; of the false light,
// that within reach of the march: where the occluder lies within contact.length of the
// receiver, toward the light.
struct Agreement {
    int counted = 0;
    int falseShadow = 0;
    int falseLight = 0;
    int falseLightNearContact = 0;
    QString text() const
    {
        return QString("%1 counted, %2 false shadow, %3 false light (%4 near contacts)").arg(counted).arg(falseShadow).arg(falseLight).arg(falseLightNearContact);
    }
};

struct Reference {
    std::vector<float> hard;
    std::vector<char> nearContact;      // an occluder within the march's length
};

Reference reference(Renderer& renderer, const VisibilityBuffer& buffer, double length)
{
    const RayTracer tracer(*renderer.scene(), buffer.cameraPosition);
    ReferenceOptions options;
    options.area = false;
    const LightFrame& light = renderer.lightFrame();
    Reference r{traceReference(tracer, buffer, light, options).hard, std::vector<char>(std::size_t(buffer.pixelCount()), 0)};
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        if (buffer.mask(i) != VisibilityBuffer::FacingLight || r.hard[std::size_t(i)] >= 0.5f)
            continue;
        const glm::dvec3 p = buffer.worldPosition(i);
        const glm::dvec3 from = shadowRayStart(tracer, p, buffer.normal(i));
        const glm::dvec3 toLight = light.perspective ? glm::normalize(light.position - from) : -light.direction;
        r.nearContact[std::size_t(i)] = tracer.occluded(from, toLight, length);
    }
    return r;
}

Agreement agreement(const VisibilityBuffer& buffer, const Reference& reference)
{
    Agreement a;
    for (int i = 0; i < buffer.pixelCount(); ++i) {
        if (buffer.mask(i) != VisibilityBuffer::FacingLight)
            continue;
        ++a.counted;
        const bool lit = buffer.visibility(i) >= 0.5f, referenceLit = reference.hard[std::size_t(i)] >= 0.5f;
        a.falseShadow += !lit && referenceLit;
        a.falseLight += lit && !referenceLit;
        a.falseLightNearContact += lit && !referenceLit && reference.nearContact[std::size_t(i)];
    }
    return a;
}

// `factor` times the default bias in world units, no front-face culling: shadows detach from
// the casters resting on the ground (the peter-panning preset is 80 and 400 times).
QStringList largeBias(double factor)
{
    const Settings defaults;
    return {QString("bias.slope=%1").arg(factor * defaults.bias.slope), QString("bias.min=%1").arg(factor * defaults.bias.min),
            "bias.cull_front=false", "filter.mode=hard"};
}

} // namespace

class TestContactShadows : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private Q_SLOTS:
    void initTestCase() { m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase() { m_headless.reset(); }

    void givesBackTheShadowABiasLifts_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("more");
        for (const double factor : {80.0, 400.0}) {
            for (const char* scene : {"seed", "cubes", "occluder", "torus"})
                QTest::newRow(qPrintable(QString("%1, bias x%2").arg(scene).arg(factor))) << QString(scene) << largeBias(factor);
        }
        QTest::newRow("seed, light low") << "seed" << largeBias(400) + QStringList{"light.position=-6,1.5,-2"};
        QTest::newRow("seed, light above") << "seed" << largeBias(400) + QStringList{"light.position=0.3,6,0.2"};
        QTest::newRow("seed, spot light") << "seed" << largeBias(400) + QStringList{"light.type=spot"};
        QTest::newRow("cubes, camera close") << "cubes" << largeBias(400) + QStringList{"camera.position=2,1,3"};
    }

    void givesBackTheShadowABiasLifts()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, more);
        Renderer& r = m_headless->renderer();
        const VisibilityBuffer without = r.renderVisibility(with(scene, more), kSize);
        const Reference truth = reference(r, without, 1.0);
        const VisibilityBuffer withContact = r.renderVisibility(with(scene, more + kContact), kSize);
        const Agreement before = agreement(without, truth), after = agreement(withContact, truth);
        qInfo().noquote() << "without:" << before.text() << "| with contact shadows:" << after.text();
        QVERIFY2(before.counted > 500, qPrintable(before.text()));
        // The bias leaves false light at the contacts, and the march removes most of what lies
        // within its length (farther it cannot see), adding none elsewhere...
        if (before.falseLightNearContact >= 50)
            QVERIFY2(after.falseLightNearContact <= 0.6 * before.falseLightNearContact, qPrintable(after.text()));
        QVERIFY2(after.falseLightNearContact <= before.falseLightNearContact, qPrintable(after.text()));
        QVERIFY2(after.falseLight <= before.falseLight, qPrintable(after.text()));
        // ... without shadowing much of what the reference says is lit.
        QVERIFY2(after.falseShadow <= before.falseShadow + 0.002 * after.counted, qPrintable(after.text()));
    }

    // The smaller of the map's visibility and the march's: never lighter than the map alone,
    // and never a value outside [0, 1].
    void onlyEverDarkens_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::addColumn<bool>("darkens");
        QTest::newRow("hw-bilinear, long march") << QStringList{"contact.length=1"} << true;
        QTest::newRow("pcss, long march") << QStringList{"filter.mode=pcss", "contact.length=2", "contact.steps=32"} << true;
        QTest::newRow("vsm, thick") << QStringList{"filter.mode=vsm", "contact.thickness=5"} << true;
        QTest::newRow("point light") << QStringList{"light.type=point", "contact.length=1"} << true;
        QTest::newRow("one short step") << QStringList{"contact.steps=1", "contact.length=0.05"} << false;
    }

    void onlyEverDarkens()
    {
        QFETCH(QStringList, assignments);
        QFETCH(bool, darkens);
        Renderer& r = m_headless->renderer();
        const VisibilityBuffer map = r.renderVisibility(with("cubes", assignments), kSize);
        const VisibilityBuffer both = r.renderVisibility(with("cubes", assignments + QStringList{"contact.enabled=true"}), kSize);
        int darker = 0;
        for (int i = 0; i < map.pixelCount(); ++i) {
            const float v = both.visibility(i);
            QVERIFY2(std::isfinite(v) && v >= 0.0f && v <= 1.0f, qPrintable(QString("pixel %1: %2").arg(i).arg(v)));
            QVERIFY2(v <= map.visibility(i) + 1e-6f, qPrintable(QString("pixel %1: %2 with, %3 without").arg(i).arg(v).arg(map.visibility(i))));
            darker += v < map.visibility(i);
        }
        if (darkens)
            QVERIFY(darker > 0);
    }

    // Shadows off: no march either, and no camera depth.
    void offWithTheShadows()
    {
        Renderer& r = m_headless->renderer();
        const VisibilityBuffer plain = r.renderVisibility(with("seed", {"shadow.enabled=false"}), kSize);
        const VisibilityBuffer contact = r.renderVisibility(with("seed", {"shadow.enabled=false", "contact.enabled=true"}), kSize);
        QCOMPARE(r.lastFrame().contactDepthDraws, 0);
        for (int i = 0; i < plain.pixelCount(); ++i)
            QCOMPARE(contact.visibility(i), plain.visibility(i));
    }

    // The camera's depth is drawn again only when the camera, the scene or the size changed.
    void aStillFrameKeepsTheCameraDepth()
    {
        Renderer& r = m_headless->renderer();
        const Settings s = with("cubes", {"contact.enabled=true"});
        m_headless->renderScene(s, kSize);
        m_headless->renderScene(s, kSize);
        QCOMPARE(r.lastFrame().contactDepthDraws, 0);
        Settings moved = s;
        moved.camera.position.x += 0.5;
        m_headless->renderScene(moved, kSize);
        QVERIFY(r.lastFrame().contactDepthDraws > 0);
        m_headless->renderScene(moved, QSize(200, 100));
        QVERIFY(r.lastFrame().contactDepthDraws > 0);
        // The light alone moving changes nothing the camera sees.
        Settings lit = moved;
        lit.light.position.x += 0.5;
        m_headless->renderScene(lit, QSize(200, 100));
        QCOMPARE(r.lastFrame().contactDepthDraws, 0);
    }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;
};

SHADOWLAB_TEST_MAIN(TestContactShadows)
#include "tst_ContactShadows.moc"
