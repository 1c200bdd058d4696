// Every technique on the models people open, under every light type: the real models of
// Debian's assimp-testmodels, picked from the package here (every file that imports with a
// model's triangle count, one of each model however many formats hold it), each under one light
// type in turn, at each technique's defaults, from the model's own camera and from one across
// the light that frames the model's self-shadowing (its terminator), at 320 x 180 against the
// ray-traced reference. The bounds, as a user sees them:
//   - no visible moiré or acne: DSSIM of the frame at most 0.01 against the frame shaded with
//     the hard reference (a moiré of partial shadow stays under a misclassified count; only the
//     picture shows it), for every hard-edged depth-compare filter;
//   - misclassified pixels at most 0.10 % (the goal) on three models in four, for every
//     technique and camera, and for the hard-edged depth-compare filters on every model but the
//     worst one (the flat-shaded STL spider, whose legs' creases shadow each other closer than
//     a texel: 0.13-0.46 %, docs/techniques.md#bias);
//   - on every model, at most 0.5 % for those filters, and 2 % for pcss and dpcf (against the
//     area reference, whose soft edges the hard one calls wrong) and the moment filters from
//     the model's camera. These hold what is reached and catch any step back; every figure is
//     printed.
#include "AccuracyMeter.h"
#include "Application.h"
#include "HeadlessRenderer.h"
#include "Measurement.h"
#include "SceneFileError.h"
#include "SceneLibrary.h"
#include "SettingsError.h"
#include "SettingsKeys.h"
#include "ShadowTechnique.h"
#include "TestFiles.h"

#include <glm/geometric.hpp>

#include <QDirIterator>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>

using namespace shadowlab;

namespace {

constexpr double kGoalMisclassified = 0.001;
constexpr double kMaxMisclassified = 0.005;
constexpr double kMaxMisclassifiedOpen = 0.02;
constexpr double kMaxDssim = 0.01;
// Below this a file is one of the package's test shapes (cubes, a triangle), not a model.
constexpr std::size_t kModelTriangles = 700;
const QSize kSize(320, 180);

struct RealModel {
    QString path;
    QString name;           // the file's base name
};

std::size_t triangles(const Scene& scene)
{
    std::size_t count = 0;
    for (const SceneObject& o : scene.objects) {
        if (o.name != u"ground")
            count += scene.meshes.at(std::size_t(o.mesh)).indices.size() / 3;
    }
    return count;
}

// Every model file of the package that imports, with a model's triangle count; of files with
// the same triangle count and proportions (one model in several formats), the first.
std::vector<RealModel> pickModels()
{
    std::vector<RealModel> picked;
    std::vector<std::pair<std::size_t, double>> seen;
    QStringList files;
    for (QDirIterator it(kTestModels, {"*.glb", "*.gltf", "*.obj", "*.ply", "*.stl", "*.dae", "*.3ds", "*.x", "*.fbx"}, QDir::Files,
                         QDirIterator::Subdirectories);
         it.hasNext();)
        files << it.next();
    files.sort();
    for (const QString& file : files) {
        Scene scene;
        try {
            scene = buildScene(file);
        } catch (const SettingsError&) {
            continue;       // a damaged file: tst_ModelImport holds its refusal to account
        }
        const std::size_t count = triangles(scene);
        const Bounds b = scene.modelBounds();
        const glm::dvec3 size = b.max - b.min;
        if (count < kModelTriangles || !(glm::length(size) > 0.0))
            continue;
        const double shape = size.y / glm::length(size);
        const bool again = std::any_of(seen.begin(), seen.end(), [&](const auto& s) {
            return std::abs(double(s.first) - double(count)) <= 0.15 * double(count) && std::abs(s.second - shape) < 0.01;
        });
        if (again)
            continue;
        seen.emplace_back(count, shape);
        picked.push_back({file, QFileInfo(file).completeBaseName()});
    }
    return picked;
}

// A camera across the light: from the side, where half the model is lit and its terminator and
// its own shadows fill the view.
CameraSettings acrossTheLight(const Settings& s, const Bounds& model)
{
    const glm::dvec3 centre = model.center();
    const double radius = glm::length(model.max - model.min) * 0.5;
    glm::dvec3 toLight = glm::normalize(s.light.position - centre);
    glm::dvec3 side = glm::cross(glm::dvec3(0.0, 1.0, 0.0), toLight);
    if (glm::length(side) < 1e-6)
        side = glm::dvec3(1.0, 0.0, 0.0);
    CameraSettings camera = s.camera;
    camera.target = centre;
    camera.position = centre + glm::normalize(glm::normalize(side) + glm::dvec3(0.0, 0.3, 0.0)) * radius * 2.6;
    return camera;
}

// Whether a technique's penumbra follows the light's size.
bool followsLightSize(FilterMode mode)
{
    return mode == FilterMode::Pcss || mode == FilterMode::Dpcf;
}

// The techniques not yet within the bounds on rough models.
bool stillOpen(const ShadowTechnique& t)
{
    return t.mode == FilterMode::Dpcf || t.mode == FilterMode::Pcss || t.map == ShadowMapKind::Moments;
}

} // namespace

