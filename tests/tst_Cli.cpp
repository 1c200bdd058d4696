// The command line as a user meets it: the real binary, its files, its exit codes and messages.
#include "ErrorPixels.h"

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

namespace {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

Run shadowlab(const QStringList& arguments, const QString& workingDirectory = {})
{
    QProcess process;
    process.setWorkingDirectory(workingDirectory);
    process.start(QStringLiteral(SHADOWLAB_BINARY), arguments);
    if (!process.waitForFinished(300000))
        return {};
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1, QString::fromUtf8(process.readAllStandardOutput()),
            QString::fromUtf8(process.readAllStandardError())};
}

// One line of a CSV file as its cells, quoted ones ("a, b" and "say ""x""") read as one.
QStringList csvCells(const QString& line)
{
    QStringList cells{QString()};
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
            cells.last() += line[++i];
        else if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            cells << QString();
        else
            cells.last() += c;
    }
    return cells;
}

QJsonObject readJson(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(file.readAll()).object() : QJsonObject();
}

bool writeFile(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

} // namespace

class TestCli : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private Q_SLOTS:
    void presetOptionStartsFromAnArtifactPreset()
    {
        const Run unknown = shadowlab({"render", "--preset", "acme", "--size", "64x64", "--out", m_dir.filePath("p.png")});
        QCOMPARE(unknown.exitCode, 2);
        for (const char* name : {"acne", "peter-panning", "light-leak", "blocky-aliasing", "depth-precision", "volume-clipping"})
            QVERIFY2(unknown.err.contains(name), qPrintable(unknown.err));
        QVERIFY(!QFile::exists(m_dir.filePath("p.png")));
        // The preset's scene and keys, with --set on top; the depth-precision preset warns as
        // its settings would.
        const Run precision = shadowlab({"render", "--preset", "depth-precision", "--size", "64x64", "--out", m_dir.filePath("p.png")});
        QVERIFY2(precision.exitCode == 0, qPrintable(precision.err));
        QVERIFY2(precision.err.contains("far/near"), qPrintable(precision.err));
        const Run fixed = shadowlab({"render", "--preset", "depth-precision", "--set", "light.near=1", "--size", "64x64", "--out",
                                     m_dir.filePath("p.png")});
        QVERIFY2(fixed.exitCode == 0 && !fixed.err.contains("far/near"), qPrintable(fixed.err));
        for (const char* command : {"bench", "report", "tune", "screenshot"}) {
            const Run help = shadowlab({command, "--help"});
            QVERIFY2(help.out.contains("--preset"), command);
        }
    }

    void renderWritesTheSceneAndTheDepthMap()
    {
        const QString scene = m_dir.filePath("scene.png");
        const QString depth = m_dir.filePath("depth.png");
        const Run r = shadowlab({"render", "--scene", "torus", "--size", "320x200", "--out", scene, "--depth-out", depth,
                                 "--set", "map.size=512"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.contains("scene.png"));
        const QImage image(scene);
        QCOMPARE(image.size(), QSize(320, 200));
        // The depth picture: the map in a square as wide as the map (at least 320, at most 1024
        // pixels), the 58-pixel legend under it.
        const QImage depthImage(depth);
        QCOMPARE(depthImage.size(), QSize(512, 512 + 58));
        // The legend's colour bar runs from dark (near the light) to pale (far).
        const int barRow = 512 + 22 + 6;
        QVERIFY(qGray(depthImage.pixel(12, barRow)) + 100 < qGray(depthImage.pixel(512 - 12, barRow)));
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 10)
            for (int x = 0; x < image.width(); x += 10)
                colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 20); // a scene, not a cleared buffer
    }

    void renderWithoutOutWritesADefaultNameAndNeverOverwrites()
    {
        QTemporaryDir here;
        const Run first = shadowlab({"render", "--scene", "torus", "--size", "64x48"}, here.path());
        QVERIFY2(first.exitCode == 0, qPrintable(first.err));
        QCOMPARE(QImage(here.filePath("shadowlab-torus.png")).size(), QSize(64, 48));
        QVERIFY2(first.out.contains(here.filePath("shadowlab-torus.png")), qPrintable(first.out)); // says where it went
        const QByteArray firstBytes = [&] { QFile f(here.filePath("shadowlab-torus.png")); f.open(QIODevice::ReadOnly); return f.readAll(); }();

        const Run second = shadowlab({"render", "--scene", "torus", "--size", "32x32"}, here.path());
        QVERIFY2(second.exitCode == 0, qPrintable(second.err));
        QCOMPARE(QImage(here.filePath("shadowlab-torus-2.png")).size(), QSize(32, 32));
        QVERIFY(second.out.contains("shadowlab-torus-2.png"));
        QFile kept(here.filePath("shadowlab-torus.png"));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), firstBytes);   // the first picture is untouched

        // Only a depth map asked for: no scene picture appears.
        const Run depth = shadowlab({"render", "--size", "32x32", "--depth-out", here.filePath("d.png")}, here.path());
        QVERIFY2(depth.exitCode == 0, qPrintable(depth.err));
        QVERIFY(!QFile::exists(here.filePath("shadowlab-seed.png")));

        // Played up to its time, a cached map says what it kept and why.
        const Run played = shadowlab({"render", "--scene", "swing", "--size", "64x36", "--set", "shadow.cache=static", "--set", "scene.time=1",
                                      "--play", "2", "--out", here.filePath("p.png")},
                                     here.path());
        QVERIFY2(played.exitCode == 0, qPrintable(played.err));
        QVERIFY2(played.out.contains("cache: ") && played.out.contains("caster moved"), qPrintable(played.out));

        // A name safe in any shell or file system: no colon from city:N.
        const Run city = shadowlab({"render", "--scene", "city:20", "--size", "32x18"}, here.path());
        QVERIFY2(city.exitCode == 0, qPrintable(city.err));
        QVERIFY2(QFile::exists(here.filePath("shadowlab-city-20.png")), qPrintable(city.out));
    }

    void helpAndVersionGoToStdoutAndSucceed_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("expected");
        QTest::newRow("--help") << QStringList{"--help"} << "usage: shadowlab";
        QTest::newRow("-h") << QStringList{"-h"} << "usage: shadowlab";
        QTest::newRow("help") << QStringList{"help"} << "usage: shadowlab";
        QTest::newRow("--version") << QStringList{"--version"} << "shadowlab " SHADOWLAB_VERSION;
        QTest::newRow("-v") << QStringList{"-v"} << "shadowlab " SHADOWLAB_VERSION;
        QTest::newRow("--version names the licence") << QStringList{"--version"} << "Licence: MIT";
        for (const char* command : {"render", "bench", "report", "settings", "audit", "tune", "screenshot"}) {
            const QString name = QString::fromLatin1(command);
            QTest::addRow("%s --help", command) << QStringList{name, "--help"} << "Usage: shadowlab " + name + " [options]";
            QTest::addRow("help %s", command) << QStringList{"help", name} << "Usage: shadowlab " + name + " [options]";
            QTest::addRow("%s --help-all", command) << QStringList{name, "--help-all"} << "Usage: shadowlab " + name + " [options]";
            QTest::addRow("%s --version", command) << QStringList{name, "--version"} << "shadowlab " SHADOWLAB_VERSION;
            QTest::addRow("%s --version names the licence", command) << QStringList{name, "--version"} << "Licence: MIT";
        }
    }

    void helpAndVersionGoToStdoutAndSucceed()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, expected);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(expected), qPrintable(r.out));
        QVERIFY2(r.err.isEmpty(), qPrintable(r.err));
        QVERIFY2(!r.out.contains(SHADOWLAB_BINARY), qPrintable(r.out)); // the command, not the binary's path
    }

    void mistypesGetASuggestion_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("suggestion");
        const QString out = m_dir.filePath("never.png");
        QTest::newRow("command") << QStringList{"rendr"} << "'rendr' is not a command; did you mean 'render'?";
        // Options after the word do not make it a model file to open, nor options of the window.
        QTest::newRow("command with options") << QStringList{"rendr", "--scene", "seed"} << "'rendr' is not a command; did you mean 'render'?";
        QTest::newRow("command with its own options") << QStringList{"benchh", "--frames", "10"} << "'benchh' is not a command; did you mean 'bench'?";
        QTest::newRow("command asking for help") << QStringList{"rendr", "--help"} << "did you mean 'render'?";
        QTest::newRow("command swapped letters") << QStringList{"becnh"} << "did you mean 'bench'?";
        QTest::newRow("help of a mistyped command") << QStringList{"help", "reprot"} << "did you mean 'report'?";
        QTest::newRow("key") << QStringList{"render", "--out", out, "--set", "bias.sloep=0.1"} << "did you mean 'bias.slope'?";
        QTest::newRow("key without its group") << QStringList{"render", "--out", out, "--set", "kernel=5"} << "did you mean 'filter.kernel'?";
        QTest::newRow("key in bench") << QStringList{"bench", "--set", "map.szie=512"} << "did you mean 'map.size'?";
        QTest::newRow("choice") << QStringList{"render", "--out", out, "--set", "filter.mode=pfc"} << "did you mean 'pcf'?";
        QTest::newRow("scene") << QStringList{"render", "--out", out, "--scene", "tours"} << "did you mean 'torus'?";
        QTest::newRow("option") << QStringList{"render", "--dpeth-out", out} << "Did you mean --depth-out?";
    }

    void mistypesGetASuggestion()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, suggestion);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(suggestion), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
        QVERIFY(!QFile::exists(m_dir.filePath("never.png")));
    }

    // The explorer takes the commands' settings options: bad ones are refused before any window
    // (exit 2, the problem named); good ones get as far as the display, which this machine has not.
    void explorerTakesTheSettingsOptions_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("mentions");
        const QString models = "/usr/share/assimp/models/";
        QTest::newRow("unknown preset") << QStringList{"--preset", "acme"} << "'acme' is not an artifact preset";
        QTest::newRow("NaN") << QStringList{"--set", "bias.slope=nan"} << "bias.slope";
        QTest::newRow("mistyped key") << QStringList{"--set", "bias.sloep=0.1"} << "did you mean 'bias.slope'?";
        QTest::newRow("unknown option") << QStringList{"--frobnicate"} << "Unknown option 'frobnicate'";
        QTest::newRow("missing model") << QStringList{"/nonexistent/engine.glb"} << "engine.glb";
        QTest::newRow("empty model") << QStringList{models + "invalid/empty.obj"} << "empty.obj";
        QTest::newRow("file and --scene") << QStringList{models + "OBJ/box.obj", "--scene", "seed"} << "give one of them";
        QTest::newRow("two files") << QStringList{models + "OBJ/box.obj", models + "OBJ/box.obj"} << "unexpected argument";
        // With no display, the offscreen command that shows the same settings.
        QTest::newRow("preset, no display") << QStringList{"--preset", "acne"} << "shadowlab screenshot --preset acne --out window.png";
        QTest::newRow("scene, no display") << QStringList{"--scene", "seed"} << "no display";
        QTest::newRow("model alone, no display") << QStringList{models + "OBJ/box.obj"}
                                                 << "shadowlab screenshot --scene " + models + "OBJ/box.obj --out window.png";
        QTest::newRow("model, no display") << QStringList{models + "OBJ/box.obj", "--set", "map.size=1024"} << "no display";
    }

    void explorerTakesTheSettingsOptions()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, mentions);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(mentions), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }

    // A word that is a file in the working folder is that file, though it reads like a command.
    void aFileNamedLikeACommandIsOpened()
    {
        QFile box("/usr/share/assimp/models/OBJ/box.obj");
        QVERIFY(box.open(QIODevice::ReadOnly));
        QVERIFY(writeFile(m_dir.filePath("rendr"), box.readAll()));
        const Run r = shadowlab({"rendr", "--set", "map.size=1024"}, m_dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(!r.err.contains("not a command") && r.err.contains("rendr"), qPrintable(r.err));
    }

    // The window measured before its picture: B's acne painted over B's view only.
    void screenshotWithAccuracyShowsEachSidesErrors()
    {
        const QString out = m_dir.filePath("measured.png");
        const Run r = shadowlab({"screenshot", "--compare", "--accuracy", "--size", "1000x600", "--set-b", "bias.cull_front=false",
                                 "--set-b", "bias.footprint=false", "--set-b", "bias.skip_floors=false", "--set-b", "bias.slope=0", "--set-b", "bias.min=0", "--set-b", "filter.mode=hard", "--out", out});
        QCOMPARE(r.exitCode, 0);
        const QImage image(out);
        QVERIFY(!image.isNull());
        // Magenta (false shadow) per half of the scene area, left (A) and right (B) of its middle.
        const auto magenta = [&image](int x0, int x1) { return falseShadowPixels(image.copy(x0, 0, x1 - x0, image.height()), 2); };
        // The views share the left part of the window; the docks and the depth pane are on the right.
        const int a = magenta(0, image.width() / 5), b = magenta(image.width() / 4, image.width() * 9 / 20);
        QVERIFY2(b > 200 && b > 20 * (a + 1), qPrintable(QString("magenta pixels: A %1, B %2").arg(a).arg(b)));
    }

    void farOffMistakesGetNoSuggestion()
    {
        const Run r = shadowlab({"render", "--out", m_dir.filePath("never.png"), "--set", "colour=red"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("unknown setting") && !r.err.contains("did you mean"), qPrintable(r.err));
        QVERIFY2(r.err.contains("`shadowlab settings`"), qPrintable(r.err));     // where the keys are, in the command line's words
    }

    // A file stopped by an import limit may only be large: the message names the option that
    // raises it, with the value it had.
    void importLimitsNameTheirOption()
    {
        qputenv("SHADOWLAB_IMPORT_WORKER", SHADOWLAB_FAKE_WORKER);
        QTemporaryDir dir;
        QFile slow(dir.filePath("slow.ply"));
        QVERIFY(slow.open(QIODevice::WriteOnly) && slow.write("sleep\n") > 0);
        slow.close();
        const Run r = shadowlab({"render", "--scene", slow.fileName(), "--import-time-limit", "1", "--out", m_dir.filePath("never.png")});
        qunsetenv("SHADOWLAB_IMPORT_WORKER");
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("took longer than 1 s") && r.err.contains("(--import-time-limit SECONDS, now 1)"), qPrintable(r.err));
    }

    void renderLoadsAModel()
    {
        const QString model = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
        if (!QFile::exists(model))
            QSKIP("assimp-testmodels is not installed");
        const QString out = m_dir.filePath("model.png");
        const Run r = shadowlab({"render", "--scene", model, "--size", "160x100", "--out", out});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QImage(out).size(), QSize(160, 100));
    }

    void settingsFileAndSetCombine()
    {
        const QString file = m_dir.filePath("s.json");
        QVERIFY(writeFile(file, R"({"filter": {"mode": "hard"}, "map.size": 256})"));
        const Run r = shadowlab({"render", "--settings", file, "--set", "map.size=128", "--size", "64x64", "--out",
                                 m_dir.filePath("combined.png"), "--depth-out", m_dir.filePath("combined-depth.png")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QImage(m_dir.filePath("combined-depth.png")).text("map.size"), QStringLiteral("128")); // --set wins over the file
    }

    void badInputExitsWithTwoAndNamesTheProblem_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("mentions");
        const QString out = m_dir.filePath("never.png");
        QTest::newRow("nan") << QStringList{"render", "--out", out, "--set", "bias.slope=nan"} << "bias.slope";
        QTest::newRow("inf") << QStringList{"render", "--out", out, "--set", "light.far=inf"} << "light.far";
        QTest::newRow("near >= far") << QStringList{"render", "--out", out, "--set", "light.near=9"} << "light.far";
        QTest::newRow("light at target") << QStringList{"render", "--out", out, "--set", "light.position=0,0,0"} << "light.position";
        QTest::newRow("size 0x0") << QStringList{"render", "--out", out, "--size", "0x0"} << "--size";
        QTest::newRow("size garbage") << QStringList{"render", "--out", out, "--size", "big"} << "WIDTHxHEIGHT";
        QTest::newRow("map beyond range") << QStringList{"render", "--out", out, "--set", "map.size=100000"} << "map.size";
        QTest::newRow("even kernel") << QStringList{"render", "--out", out, "--set", "filter.kernel=2"} << "filter.kernel";
        QTest::newRow("unknown key") << QStringList{"render", "--out", out, "--set", "bias.sloppy=1"} << "bias.sloppy";
        QTest::newRow("no equals") << QStringList{"render", "--out", out, "--set", "bias.slope"} << "key=value";
        QTest::newRow("unknown scene") << QStringList{"render", "--out", out, "--scene", "sponza"} << "seed";
        QTest::newRow("missing file") << QStringList{"render", "--out", out, "--settings", "/nonexistent/s.json"} << "s.json";
        const QString models = "/usr/share/assimp/models/";
        QTest::newRow("missing model") << QStringList{"render", "--out", out, "--scene", "/nonexistent/engine.glb"} << "engine.glb";
        QTest::newRow("empty model") << QStringList{"render", "--out", out, "--scene", models + "invalid/empty.obj"} << "empty.obj";
        QTest::newRow("points only") << QStringList{"bench", "--scene", models + "PLY/points.ply"} << "no triangles";
        QTest::newRow("unsupported format") << QStringList{"report", "--out", m_dir.filePath("never"), "--scene", models + "invalid/readme.txt"}
                                            << "not a model format";
        QTest::newRow("model without its buffer") << QStringList{"settings", "--scene", models + "glTF2/MissingBin/BoxTextured.gltf"}
                                                  << "BoxTextured.gltf";
        QTest::newRow("unknown option") << QStringList{"render", "--frobnicate"} << "frobnicate";
        QTest::newRow("bench frames 0") << QStringList{"bench", "--frames", "0"} << "--frames";
        QTest::newRow("play negative") << QStringList{"render", "--out", out, "--play", "-3"} << "--play";
        QTest::newRow("pages without virtual") << QStringList{"render", "--out", out, "--set", "shadow.cache=pages"} << "shadow.virtual=true";
        QTest::newRow("unknown cache") << QStringList{"render", "--out", out, "--set", "shadow.cache=sometimes"} << "on-demand";
        QTest::newRow("unknown command") << QStringList{"paint"} << "usage";
    }

    void badInputExitsWithTwoAndNamesTheProblem()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, mentions);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(mentions), qPrintable(r.err));
        QVERIFY(!QFile::exists(m_dir.filePath("never.png")));
    }

    void malformedSettingsFileIsNamed()
    {
        const QString file = m_dir.filePath("broken.json");
        QVERIFY(writeFile(file, "{ \"bias.slope\": 0.1, "));
        const Run r = shadowlab({"render", "--out", m_dir.filePath("x.png"), "--settings", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("broken.json") && r.err.contains("not valid JSON"), qPrintable(r.err));
    }

    void riskyValuesWarnButRender()
    {
        const Run r = shadowlab({"render", "--size", "64x64", "--out", m_dir.filePath("risky.png"), "--set", "light.fit=manual",
                                 "--set", "light.projection=perspective", "--set", "light.near=0.00001", "--set", "light.far=100"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains("warning: light.near"), qPrintable(r.err));
    }

    void settingsListsEveryKeyAsJson()
    {
        const Run r = shadowlab({"settings", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray keys = QJsonDocument::fromJson(r.out.toUtf8()).array();
        QVERIFY(keys.size() >= 22);
        bool sawSlope = false;
        for (const QJsonValue& k : keys) {
            const QJsonObject o = k.toObject();
            // Every default is shown; a list of objects switched off is empty by default: none.
            QVERIFY(!o.value("default").toString().isEmpty() || o.value("type").toString() == "objects");
            QVERIFY(!o.value("range").toString().isEmpty());
            if (o.value("key").toString() == "bias.slope")
                sawSlope = true;
        }
        QVERIFY(sawSlope);
        const Run table = shadowlab({"settings"});
        QCOMPARE(table.exitCode, 0);
        QVERIFY(table.out.contains("filter.mode") && table.out.contains("hard | pcf | pcf-optimized | pcf-dither4 | pcf64 | hw-bilinear"));
        // Readable as a table: every key's default starts in one column, whatever the key's
        // length, and the help is wrapped (a range may run long: it is one list).
        const QStringList lines = table.out.split('\n', Qt::SkipEmptyParts);
        const qsizetype column = lines.first().indexOf("default");
        int rows = 0;
        for (const QString& line : lines.mid(1)) {
            if (line.startsWith(' ')) {
                QVERIFY2(line.size() <= 100, qPrintable("a help line of " + QString::number(line.size()) + " characters: " + line));
                continue;
            }
            ++rows;
            QVERIFY2(line.at(column - 1) == ' ' && line.at(column) != ' ', qPrintable("the default is not in its column: " + line));
        }
        QCOMPARE(rows, int(keys.size()));
    }

    void reportWritesEveryConfiguredRow()
    {
        const QString sweep = m_dir.filePath("sweep.json");
        QVERIFY(writeFile(sweep, R"([{"label": "hard 512", "set": {"filter.mode": "hard", "map.size": 512}},
                    {"label": "pcf 5", "set": {"filter.mode": "pcf", "filter.kernel": 5}},
                    {"label": "no bias", "set": {"bias.cull_front": false, "bias.footprint": false, "bias.skip_floors": false, "bias.slope": 0, "bias.min": 0}}])"));
        const QString dir = m_dir.filePath("report");
        const Run r = shadowlab({"report", "--scene", "seed", "--size", "160x90", "--sweep", sweep, "--frames", "2", "--warmup", "0",
                                 "--area-samples", "2", "--out", dir});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));

        QFile csv(dir + "/report.csv");
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(csv.readAll()).trimmed().split('\n');
        QCOMPARE(lines.size(), 4); // header + one row per configuration
        QVERIFY(lines[1].startsWith("hard 512,") && lines[2].startsWith("pcf 5,") && lines[3].startsWith("no bias,"));

        QFile json(dir + "/report.json");
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QJsonObject report = QJsonDocument::fromJson(json.readAll()).object();
        const QJsonArray rows = report.value("rows").toArray();
        QCOMPARE(rows.size(), 3);
        QCOMPARE(report.value("reference_computations").toInt(), 1);
        QVERIFY(report.value("rays_per_second").toDouble() > 0.0);
        // Without bias the shadow is mostly acne: far more false shadow than with the defaults.
        const double acne = rows[2].toObject().value("hard_reference").toObject().value("false_shadow_pct").toDouble();
        const double clean = rows[0].toObject().value("hard_reference").toObject().value("false_shadow_pct").toDouble();
        QVERIFY2(acne > 10 * clean && acne > 5.0, qPrintable(QString("%1 % vs %2 %").arg(acne).arg(clean)));
        // The CSV says the same in the same unit.
        const QStringList header = lines[0].split(',');
        const qsizetype column = header.indexOf("false_shadow_pct");
        QVERIFY(column > 0 && header.contains("frame_ms") && header.contains("misclassified_pct"));
        QVERIFY(qAbs(lines[3].split(',')[column].toDouble() - acne) < 1e-3);

        QFile html(dir + "/report.html");
        QVERIFY(html.open(QIODevice::ReadOnly));
        const QString page = QString::fromUtf8(html.readAll());
        for (const char* label : {"hard 512", "pcf 5", "no bias"})
            QVERIFY(page.contains(label));
        QVERIFY(page.contains("<svg") && page.contains("data:image/png;base64,"));
        QVERIFY(!page.contains("http://") || page.contains("xmlns=\"http://www.w3.org/2000/svg\"")); // self-contained
    }

    // The perceptual column, last in every format: acne spoils the picture, the defaults
    // hardly do, and the CSV, JSON and page agree on it.
    void reportRanksAcneWorseOnSsim()
    {
        const QString sweep = m_dir.filePath("ssim-sweep.json");
        QVERIFY(writeFile(sweep, R"([{"label": "defaults", "set": {}},
                    {"label": "acne", "set": {"bias.cull_front": false, "bias.footprint": false, "bias.skip_floors": false, "bias.slope": 0, "bias.min": 0, "filter.mode": "hard"}}])"));
        const QString dir = m_dir.filePath("ssim-report");
        const Run r = shadowlab({"report", "--scene", "seed", "--size", "160x90", "--sweep", sweep, "--frames", "1", "--warmup", "0",
                                 "--area-samples", "1", "--flicker-frames", "0", "--out", dir});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));

        QFile csv(dir + "/report.csv");
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(csv.readAll()).trimmed().split('\n');
        QCOMPARE(lines.size(), 3);
        QVERIFY2(lines[0].endsWith(",area_mae_noise_pct,dssim,fine_texels_pct,shadow_draws,shadow_primitives,shadow_samples,cleared_texels,"
                                   "blur_texels,blur_bytes,map_bytes,lit_draws,lit_primitives,lit_samples,taps_per_lookup,lookup_fragments,"
                                   "taps,copied_texels,cache_bytes,shadow_per_frame_ms,renderer,machine"),
                 qPrintable(lines[0]));
        // Counts beside the times, the same on any GPU: every row drew, looked up and cleared.
        for (const char* count : {"shadow_primitives", "shadow_samples", "cleared_texels", "map_bytes", "lit_samples", "lookup_fragments", "taps"}) {
            const qsizetype at = csvCells(lines[0]).indexOf(count);
            for (int row = 1; row < lines.size(); ++row)
                QVERIFY2(csvCells(lines[row]).at(at).toLongLong() > 0, qPrintable(QString("%1 in row %2: %3").arg(count).arg(row).arg(lines[row])));
        }
        const qsizetype column = csvCells(lines[0]).indexOf("dssim");
        const auto dssim = [&](const QString& line) { return csvCells(line).at(column).toDouble(); };
        const double defaults = dssim(lines[1]), acne = dssim(lines[2]);
        QVERIFY2(defaults >= 0.0 && acne > 3.0 * defaults && acne > 0.01, qPrintable(QString("DSSIM defaults %1, acne %2").arg(defaults).arg(acne)));

        QFile json(dir + "/report.json");
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QJsonArray rows = QJsonDocument::fromJson(json.readAll()).object().value("rows").toArray();
        QCOMPARE(rows.size(), 2);
        for (int i = 0; i < 2; ++i) {
            const QJsonObject row = rows[i].toObject();
            QVERIFY(qAbs(row.value("dssim").toDouble() - dssim(lines[i + 1])) < 1e-5);
            QVERIFY(qAbs(row.value("mean_ssim").toDouble() + row.value("dssim").toDouble() - 1.0) < 1e-9);
        }

        QFile html(dir + "/report.html");
        QVERIFY(html.open(QIODevice::ReadOnly));
        const QString page = QString::fromUtf8(html.readAll());
        QVERIFY(page.contains(QStringLiteral(">DSSIM</th><th>texels ≤ 1 px %</th></tr>")));
        QVERIFY(page.contains(QStringLiteral("<h2>Counts</h2>")) && page.contains(QStringLiteral("<th>taps per lookup</th><th>shadow taps</th></tr>")));
        const QRegularExpressionMatch acneRow = QRegularExpression(">acne</td>.*?<td>([0-9.]+)</td><td>[^<]*</td></tr>").match(page);
        QVERIFY2(acneRow.hasMatch() && qAbs(acneRow.captured(1).toDouble() - acne) < 1e-5, qPrintable(acneRow.captured(0)));
    }

    // A sweep cut into shares, measured apart and put together, is the report measured whole but
    // for its times: the same rows in the sweep's order, with the same errors, flicker, density
    // and error images. Shares that do not make one sweep are refused, saying which is missing,
    // doubled or foreign; reports of one sweep from two machines stand side by side.
    void reportSharesMergeIntoTheWholeReport()
    {
        const QString sweep = m_dir.filePath("shard-sweep.json");
        QVERIFY(writeFile(sweep, R"([{"label": "hard 512", "set": {"filter.mode": "hard", "map.size": 512}},
                    {"label": "pcf 5", "set": {"filter.mode": "pcf", "filter.kernel": 5}},
                    {"label": "no bias", "set": {"bias.cull_front": false, "bias.footprint": false, "bias.skip_floors": false, "bias.slope": 0, "bias.min": 0}}])"));
        const auto report = [&](const QString& out, const QStringList& more) {
            return shadowlab(QStringList{"report", "--scene", "seed", "--size", "96x54", "--sweep", sweep, "--frames", "2", "--warmup", "0",
                                         "--area-samples", "2", "--flicker-frames", "2", "--out", m_dir.filePath(out)}
                             + more);
        };
        const Run whole = report("whole", {});
        QVERIFY2(whole.exitCode == 0, qPrintable(whole.err));
        const Run first = report("share1", {"--shard", "1/2"});
        QVERIFY2(first.exitCode == 0, qPrintable(first.err));
        QVERIFY2(first.out.contains("share 1 of 2") && first.out.contains("--merge"), qPrintable(first.out));
        const Run second = report("share2", {"--shard", "2/2"});
        QVERIFY2(second.exitCode == 0, qPrintable(second.err));
        QCOMPARE(readJson(m_dir.filePath("share1/report.json")).value("rows").toArray().size(), 2);   // 1st and 3rd
        QCOMPARE(readJson(m_dir.filePath("share2/report.json")).value("rows").toArray().size(), 1);

        // Given in any order, the shares come back in the sweep's.
        const Run merge = shadowlab({"report", "--merge", "--out", m_dir.filePath("merged"), m_dir.filePath("share2"), m_dir.filePath("share1")});
        QVERIFY2(merge.exitCode == 0, qPrintable(merge.err));
        QVERIFY2(merge.out.contains("merged 2 reports: 3 rows"), qPrintable(merge.out));
        const QJsonObject a = readJson(m_dir.filePath("whole/report.json")), b = readJson(m_dir.filePath("merged/report.json"));
        for (const char* key : {"scene", "size", "sweep", "configurations", "area_samples_per_pixel", "renderer", "machine", "area_noise_floor_pct"})
            QVERIFY2(a.value(key) == b.value(key), key);
        QCOMPARE(b.value("parts").toInt(), 2);
        QCOMPARE(b.value("shard").toString(), QStringLiteral("1/1"));
        const QJsonArray wholeRows = a.value("rows").toArray(), mergedRows = b.value("rows").toArray();
        QCOMPARE(mergedRows.size(), wholeRows.size());
        // Every figure but the times (and the fronts they decide), to the last digit or within
        // the rounding of a percentage read back.
        const std::function<void(const QJsonValue&, const QJsonValue&, const QString&)> same = [&](const QJsonValue& x, const QJsonValue& y, const QString& at) {
            if (x.isObject()) {
                for (const QString& key : x.toObject().keys()) {
                    if (!key.endsWith("_wall") && !key.contains("front") && key != "frames")
                        same(x.toObject().value(key), y.toObject().value(key), at + '.' + key);
                }
            } else if (x.isDouble()) {
                QVERIFY2(y.isDouble() && qAbs(x.toDouble() - y.toDouble()) <= 1e-12 * qMax(1.0, qAbs(x.toDouble())),
                         qPrintable(QString("%1: %2 whole, %3 merged").arg(at).arg(x.toDouble()).arg(y.toDouble())));
            } else {
                QVERIFY2(x == y, qPrintable(at));
            }
        };
        for (qsizetype i = 0; i < wholeRows.size(); ++i)
            same(wholeRows[i], mergedRows[i], QString("rows[%1]").arg(i));
        QVERIFY(QImage(m_dir.filePath("merged/" + mergedRows[2].toObject().value("error_image").toString())).size() == QSize(96, 54));
        QFile html(m_dir.filePath("merged/report.html"));
        QVERIFY(html.open(QIODevice::ReadOnly));
        const QString page = QString::fromUtf8(html.readAll());
        QVERIFY(page.contains("no bias") && page.contains("data:image/png;base64,"));
        QVERIFY(!page.contains("<th>renderer</th>"));   // one machine: no column for it

        // What does not make one report.
        const Run alone = shadowlab({"report", "--merge", "--out", m_dir.filePath("never"), m_dir.filePath("share1")});
        QCOMPARE(alone.exitCode, 2);
        QVERIFY2(alone.err.contains("1 of the sweep's 3 configurations is in none of the reports given (number 2)") && alone.err.contains("--shard 2/2"), qPrintable(alone.err));
        const Run twice = shadowlab({"report", "--merge", "--out", m_dir.filePath("never"), m_dir.filePath("share1"), m_dir.filePath("share2"),
                                     m_dir.filePath("share1")});
        QCOMPARE(twice.exitCode, 2);
        QVERIFY2(twice.err.contains("give each share once"), qPrintable(twice.err));
        const Run smaller = shadowlab({"report", "--scene", "seed", "--size", "64x36", "--sweep", sweep, "--frames", "1", "--warmup", "0",
                                       "--area-samples", "2", "--flicker-frames", "2", "--shard", "2/2", "--out", m_dir.filePath("share2-small")});
        QVERIFY2(smaller.exitCode == 0, qPrintable(smaller.err));
        const Run foreign = shadowlab({"report", "--merge", "--out", m_dir.filePath("never"), m_dir.filePath("share1"), m_dir.filePath("share2-small")});
        QCOMPARE(foreign.exitCode, 2);
        QVERIFY2(foreign.err.contains("different sweeps (size 96x54 against 64x36)"), qPrintable(foreign.err));
        const Run notAReport = shadowlab({"report", "--merge", "--out", m_dir.filePath("never"), m_dir.filePath("share1"), m_dir.path()});
        QCOMPARE(notAReport.exitCode, 2);
        QVERIFY2(notAReport.err.contains("report.json") && notAReport.err.contains("cannot be read"), qPrintable(notAReport.err));
        const Run overItself = shadowlab({"report", "--merge", "--out", m_dir.filePath("share2") + "/", m_dir.filePath("share1"), m_dir.filePath("share2")});
        QCOMPARE(overItself.exitCode, 2);
        QVERIFY2(overItself.err.contains("is one of the reports being merged"), qPrintable(overItself.err));
        const Run notForMerge = shadowlab({"report", "--merge", "--size", "96x54", "--out", m_dir.filePath("never"), m_dir.filePath("share1")});
        QCOMPARE(notForMerge.exitCode, 2);
        QVERIFY2(notForMerge.err.contains("--size does not apply"), qPrintable(notForMerge.err));
        // A damaged count is refused before anything is sized by it.
        QVERIFY(QDir().mkpath(m_dir.filePath("damaged")));
        QJsonObject damaged = readJson(m_dir.filePath("share2/report.json"));
        damaged.insert("configurations", 1e9);
        QVERIFY(writeFile(m_dir.filePath("damaged/report.json"), QJsonDocument(damaged).toJson()));
        const Run huge = shadowlab({"report", "--merge", "--out", m_dir.filePath("never"), m_dir.filePath("share1"), m_dir.filePath("damaged")});
        QCOMPARE(huge.exitCode, 2);
        QVERIFY2(huge.err.contains("configurations is not between 1 and 100000"), qPrintable(huge.err));
        damaged = readJson(m_dir.filePath("share2/report.json"));
        QJsonArray damagedRows = damaged.value("rows").toArray();
        QJsonObject row = damagedRows[0].toObject(), hard = row.value("hard_reference").toObject();
        hard.insert("misclassified_pct", -5);
        row.insert("hard_reference", hard);
        damagedRows[0] = row;
        damaged.insert("rows", damagedRows);
        QVERIFY(writeFile(m_dir.filePath("damaged/report.json"), QJsonDocument(damaged).toJson()));
        const Run negative = shadowlab({"report", "--merge", "--out", m_dir.filePath("never"), m_dir.filePath("share1"), m_dir.filePath("damaged")});
        QCOMPARE(negative.exitCode, 2);
        QVERIFY2(negative.err.contains("hard_reference.misclassified_pct is not a percentage"), qPrintable(negative.err));
        for (const QString& shard : {QString("0/2"), QString("3/2"), QString("two"), QString("1/4")}) {
            const Run bad = report("never", {"--shard", shard});
            QCOMPARE(bad.exitCode, 2);
            QVERIFY2(bad.err.contains("--shard " + shard), qPrintable(bad.err));
        }
        QVERIFY(!QFile::exists(m_dir.filePath("never")));

        // The same sweep from a second machine (its report.json as one would bring it): both
        // machines' rows side by side, each machine with its own front, the renderer a column.
        QVERIFY(QDir().mkpath(m_dir.filePath("gpu/errors")));
        QJsonObject gpu = a;
        QJsonArray gpuRows;
        for (const QJsonValue& row : wholeRows) {
            QJsonObject r = row.toObject();
            r.insert("renderer", "NVIDIA Test GPU/PCIe/SSE2");
            QVERIFY(QFile::copy(m_dir.filePath("whole/" + r.value("error_image").toString()), m_dir.filePath("gpu/" + r.value("error_image").toString())));
            gpuRows.append(r);
        }
        gpu.insert("rows", gpuRows);
        gpu.insert("renderer", "NVIDIA Test GPU/PCIe/SSE2");
        QVERIFY(writeFile(m_dir.filePath("gpu/report.json"), QJsonDocument(gpu).toJson()));
        const Run compared = shadowlab({"report", "--merge", "--out", m_dir.filePath("compared"), m_dir.filePath("whole"), m_dir.filePath("gpu")});
        QVERIFY2(compared.exitCode == 0, qPrintable(compared.err));
        QVERIFY2(compared.out.contains("note: the rows were measured on 2 renderers"), qPrintable(compared.out));
        const QJsonArray both = readJson(m_dir.filePath("compared/report.json")).value("rows").toArray();
        QCOMPARE(both.size(), 6);
        int gpuFront = 0, cpuFront = 0;
        for (const QJsonValue& row : both) {
            const bool front = row.toObject().value("pareto_front").toBool();
            (row.toObject().value("renderer").toString().startsWith("NVIDIA") ? gpuFront : cpuFront) += front ? 1 : 0;
        }
        QVERIFY(gpuFront > 0 && cpuFront > 0);
        QFile comparedHtml(m_dir.filePath("compared/report.html"));
        QVERIFY(comparedHtml.open(QIODevice::ReadOnly));
        const QString comparison = QString::fromUtf8(comparedHtml.readAll());
        QVERIFY(comparison.contains("<th>renderer</th>") && comparison.contains("NVIDIA Test GPU"));
        QFile csv(m_dir.filePath("compared/report.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(csv.readAll()).trimmed().split('\n');
        QCOMPARE(lines.size(), 7);
        const qsizetype renderer = csvCells(lines[0]).indexOf("renderer");
        QVERIFY(renderer > 0);
        QCOMPARE(csvCells(lines[2]).at(renderer), QStringLiteral("NVIDIA Test GPU/PCIe/SSE2"));   // sweep order, the same configuration twice

        // Written again into the same folder with fewer rows: no image of the old report stays
        // to be taken for the new one's.
        QVERIFY(QFile::exists(m_dir.filePath("compared/errors/005.png")));
        const Run again = shadowlab({"report", "--merge", "--out", m_dir.filePath("compared"), m_dir.filePath("share1"), m_dir.filePath("share2")});
        QVERIFY2(again.exitCode == 0, qPrintable(again.err));
        QVERIFY(QFile::exists(m_dir.filePath("compared/errors/002.png")) && !QFile::exists(m_dir.filePath("compared/errors/003.png")));
    }

    // --cost taps draws the fronts on a count, the same on any GPU, and says so; a cost that is
    // none is refused before any work.
    void reportFrontOnACount()
    {
        const QString dir = m_dir.filePath("taps-report");
        const QString sweep = m_dir.filePath("taps-sweep.json");
        QVERIFY(writeFile(sweep, R"([{"label": "hard", "set": {"filter.mode": "hard"}}, {"label": "pcf 5x5", "set": {"filter.mode": "pcf", "filter.kernel": 5}}])"));
        const Run r = shadowlab({"report", "--scene", "seed", "--size", "160x90", "--sweep", sweep, "--frames", "1",
                                 "--warmup", "0", "--area-samples", "1", "--flicker-frames", "0", "--cost", "taps", "--out", dir});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("on a count's cost, the same on any GPU") && r.out.contains(" taps a frame"), qPrintable(r.out));
        QFile html(dir + "/report.html");
        QVERIFY(html.open(QIODevice::ReadOnly));
        QVERIFY(QString::fromUtf8(html.readAll()).contains("shadow taps a frame, the same on any GPU (log scale)"));
        QFile json(dir + "/report.json");
        QVERIFY(json.open(QIODevice::ReadOnly));
        for (const QJsonValue row : QJsonDocument::fromJson(json.readAll()).object().value("rows").toArray())
            QCOMPARE(row.toObject().value("cost_axis").toString(), QStringLiteral("taps"));
        const Run bad = shadowlab({"report", "--cost", "ms", "--out", m_dir.filePath("never")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("--cost") && bad.err.contains("time, taps or samples"), qPrintable(bad.err));
        QVERIFY(!QFile::exists(m_dir.filePath("never")));
    }

    // A report on a base of cascades or a virtual map keeps its tutorial row, a plain map: the
    // tutorial's hand-set volume would be refused on either rig.
    void reportOnAnyRigKeepsTheTutorialRow()
    {
        const QString sweep = m_dir.filePath("rig-sweep.json");
        QVERIFY(writeFile(sweep, R"([{"label": "hard", "set": {"filter.mode": "hard"}}])"));
        for (const char* rig : {"shadow.virtual=true", "shadow.cascades=4", "light.warp=lispsm"}) {
            const QString dir = m_dir.filePath(QStringLiteral("rig-report-%1").arg(QString::fromLatin1(rig).section('=', 0, 0)));
            const Run r = shadowlab({"report", "--scene", "seed", "--set", rig, "--size", "96x54", "--sweep", sweep, "--frames", "1", "--warmup",
                                     "0", "--area-samples", "1", "--flicker-frames", "0", "--out", dir});
            QVERIFY2(r.exitCode == 0, qPrintable(QStringLiteral("%1: %2").arg(QString::fromLatin1(rig), r.err)));
            QVERIFY(QFile::exists(dir + "/report.json"));
        }
    }

    // Over an animation each row is measured at every instant; its error is the worst one's,
    // with the mean and each instant in report.json. A scene that does not move is refused.
    void reportOverAnAnimation()
    {
        const QString dir = m_dir.filePath("animation-report");
        const QString sweep = m_dir.filePath("animation-sweep.json");
        QVERIFY(writeFile(sweep, R"([{"label": "hard", "set": {"filter.mode": "hard"}}, {"label": "pcf 5x5", "set": {"filter.mode": "pcf", "filter.kernel": 5}}])"));
        const Run r = shadowlab({"report", "--scene", "swing", "--size", "160x90", "--sweep", sweep, "--frames", "2", "--warmup", "0",
                                 "--area-samples", "1", "--flicker-frames", "0", "--times", "0.2,0.9,1.6", "--out", dir});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("over the animation (3 instants") && r.out.contains("reference traced 3 times"), qPrintable(r.out));
        QFile json(dir + "/report.json");
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QJsonArray rows = QJsonDocument::fromJson(json.readAll()).object().value("rows").toArray();
        QCOMPARE(rows.size(), 2);
        for (const QJsonValue value : rows) {
            const QJsonObject row = value.toObject();
            const QJsonObject animation = row.value("animation").toObject();
            QCOMPARE(animation.value("times").toArray().size(), 3);
            const QJsonObject wrong = animation.value("misclassified_pct").toObject();
            QCOMPARE(wrong.value("each").toArray().size(), 3);
            QVERIFY(wrong.value("worst").toDouble() >= wrong.value("mean").toDouble());
            QCOMPARE(row.value("hard_reference").toObject().value("misclassified_pct").toDouble(), wrong.value("worst").toDouble());
        }
        const Run still = shadowlab({"report", "--scene", "seed", "--animation", "4", "--out", m_dir.filePath("never")});
        QCOMPARE(still.exitCode, 2);
        QVERIFY2(still.err.contains("--animation") && still.err.contains("nothing in the scene") && still.err.contains("swing"), qPrintable(still.err));
        const Run bad = shadowlab({"report", "--scene", "swing", "--times", "0,soon", "--out", m_dir.filePath("never")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("--times: 'soon' is not a time"), qPrintable(bad.err));
        const Run render = shadowlab({"render", "--scene", "seed", "--time", "2", "--size", "64x36", "--out", m_dir.filePath("still.png")});
        QVERIFY2(render.exitCode == 0 && render.err.contains("nothing in the scene seed moves"), qPrintable(render.err));
        // The window of a playing scene never stops drawing: its screenshot is a moment of it.
        const Run playing = shadowlab({"screenshot", "--scene", "swing", "--set", "scene.play=true", "--out", m_dir.filePath("playing.png")});
        QVERIFY2(playing.exitCode == 0 && QImage(m_dir.filePath("playing.png")).width() > 0, qPrintable(playing.err));
        const Run late = shadowlab({"render", "--scene", "swing", "--time", "-1", "--out", m_dir.filePath("never.png")});
        QCOMPARE(late.exitCode, 2);
        QVERIFY2(late.err.contains("--time"), qPrintable(late.err));
        QVERIFY(!QFile::exists(m_dir.filePath("never")));
    }

    void reportRejectsABadSweep()
    {
        const QString sweep = m_dir.filePath("bad-sweep.json");
        QVERIFY(writeFile(sweep, R"([{"label": "broken", "set": {"filter.kernel": 4}}])"));
        const Run r = shadowlab({"report", "--sweep", sweep, "--out", m_dir.filePath("never")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("broken") && r.err.contains("filter.kernel"), qPrintable(r.err));
        QVERIFY2(r.err.count("filter.kernel") == 1, qPrintable("the key is named once:\n" + r.err));
        QVERIFY(!QFile::exists(m_dir.filePath("never")));
        const Run misspelt = shadowlab({"report", "--sweep", "virtaul", "--out", m_dir.filePath("never")});
        QCOMPARE(misspelt.exitCode, 2);
        QVERIFY2(misspelt.err.contains("did you mean 'virtual'"), qPrintable(misspelt.err));
        QVERIFY(!QFile::exists(m_dir.filePath("never")));
    }

    // The defaults already sit on the knee of the acne-against-leak curve: tune says so and
    // prints nothing to apply.
    void tuneKeepsASettingAlreadyOnTheKnee()
    {
        const Run r = shadowlab({"tune", "--scene", "seed", "--size", "96x54"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("already on the knee") && r.out.contains("nothing to change"), qPrintable(r.out));
        QVERIFY2(!r.out.contains("--set"), qPrintable(r.out));
    }

    // No bias on front faces is acne everywhere: tune recommends a change, and what it
    // recommends is a point of the curve it printed.
    void tuneRecommendsAPointOfItsCurve()
    {
        const Run r = shadowlab({"tune", "--scene", "seed", "--size", "96x54", "--set", "bias.cull_front=false", "--set", "bias.footprint=false",
                                 "--set", "bias.skip_floors=false", "--set", "bias.slope=0", "--set", "bias.min=0"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        static const QRegularExpression apply(R"(apply with: --set bias.space=\S+ --set bias.slope=(\S+) --set bias.min=(\S+))");
        const QRegularExpressionMatch set = apply.match(r.out);
        QVERIFY2(set.hasMatch() && !r.out.contains("already on the knee"), qPrintable(r.out));
        static const QRegularExpression best(R"(^\s+(\S+)\s+(\S+)\s+\S+\s+\S+\s+<- best(, as set)?$)", QRegularExpression::MultilineOption);
        const QRegularExpressionMatch onCurve = best.match(r.out);
        QVERIFY2(onCurve.hasMatch(), qPrintable(r.out));
        QCOMPARE(set.captured(1), onCurve.captured(1));
        QCOMPARE(set.captured(2), onCurve.captured(2));
        QVERIFY(set.captured(1).toDouble() > 0.0 || set.captured(2).toDouble() > 0.0);
    }

    void benchLabelsItsColumnsAndAlignsThem()
    {
        const Run r = shadowlab({"bench", "--size", "96x64", "--frames", "3", "--warmup", "0", "--phase", "moving-light"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList lines = r.out.split('\n');
        const qsizetype header = lines.indexOf(QRegularExpression(R"(^\s+ms per frame\s+median\s+p10\s+p90\s+mean$)"));
        QVERIFY2(header >= 0, qPrintable(r.out));
        const qsizetype medianEnd = lines[header].indexOf("median") + 6;
        const qsizetype p90End = lines[header].indexOf("p90") + 3;
        const qsizetype meanEnd = lines[header].size();
        // Shadow and lit pass (wall, and the GPU timer where it means something), the frame and
        // what it spends outside its passes: each figure ends in its heading's column.
        const bool software = r.out.contains("software renderer");
        QCOMPARE(r.out.contains("(GPU)"), !software);
        const int rows = software ? 4 : 6;
        QVERIFY(lines.size() > header + rows);
        for (qsizetype i = header + 1; i <= header + rows; ++i) {
            const QString& line = lines[i];
            QVERIFY2(line.contains("pass (") || line.contains("frame (wall)") || line.contains("outside the passes"), qPrintable(line));
            QVERIFY2(line.at(medianEnd - 1).isDigit() && line.at(medianEnd) == ' ' && line.at(p90End - 1).isDigit() && line.at(p90End) == ' '
                         && line.at(meanEnd - 1).isDigit(),
                     qPrintable(line));
        }
        QVERIFY2(lines[header + rows + 1].contains("shadow texel"), qPrintable(lines[header + rows + 1]));
    }

    void benchReportsCachedAndUncachedPhases()
    {
        const Run r = shadowlab({"bench", "--size", "160x90", "--frames", "5", "--warmup", "1", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY(o.value("renderer").toString().size() > 3);
        const QJsonArray phases = o.value("phases").toArray();
        QMap<QString, QJsonObject> byName;
        for (const QJsonValue& p : phases)
            byName.insert(p.toObject().value("phase").toString(), p.toObject());
        QCOMPARE(byName.keys(), (QStringList{"moving-camera", "moving-camera-no-shadows", "moving-light", "steady"}));
        QCOMPARE(byName["steady"].value("shadow_passes_run").toInt(), 0);
        QVERIFY(byName["steady"].value("shadow_pass_cached").toBool());
        QCOMPARE(byName["moving-light"].value("shadow_passes_run").toInt(), 5);
        QCOMPARE(byName["moving-camera-no-shadows"].value("shadow_passes_run").toInt(), 0);
        // A quarter degree a frame keeps the stabilised fit: the map is not redrawn every frame.
        QVERIFY(byName["moving-camera"].value("shadow_passes_run").toInt() < 5);
        // GPU rows only where the timer measures something; a software renderer runs no query.
        const bool gpuTimed = o.value("gpu_timer_meaningful").toBool();
        for (const QJsonObject& phase : byName) {
            const QJsonObject frame = phase.value("frame_wall").toObject();
            QVERIFY(frame.value("median_ms").toDouble() > 0.0);
            // What the frame spends outside its passes (the fit, the reach), every frame: within the frame.
            const QJsonObject outside = phase.value("outside_passes_wall").toObject();
            QCOMPARE(outside.value("count").toInt(), frame.value("count").toInt());
            QVERIFY(outside.value("median_ms").toDouble() >= 0.0 && outside.value("median_ms").toDouble() < frame.value("median_ms").toDouble());
            QCOMPARE(phase.value("lit_pass_gpu").isObject(), gpuTimed);
            QCOMPARE(phase.value("lit_pass_gpu").isNull(), !gpuTimed);
        }
    }

    // The tutorial's own program is timed in the same loop, one frame a round, and the ratios
    // are then to it; it draws seed's scene only.
    void benchTimesTheTutorialsOwnProgram()
    {
        const Run r = shadowlab({"bench", "--size", "160x90", "--frames", "4", "--warmup", "1", "--phase", "moving-light", "--anchor", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonArray phases = QJsonDocument::fromJson(r.out.toUtf8()).object().value("phases").toArray();
        QCOMPARE(phases.size(), 2);
        const QJsonObject anchor = phases.at(1).toObject();
        QCOMPARE(anchor.value("phase").toString(), QStringLiteral("tutorial-program"));
        QCOMPARE(anchor.value("frame_wall").toObject().value("count").toInt(), 4);
        QVERIFY(anchor.value("frame_wall").toObject().value("median_ms").toDouble() > 0.0);
        // The ratio comes with its own noise: each round's ShadowLab frame over the same
        // round's tutorial frame, whose spread holds the ratio of medians' neighbourhood.
        const QJsonObject relative = phases.at(0).toObject().value("frame_wall_relative").toObject();
        QCOMPARE(relative.value("to").toString(), QStringLiteral("tutorial-program"));
        QCOMPARE(relative.value("rounds").toInt(), 4);
        const double p10 = relative.value("round_p10").toDouble(), p90 = relative.value("round_p90").toDouble();
        QVERIFY2(p10 > 0.0 && p10 <= relative.value("round_median").toDouble() && relative.value("round_median").toDouble() <= p90,
                 qPrintable(QJsonDocument(relative).toJson()));
        QVERIFY(relative.value("ratio_of_medians").toDouble() > 0.0);
        QVERIFY(relative.value("ratio_of_means").toDouble() > 0.0);
        const Run text = shadowlab({"bench", "--size", "96x64", "--frames", "2", "--warmup", "0", "--phase", "moving-light", "--anchor"});
        QVERIFY2(text.out.contains("relative to tutorial-program"), qPrintable(text.out));
        QVERIFY2(text.out.contains("round by round"), qPrintable(text.out));
        const Run refused = shadowlab({"bench", "--scene", "torus", "--anchor", "--frames", "1"});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains("--anchor") && refused.err.contains("seed"), qPrintable(refused.err));
    }

    // A moving light redraws the map every frame and clears it once in map.slices draws; bench
    // says so, and its mean counts the frames that clear.
    void benchCountsTheMapsClears()
    {
        for (int slices : {1, 4, 8}) {
            const Run r = shadowlab({"bench", "--size", "96x64", "--frames", "8", "--warmup", "1", "--phase", "moving-light", "--json", "--set",
                                     QStringLiteral("map.slices=%1").arg(slices)});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const QJsonObject phase = QJsonDocument::fromJson(r.out.toUtf8()).object().value("phases").toArray().at(0).toObject();
            QCOMPARE(phase.value("shadow_passes_run").toInt(), 8);
            // Draws 0 (the warm-up) to 8, a clear in draws 0, n, 2n...: of the 8 timed, 8 / n.
            QCOMPARE(phase.value("shadow_map_clears").toInt(), 8 / slices);
            const QJsonObject frame = phase.value("frame_wall").toObject();
            QVERIFY(frame.value("mean_ms").toDouble() >= frame.value("min_ms").toDouble());
            QVERIFY(frame.value("mean_ms").toDouble() <= frame.value("max_ms").toDouble());
        }
        const Run text = shadowlab({"bench", "--size", "96x64", "--frames", "8", "--warmup", "0", "--phase", "moving-light"});
        QVERIFY2(text.out.contains("map cleared in 2 (map.slices=4)"), qPrintable(text.out));
    }

    // The shadow term's cost: the still frame with and without shadows, frame by frame in one
    // process, so the ratio of each round's pair is the noise of the ratio itself.
    void benchTimesTheStillFrameWithoutShadows()
    {
        const Run r = shadowlab({"bench", "--size", "96x64", "--frames", "6", "--warmup", "1", "--phase", "steady", "--without-shadows", "--json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject document = QJsonDocument::fromJson(r.out.toUtf8()).object();
        const QJsonArray phases = document.value("phases").toArray();
        QCOMPARE(phases.size(), 2);
        const QJsonObject on = phases.at(0).toObject(), off = phases.at(1).toObject();
        QCOMPARE(on.value("phase").toString(), QStringLiteral("steady"));
        QCOMPARE(off.value("phase").toString(), QStringLiteral("steady-no-shadows"));
        QCOMPARE(document.value("settings").toObject().value("shadow.enabled").toBool(), true);
        const QJsonObject cost = document.value("still_lit_pass_shadows_over_none").toObject();
        QCOMPARE(cost.value("rounds").toInt(), 6);
        const double ratio = cost.value("ratio_of_medians").toDouble();
        const double onMedian = on.value("lit_pass_wall").toObject().value("median_ms").toDouble();
        const double offMedian = off.value("lit_pass_wall").toObject().value("median_ms").toDouble();
        QVERIFY(offMedian > 0.0);
        QVERIFY2(std::abs(ratio - onMedian / offMedian) < 1e-9, qPrintable(QString::number(ratio)));
        QVERIFY(cost.value("round_p10").toDouble() <= cost.value("round_median").toDouble());
        QVERIFY(cost.value("round_median").toDouble() <= cost.value("round_p90").toDouble());
        const Run text = shadowlab({"bench", "--size", "96x64", "--frames", "4", "--warmup", "0", "--phase", "both", "--without-shadows"});
        QVERIFY2(text.exitCode == 0, qPrintable(text.err));
        QVERIFY2(text.out.contains("still lit pass, shadows on / off: "), qPrintable(text.out));
        // Nothing still to compare with: a clear refusal, not a silent run.
        const Run moving = shadowlab({"bench", "--frames", "1", "--phase", "moving-light", "--without-shadows"});
        QCOMPARE(moving.exitCode, 2);
        QVERIFY2(moving.err.contains("--without-shadows") && moving.err.contains("--phase steady"), qPrintable(moving.err));
    }

    // The importer's limits are options, not settings: their messages name them as typed.
    void importLimitsOutOfRangeNameTheOption()
    {
        for (const QStringList& option : {QStringList{"--import-time-limit", "0"}, QStringList{"--import-time-limit", "nan"},
                                          QStringList{"--import-time-limit", "soon"}, QStringList{"--import-memory-limit", "16"}}) {
            const Run r = shadowlab(QStringList{"render", "--size", "32x32", "--out", m_dir.filePath("limit.png")} + option);
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains(option.front() + ": ") && r.err.contains(", e.g. " + option.front() + " "), qPrintable(r.err));
            QVERIFY(!QFile::exists(m_dir.filePath("limit.png")));
        }
    }

    void benchRefusesAnUnknownPhase()
    {
        const Run r = shadowlab({"bench", "--phase", "sideways", "--frames", "1"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("sideways") && r.err.contains("moving-camera"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "tst_Cli.moc"
