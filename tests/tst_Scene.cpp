// Meshes and presets without GL: closed meshes wind outward, normals agree with the winding,
// and the presets put things where the tutorial scene has them.
#include "ProceduralTexture.h"
#include "SceneLibrary.h"

#include <glm/glm.hpp>

#include <QtTest>

using namespace shadowlab;

Q_DECLARE_METATYPE(shadowlab::Mesh)

class TestScene : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void meshesWindOutward_data()
    {
        QTest::addColumn<Mesh>("mesh");
        QTest::newRow("plane") << meshes::plane(2.0f, 1.0f);
        QTest::newRow("cube") << meshes::cube();
        QTest::newRow("sphere") << meshes::sphere(24, 12);
        QTest::newRow("torus") << meshes::torus(1.0f, 0.3f, 32, 16);
        QTest::newRow("pyramid") << meshes::pyramid();
    }

    void meshesWindOutward()
    {
        QFETCH(Mesh, mesh);
        QVERIFY(!mesh.indices.empty());
        QCOMPARE(mesh.indices.size() % 3, std::size_t(0));
        for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
            const Vertex& a = mesh.vertices.at(mesh.indices[i]);
            const Vertex& b = mesh.vertices.at(mesh.indices[i + 1]);
            const Vertex& c = mesh.vertices.at(mesh.indices[i + 2]);
            const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
            if (glm::length(face) < 1e-7f)
                continue; // pole slivers of the sphere
            const glm::vec3 average = a.normal + b.normal + c.normal;
            QVERIFY2(glm::dot(face, average) > 0.0f, qPrintable(QString("triangle %1 winds against its normals").arg(i / 3)));
            QCOMPARE_LT(std::abs(glm::length(a.normal) - 1.0f), 1e-4f);
        }
    }

    void seedSceneMatchesTheTutorial()
    {
        const Scene s = buildScene("seed");
        QCOMPARE(s.objects.size(), std::size_t(4));
        const Bounds ground = s.worldBounds(s.objects[0]);
        QCOMPARE(ground.min.y, -0.5);
        QCOMPARE(ground.max.x - ground.min.x, 50.0);
        const Bounds high = s.worldBounds(s.objects[1]);
        QVERIFY(high.center() == glm::dvec3(0.0, 1.5, 0.0));
        QCOMPARE(high.max.x - high.min.x, 1.0);
        const Bounds resting = s.worldBounds(s.objects[2]);
        QCOMPARE(resting.min.y, -0.5); // rests on the plane
        QVERIFY(glm::length(s.worldBounds(s.objects[3]).center() - glm::dvec3(-1.0, 0.0, 2.0)) < 1e-12);
        QVERIFY(!s.casterBounds().isEmpty());
    }

    void everyPresetBuilds()
    {
        for (const QString& name : sceneNames()) {
            const Scene s = buildScene(name);
            QCOMPARE(s.name, name);
            QVERIFY(s.objects.size() >= 2);
            QVERIFY(!s.bounds().isEmpty());
        }
        QCOMPARE(buildScene("cubes").objects.size(), std::size_t(11));
    }

    void texturesAreGeneratedNotFlat()
    {
        for (TextureKind kind : {TextureKind::Checker, TextureKind::Wood}) {
            const QImage image = makeProceduralTexture(kind, 64);
            QCOMPARE(image.size(), QSize(64, 64));
            QSet<QRgb> colours;
            for (int y = 0; y < 64; y += 4)
                for (int x = 0; x < 64; x += 4)
                    colours.insert(image.pixel(x, y));
            QVERIFY(colours.size() > 1);
        }
    }
};

QTEST_APPLESS_MAIN(TestScene)
#include "tst_Scene.moc"