class TestRealModels : public QObject {
    Q_OBJECT

public:
    static void initMain() { configureApplication(); }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY2(QDir(kTestModels).exists(), "assimp-testmodels is not installed; run scripts/setup.sh");
        m_models = pickModels();
        QStringList names;
        for (const RealModel& m : m_models)
            names << m.name;
        qInfo("%d real models: %s", int(m_models.size()), qPrintable(names.join(", ")));
        // The package holds the engine, the spider, the duck, Wuson, the truck, the rock...
        QVERIFY2(m_models.size() >= 6, qPrintable(names.join(", ")));
    }

    void everyTechniqueIsCleanOnEveryModel_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("light");
        const QStringList lights{QStringLiteral("directional"), QStringLiteral("spot"), QStringLiteral("point")};
        for (std::size_t i = 0; i < m_models.size(); ++i) {
            const QString& light = lights[int(i % 3)];
            QTest::newRow(qPrintable(m_models[i].name + "/" + light)) << m_models[i].path << light;
        }
    }

    void everyTechniqueIsCleanOnEveryModel()
    {
        QFETCH(QString, path);
        QFETCH(QString, light);
        Settings base = presetSettings(path);
        applyAssignment(base, "light.type=" + light);
        const Bounds model = buildScene(path).modelBounds();
        HeadlessRenderer headless;
        QStringList failures;
        int measured = 0;
        for (const auto& [close, camera] : {std::pair{false, base.camera}, std::pair{true, acrossTheLight(base, model)}}) {
            const QString cameraName = close ? QStringLiteral("across the light") : QStringLiteral("model's camera");
            // One trace per camera for every technique: hard, and the area light for the soft ones.
            AccuracyMeter hard(ReferenceOptions{false, 0.0, 1});
            AccuracyMeter area(ReferenceOptions{true, base.reference.lightRadius, 4});
            for (const ShadowTechnique& t : shadowTechniques()) {
                const bool open = stillOpen(t);
                if (open && close)
                    continue;
                Settings s = base;
                s.camera = camera;
                s.filter.mode = t.mode;
                const bool soft = followsLightSize(t.mode);
                const AccuracyResult r = measureAccuracy(soft ? area : hard, headless.renderer(), s, kSize);
                const ErrorMetrics& m = soft ? r.area : r.hard;
                const double dssim = 1.0 - r.ssim;
                ++measured;
                QVERIFY(m.pixels > 0);
                const double bound = open ? kMaxMisclassifiedOpen : kMaxMisclassified;
                qInfo("%s, %s: %.3f %% misclassified, DSSIM %.4f", qPrintable(t.key), qPrintable(cameraName), 100 * m.misclassified, dssim);
                m_misclassified[{t.key, cameraName}].push_back(m.misclassified);
                if (m.misclassified > bound || (!soft && !open && dssim > kMaxDssim))
                    failures << QString("%1, %2: %3 % misclassified (%4 acne, %5 leaks), DSSIM %6")
                                    .arg(t.key, cameraName)
                                    .arg(100 * m.misclassified, 0, 'f', 3)
                                    .arg(100 * m.falseShadow, 0, 'f', 3)
                                    .arg(100 * m.falseLight, 0, 'f', 3)
                                    .arg(dssim, 0, 'f', 4);
            }
        }
        ++m_modelsMeasured;
        QVERIFY2(failures.isEmpty(), qPrintable(QString("%1 of %2 over the bounds:\n  ").arg(failures.size()).arg(measured) + failures.join("\n  ")));
    }

    // The goal on the typical model: the upper quartile of each technique's misclassified share
    // over every model within 0.10 %, and for the hard-edged filters every model's but the worst.
    void theTypicalModelMeetsTheGoal()
    {
        QVERIFY2(m_modelsMeasured == m_models.size(), "the goal is over every model: run everyTechniqueIsCleanOnEveryModel whole first");
        QStringList failures;
        for (auto& [row, shares] : m_misclassified) {
            std::sort(shares.begin(), shares.end());
            const double median = shares[shares.size() / 2];
            const double upperQuartile = shares[(3 * shares.size()) / 4];
            const double secondWorst = shares[shares.size() - 2];
            const bool hardEdged = std::any_of(shadowTechniques().begin(), shadowTechniques().end(),
                                               [&](const ShadowTechnique& t) { return t.key == row.first && !stillOpen(t); });
            qInfo("%s, %s: median %.3f %%, upper quartile %.3f %%, all but the worst model %.3f %% misclassified over %d models", qPrintable(row.first),
                  qPrintable(row.second), 100 * median, 100 * upperQuartile, 100 * secondWorst, int(shares.size()));
            if (upperQuartile > kGoalMisclassified || (hardEdged && secondWorst > kGoalMisclassified))
                failures << QString("%1, %2: median %3 %, upper quartile %4 %, all but the worst model %5 %")
                                .arg(row.first, row.second)
                                .arg(100 * median, 0, 'f', 3)
                                .arg(100 * upperQuartile, 0, 'f', 3)
                                .arg(100 * secondWorst, 0, 'f', 3);
        }
        QVERIFY(!m_misclassified.empty());
        QVERIFY2(failures.isEmpty(), qPrintable("over the goal of 0.10 %:\n  " + failures.join("\n  ")));
    }

private:
    std::vector<RealModel> m_models;
    std::size_t m_modelsMeasured = 0;
    std::map<std::pair<QString, QString>, std::vector<double>> m_misclassified;     // (technique, camera): per model
};

QTEST_MAIN(TestRealModels)
#include "tst_RealModels.moc"
