// The artifact presets show what they promise: against the Embree reference at the rendered
// pixels, each preset makes its artifact well above what its scene's defaults show, from
// several light directions, and the fix its sentence names takes it away again.
#include "Application.h"
#include "ArtifactPresets.h"
#include "ArtifactsPage.h"
#include "HeadlessRenderer.h"
#include "HeadlessTestMain.h"
#include "ReferenceAgreement.h"
#include "SceneLibrary.h"
#include "SettingsError.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QtTest>

#include <memory>

using namespace shadowlab;

namespace {

const QSize kSize(320, 180);

// Which misclassified pixels make each artifact.
enum class Kind { FalseShadow, FalseLight, Both };

const std::map<QString, Kind> kArtifactKind{
    {QStringLiteral("acne"), Kind::FalseShadow},
    {QStringLiteral("peter-panning"), Kind::FalseLight},
    {QStringLiteral("light-leak"), Kind::FalseLight},
    {QStringLiteral("blocky-aliasing"), Kind::Both},
    {QStringLiteral("depth-precision"), Kind::FalseShadow},
    {QStringLiteral("volume-clipping"), Kind::FalseLight},
};

// False shadow as a share of the pixels the reference lights; false light, and both kinds at
// blocky edges, as a share of the pixels it shadows: a leak at a contact is a small part of
// the screen but a large part of the shadow it eats into.
double share(const probe::Agreement& a, Kind kind)
{
    const int lit = a.counted - a.referenceShadowed;
    switch (kind) {
    case Kind::FalseShadow:
        return lit > 0 ? double(a.falseShadow) / lit : 0.0;
    case Kind::FalseLight:
        return a.referenceShadowed > 0 ? double(a.falseLight) / a.referenceShadowed : 0.0;
    case Kind::Both:
        return a.referenceShadowed > 0 ? double(a.falseShadow + a.falseLight) / a.referenceShadowed : 0.0;
    }
    return 0.0;
}

// The light turned `degrees` about the vertical through its target.
Settings turned(Settings s, double degrees)
{
    const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0.0, 1.0, 0.0));
    s.light.position = s.light.target + glm::dvec3(turn * glm::dvec4(s.light.position - s.light.target, 0.0));
    return s;
}

} // namespace

class tst_ArtifactPresets : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private:
    std::unique_ptr<HeadlessRenderer> m_headless;

    probe::Agreement measure(const Settings& settings)
    {
        return probe::agreement(m_headless->renderer(), settings, kSize);
    }

private slots:
    void initTestCase() { m_headless = std::make_unique<HeadlessRenderer>(); }
    void cleanupTestCase() { m_headless.reset(); }

    void everyPresetIsShippedComplete()
    {
        QStringList tested;
        for (const auto& [name, kind] : kArtifactKind)
            tested << name;
        QStringList shipped = artifactPresetNames();
        shipped.sort();
        tested.sort();
        QCOMPARE(shipped, tested);  // a new preset needs a row here, and so a test of its artifact
        for (const ArtifactPreset& p : artifactPresets()) {
            QVERIFY2(!p.title.isEmpty() && p.lookFor.size() > 40 && p.fix.size() > 40, qPrintable(p.name));
            // Both the preset and its fix are valid settings.
            ensureValid(artifactPresetSettings(p));
            ensureValid(artifactPresetFixed(p));
            QVERIFY2(artifactPresetSettings(p) != artifactPresetFixed(p), qPrintable(p.name + ": the fix changes nothing"));
        }
    }

    void unknownPresetIsRefusedWithTheNames()
    {
        try {
            artifactPreset(QStringLiteral("acme"));
            QFAIL("an unknown preset was accepted");
        } catch (const SettingsError& e) {
            const QString message = QString::fromUtf8(e.what());
            for (const QString& name : artifactPresetNames())
                QVERIFY2(message.contains(name), qPrintable(message));
        }
        QCOMPARE(artifactPreset(QStringLiteral(" Acne ")).name, QStringLiteral("acne"));
    }

    void presetShowsItsArtifactAndTheFixRemovesIt_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("turn");
        for (const ArtifactPreset& p : artifactPresets()) {
            for (double turn : {-60.0, -30.0, 0.0})
                QTest::addRow("%s, light turned %g°", qPrintable(p.name), turn) << p.name << turn;
        }
    }

    void presetShowsItsArtifactAndTheFixRemovesIt()
    {
        QFETCH(QString, name);
        QFETCH(double, turn);
        const ArtifactPreset& preset = artifactPreset(name);
        const Kind kind = kArtifactKind.at(name);
        const Settings shown = turned(artifactPresetSettings(preset), turn);
        const Settings fixed = turned(artifactPresetFixed(preset), turn);
        const Settings defaults = turned(presetSettings(shown.scene), turn);

        const probe::Agreement presetAgreement = measure(shown);
        QVERIFY2(presetAgreement.counted >= kSize.width() * kSize.height() / 10, "the view shows too few receivers to judge");
        QVERIFY2(presetAgreement.referenceShadowed >= presetAgreement.counted / 100, "the view shows too little shadow to judge");
        const double withPreset = share(presetAgreement, kind);
        const double withDefaults = share(measure(defaults), kind);
        const double withFix = share(measure(fixed), kind);
        const QString numbers = QStringLiteral("%1: %2 % wrong with the preset, %3 % with the scene's defaults, %4 % with the fix")
                                    .arg(name)
                                    .arg(100.0 * withPreset, 0, 'f', 3)
                                    .arg(100.0 * withDefaults, 0, 'f', 3)
                                    .arg(100.0 * withFix, 0, 'f', 3);
        qInfo("%s", qPrintable(numbers));
        // Visible: at least 1 % of the lit (or shadowed) receivers, and five times the defaults.
        QVERIFY2(withPreset >= 0.01 && withPreset >= 5.0 * withDefaults, qPrintable(numbers));
        // Fixed: within a percentage point of the defaults, and a fifth of the preset or less.
        QVERIFY2(withFix <= withDefaults + 0.01 && withFix <= withPreset / 5.0, qPrintable(numbers));
    }

    // Help → Shadow Artifacts shows each artifact and its fix as the program renders them.
    void helpShowsEachArtifactAndItsFix()
    {
        const std::map<QString, QImage>& pictures = artifactPictures();
        QCOMPARE(pictures.size(), artifactPresets().size() * 2);
        const QString page = artifactsPageHtml(true);
        for (const ArtifactPreset& preset : artifactPresets()) {
            const QImage& artifact = pictures.at(preset.name);
            const QImage& fixed = pictures.at(preset.name + QStringLiteral("-fixed"));
            QCOMPARE(artifact.size(), QSize(kArtifactPictureWidth, kArtifactPictureHeight));
            // The fix shows: the two pictures differ somewhere visibly.
            int differing = 0;
            for (int y = 0; y < artifact.height(); ++y) {
                for (int x = 0; x < artifact.width(); ++x)
                    differing += qGray(artifact.pixel(x, y)) != qGray(fixed.pixel(x, y)) ? 1 : 0;
            }
            QVERIFY2(differing > 10, qPrintable(QStringLiteral("%1: %2 pixels differ").arg(preset.name).arg(differing)));
            QVERIFY(page.contains(QStringLiteral("artifact:%1-fixed").arg(preset.name)));
        }
        QVERIFY(!artifactsPageHtml(false).contains(QStringLiteral("<img")));
    }
};

SHADOWLAB_TEST_MAIN(tst_ArtifactPresets)

#include "tst_ArtifactPresets.moc"
