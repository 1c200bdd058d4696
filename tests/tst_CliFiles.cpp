// Files at the edges, as a careful user and a hostile file meet them: outputs written whole or
// not at all and checked before any work; inputs read once, with a size limit and without
// hanging; sweep files checked; sizes bounded; messages that stay readable.
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <optional>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

struct Run {
    int exitCode = -1;      // -1: crashed or timed out
    QString out;
    QString err;
    qint64 ms = 0;
};

struct Options {
    QMap<QString, std::optional<QString>> env;  // nullopt: unset
    QByteArray input;                           // written to stdin, which is then closed
    qint64 fileSizeLimit = -1;                  // RLIMIT_FSIZE in bytes: writes past it fail with EFBIG
    std::function<void()> whileRunning;         // called once the process has started
};

Run shadowlab(const QStringList& arguments, const Options& options = {})
{
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (auto it = options.env.begin(); it != options.env.end(); ++it) {
        if (it.value())
            env.insert(it.key(), *it.value());
        else
            env.remove(it.key());
    }
    process.setProcessEnvironment(env);
    if (options.fileSizeLimit >= 0) {
        const rlim_t limit = rlim_t(options.fileSizeLimit);
        process.setChildProcessModifier([limit] {
            // Ignored, SIGXFSZ turns the overlong write into an EFBIG error, as a full disk would.
            std::signal(SIGXFSZ, SIG_IGN);
            const rlimit r{limit, limit};
            setrlimit(RLIMIT_FSIZE, &r);
        });
    }
    QElapsedTimer timer;
    timer.start();
    process.start(QStringLiteral(SHADOWLAB_BINARY), arguments);
    if (!process.waitForStarted())
        return {};
    if (!options.input.isNull()) {
        process.write(options.input);
        process.closeWriteChannel();
    }
    if (options.whileRunning)
        options.whileRunning();
    if (!process.waitForFinished(300000)) {
        process.kill();
        process.waitForFinished();
        return {-1, {}, {}, timer.elapsed()};
    }
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1, QString::fromUtf8(process.readAllStandardOutput()),
            QString::fromUtf8(process.readAllStandardError()), timer.elapsed()};
}

bool writeFile(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

QByteArray readFile(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Everything in `folder`, hidden files included: a temporary file left behind shows here.
QStringList entries(const QString& folder)
{
    QStringList names = QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot);
    names.sort();
    return names;
}

const QByteArray kOldContent = "the old file, which a failed write must leave as it was";

} // namespace

class TestCliFiles : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    // A fresh folder holding one old file, `old.png`, for one test row.
    QString folderWithOldFile(const QString& name)
    {
        const QString folder = m_dir.filePath(name);
        QDir().mkpath(folder);
        writeFile(folder + "/old.png", kOldContent);
        return folder;
    }

private Q_SLOTS:
    // --- outputs ---------------------------------------------------------------------------

    void badOutputIsRefusedBeforeAnyWork_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("mentions");
        const QString old = QStringLiteral("%OLD%");
        QTest::newRow("render --out /dev/full") << QStringList{"render", "--out", "/dev/full"} << "/dev/full";
        QTest::newRow("render --out a folder") << QStringList{"render", "--out", "%DIR%"} << "folder";
        QTest::newRow("render --out in a missing folder") << QStringList{"render", "--out", "%DIR%/missing/x.png"} << "does not exist";
        QTest::newRow("render --depth-out in /proc") << QStringList{"render", "--out", old, "--depth-out", "/proc/nope.png"} << "/proc";
        QTest::newRow("render --depth-out /dev/full") << QStringList{"render", "--out", old, "--depth-out", "/dev/full"} << "/dev/full";
        QTest::newRow("screenshot --out /dev/full") << QStringList{"screenshot", "--out", "/dev/full"} << "/dev/full";
        QTest::newRow("screenshot --out in /proc") << QStringList{"screenshot", "--out", "/proc/nope.png"} << "/proc";
        QTest::newRow("report --out /proc/nope") << QStringList{"report", "--out", "/proc/nope"} << "/proc";
        QTest::newRow("report --out a file") << QStringList{"report", "--out", old} << "not a folder";
    }

    void badOutputIsRefusedBeforeAnyWork()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, mentions);
        const QString folder = folderWithOldFile(QTest::currentDataTag());
        for (QString& a : arguments)
            a.replace("%OLD%", folder + "/old.png").replace("%DIR%", folder);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(mentions) && r.err.contains("cannot write"), qPrintable(r.err));
        QVERIFY2(r.ms < 10000, qPrintable(QString("took %1 ms: the check came after the work").arg(r.ms)));
        QCOMPARE(readFile(folder + "/old.png"), kOldContent);
        QCOMPARE(entries(folder), QStringList{"old.png"});
    }

    void writeFailingMidwayKeepsTheOldFile_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("target");  // the file whose write fails, inside the row's folder
        QTest::newRow("render --out") << QStringList{"render", "--size", "64x64", "--out", "%DIR%/old.png"} << "old.png";
        QTest::newRow("render --depth-out") << QStringList{"render", "--size", "64x64", "--set", "map.size=256", "--depth-out", "%DIR%/old.png"}
                                            << "old.png";
        QTest::newRow("screenshot") << QStringList{"screenshot", "--size", "640x400", "--out", "%DIR%/old.png"} << "old.png";
        QTest::newRow("report") << QStringList{"report", "--size", "32x18", "--sweep", "%DIR%/sweep.json", "--frames", "1", "--warmup", "0",
                                               "--area-samples", "1", "--out", "%DIR%"}
                                << "report.csv";
    }

    void writeFailingMidwayKeepsTheOldFile()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, target);
        const QString folder = folderWithOldFile(QTest::currentDataTag());
        QVERIFY(writeFile(folder + "/report.csv", kOldContent));
        QVERIFY(writeFile(folder + "/sweep.json", R"([{"label": "hard", "set": {"filter.mode": "hard"}}])"));
        const QStringList before = entries(folder);
        for (QString& a : arguments)
            a.replace("%DIR%", folder);

        Options options;
        options.fileSizeLimit = 16; // every output is larger: its write fails part-way, like a full disk
        const Run r = shadowlab(arguments, options);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(target) && r.err.contains("left as it was"), qPrintable(r.err));
        QCOMPARE(readFile(folder + "/" + target), kOldContent);
        QCOMPARE(entries(folder), before); // no partial or temporary file

        // The same command with room to write replaces the file whole.
        const Run ok = shadowlab(arguments);
        QVERIFY2(ok.exitCode == 0, qPrintable(ok.err));
        if (target.endsWith(".png"))
            QVERIFY(!QImage(folder + "/" + target).isNull());
        else
            QVERIFY(readFile(folder + "/" + target).startsWith("label,"));
    }

    // A command stopped by SIGTERM or SIGINT (a scheduler's time limit, Ctrl+C) dies of it, as
    // scripts and schedulers expect (128 + n in a shell), and leaves nothing half-written where
    // its output goes.
    void stopSignalLeavesNoPartialFile_data()
    {
        QTest::addColumn<int>("signal");
        QTest::newRow("SIGTERM") << SIGTERM;
        QTest::newRow("SIGINT") << SIGINT;
    }
    void stopSignalLeavesNoPartialFile()
    {
        QFETCH(int, signal);
        const QString folder = m_dir.filePath(QStringLiteral("stopped-%1").arg(signal));
        QVERIFY(QDir().mkpath(folder));
        QProcess process;
        process.setChildProcessModifier([] {
            for (int s : {SIGTERM, SIGINT})
                std::signal(s, SIG_DFL);    // however this test was started (a shell's background job ignores SIGINT)
        });
        process.start(QStringLiteral(SHADOWLAB_BINARY), {"report", "--scene", "seed", "--size", "320x180", "--out", folder});
        QVERIFY(process.waitForStarted());
        QTest::qWait(1500);     // into the work: the default sweep takes a minute
        QCOMPARE(process.state(), QProcess::Running);
        QCOMPARE(::kill(pid_t(process.processId()), signal), 0);
        QVERIFY(process.waitForFinished(30000));
        QCOMPARE(process.exitStatus(), QProcess::CrashExit);
        QCOMPARE(process.exitCode(), signal);
        QCOMPARE(entries(folder), QStringList());
    }

    // A report folder may be several levels new, as its help says: the nearest folder that
    // exists is the one that must take new folders.
    void reportMakesMissingFolders()
    {
        const QString folder = m_dir.filePath("deep/er/report");
        QVERIFY(writeFile(m_dir.filePath("one.json"), R"([{"label": "hard", "set": {"filter.mode": "hard"}}])"));
        const Run r = shadowlab({"report", "--size", "32x18", "--sweep", m_dir.filePath("one.json"), "--frames", "1", "--warmup", "0",
                                 "--area-samples", "1", "--flicker-frames", "0", "--out", folder});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFile::exists(folder + "/report.json"));
        const Run proc = shadowlab({"report", "--out", "/proc/nope/deeper"});
        QCOMPARE(proc.exitCode, 2);
        QVERIFY2(proc.err.contains("/proc"), qPrintable(proc.err));
    }

    void depthOutCheckedBeforeOutIsWritten()
    {
        const QString folder = folderWithOldFile("depth-out-first");
        const Run r = shadowlab({"render", "--size", "64x64", "--out", folder + "/old.png", "--depth-out", folder + "/missing/depth.png"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--depth-out"), qPrintable(r.err));
        QCOMPARE(readFile(folder + "/old.png"), kOldContent);
    }

    // --- inputs ----------------------------------------------------------------------------

    void oversizedInputIsRefusedQuickly_data()
    {
        QTest::addColumn<QStringList>("arguments");
        const QString big = m_dir.filePath("big.json");
        writeFile(big, "{\"bias.slope\": \"" + QByteArray(2 << 20, 'a') + "\"}");
        const QString out = m_dir.filePath("never.png");
        QTest::newRow("settings /dev/zero") << QStringList{"render", "--out", out, "--settings", "/dev/zero"};
        QTest::newRow("settings /dev/urandom") << QStringList{"render", "--out", out, "--settings", "/dev/urandom"};
        QTest::newRow("settings 2 MiB file") << QStringList{"render", "--out", out, "--settings", big};
        QTest::newRow("sweep /dev/zero") << QStringList{"report", "--out", m_dir.filePath("never"), "--sweep", "/dev/zero"};
        QTest::newRow("screenshot settings /dev/urandom") << QStringList{"screenshot", "--out", out, "--settings", "/dev/urandom"};
    }

    void oversizedInputIsRefusedQuickly()
    {
        QFETCH(QStringList, arguments);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("1 MiB"), qPrintable(r.err.left(500)));
        QVERIFY2(r.err.size() < 1000, qPrintable(QString("%1 characters on stderr").arg(r.err.size())));
        QVERIFY2(r.ms < 10000, qPrintable(QString("took %1 ms").arg(r.ms)));
        QVERIFY(!QFile::exists(m_dir.filePath("never.png")) && !QFile::exists(m_dir.filePath("never")));
    }

    void settingsFromAPipeAreReadOnce_data()
    {
        QTest::addColumn<QString>("path");
        QTest::newRow("/dev/stdin") << "/dev/stdin";
        QTest::newRow("/proc/self/fd/0") << "/proc/self/fd/0";
    }

    void settingsFromAPipeAreReadOnce()
    {
        QFETCH(QString, path);
        const QString depth = m_dir.filePath("piped-depth.png");
        QFile::remove(depth);
        Options options;
        options.input = R"({"scene": "torus", "map.size": 128})";
        const Run r = shadowlab({"render", "--size", "32x32", "--settings", path, "--depth-out", depth}, options);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QImage(depth).text("map.size"), QStringLiteral("128")); // the file's map.size was applied...
        QVERIFY(r.err.isEmpty() || !r.err.contains("JSON"));
    }

    void sceneOfAPipedFileIsUsed()
    {
        // ...and its scene too, which is looked at before the rest: both from one read.
        Options options;
        options.input = R"({"scene": "torus"})";
        const Run piped = shadowlab({"render", "--size", "48x48", "--settings", "/dev/stdin", "--out", m_dir.filePath("piped.png")}, options);
        const Run named = shadowlab({"render", "--size", "48x48", "--scene", "torus", "--out", m_dir.filePath("named.png")});
        QVERIFY2(piped.exitCode == 0 && named.exitCode == 0, qPrintable(piped.err + named.err));
        QCOMPARE(QImage(m_dir.filePath("piped.png")), QImage(m_dir.filePath("named.png")));
    }

    void fifoWithoutWriterDoesNotHang()
    {
        const QString fifo = m_dir.filePath("no-writer.fifo");
        QVERIFY(mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
        const Run r = shadowlab({"render", "--out", m_dir.filePath("never.png"), "--settings", fifo});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("no-writer.fifo") && r.err.contains("nothing arrived"), qPrintable(r.err));
        QVERIFY2(r.ms < 30000, qPrintable(QString("took %1 ms").arg(r.ms)));
    }

    void fifoWithAWriterIsRead()
    {
        const QString fifo = m_dir.filePath("writer.fifo");
        QVERIFY(mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
        const QString depth = m_dir.filePath("fifo-depth.png");
        Options options;
        options.whileRunning = [&] {
            QThread::msleep(300); // the reader is already waiting
            const int fd = ::open(QFile::encodeName(fifo).constData(), O_WRONLY);
            const QByteArray json = R"({"map.size": 64})";
            if (fd >= 0) {
                [[maybe_unused]] const ssize_t written = ::write(fd, json.constData(), size_t(json.size()));
                ::close(fd);
            }
        };
        const Run r = shadowlab({"render", "--size", "32x32", "--settings", fifo, "--depth-out", depth}, options);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QImage(depth).text("map.size"), QStringLiteral("64"));
    }

    // --- messages --------------------------------------------------------------------------

    void messagesStayReadable_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QByteArray>("file");       // written to %FILE% first when not empty
        QTest::addColumn<QString>("mentions");
        QTest::addColumn<QString>("mustNotContain");
        const QString out = m_dir.filePath("never.png");
        const QStringList withFile{"render", "--out", out, "--settings", "%FILE%"};
        QTest::newRow("escape sequence in a key") << QStringList{"render", "--out", out, "--set", "bi\x1b[31mas.slope=1"} << QByteArray()
                                                  << "bi\\x1b[31mas.slope" << "\x1b";
        QTest::newRow("escape sequence in a value") << QStringList{"render", "--out", out, "--set", "filter.mode=\x1b]0;x\x07"} << QByteArray()
                                                    << "\\x1b]0;x\\x07" << "\x07";
        QTest::newRow("NUL in a key") << withFile << QByteArray(R"({"bias\u0000slope": 1})") << "bias\\x00slope: unknown setting" << QString();
        QTest::newRow("newline in a value") << withFile << QByteArray(R"({"filter.mode": "hard\nsoft"})") << "hard\\nsoft" << QString();
        QTest::newRow("long value shortened") << withFile << "{\"filter.mode\": \"" + QByteArray(500000, 'x') + "\"}"
                                              << "more characters" << QString(QString(200, 'x'));
        QTest::newRow("1e-400 is too small") << QStringList{"render", "--out", out, "--set", "bias.slope=1e-400"} << QByteArray()
                                             << "too small" << "not a number";
        QTest::newRow("1e-400 in a vector") << QStringList{"render", "--out", out, "--set", "light.position=1e-400,5,5"} << QByteArray()
                                            << "too small" << QString();
        QTest::newRow("1e400 is too large") << QStringList{"render", "--out", out, "--set", "bias.slope=1e400"} << QByteArray()
                                            << "too large" << "not a number";
    }

    void messagesStayReadable()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QByteArray, file);
        QFETCH(QString, mentions);
        QFETCH(QString, mustNotContain);
        const QString path = m_dir.filePath("message.json");
        if (!file.isEmpty())
            QVERIFY(writeFile(path, file));
        for (QString& a : arguments)
            a.replace("%FILE%", path);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(mentions), qPrintable(r.err.left(500)));
        if (!mustNotContain.isEmpty())
            QVERIFY2(!r.err.contains(mustNotContain), qPrintable(r.err.left(500)));
        QVERIFY2(r.err.size() < 1000, qPrintable(QString("%1 characters on stderr").arg(r.err.size())));
    }

    void duplicateFlagsAreAnError_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("flag");
        const QString a = m_dir.filePath("a.png"), b = m_dir.filePath("b.png");
        QTest::newRow("render --out twice") << QStringList{"render", "--out", a, "--out", b} << "--out";
        QTest::newRow("render --size twice") << QStringList{"render", "--out", a, "--size", "8x8", "--size", "16x16"} << "--size";
        QTest::newRow("render --settings twice") << QStringList{"render", "--out", a, "--settings", "x.json", "--settings", "y.json"} << "--settings";
        QTest::newRow("screenshot --compare twice") << QStringList{"screenshot", "--out", a, "--compare", "--compare"} << "--compare";
        QTest::newRow("bench --frames twice") << QStringList{"bench", "--frames", "5", "--frames", "6"} << "--frames";
        QTest::newRow("report --sweep twice") << QStringList{"report", "--out", m_dir.filePath("r"), "--sweep", "bias", "--sweep", "filters"}
                                              << "--sweep";
    }

    void duplicateFlagsAreAnError()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, flag);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(flag + " is given 2 times"), qPrintable(r.err));
        QVERIFY(!QFile::exists(m_dir.filePath("a.png")) && !QFile::exists(m_dir.filePath("b.png")));
    }

    void repeatableSetIsNotADuplicate()
    {
        const Run r = shadowlab({"render", "--size", "16x16", "--out", m_dir.filePath("sets.png"), "--set", "map.size=256", "--set",
                                 "filter.mode=hard"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    }

    // --- sweep files -----------------------------------------------------------------------

    void sweepFilesAreChecked_data()
    {
        QTest::addColumn<QByteArray>("sweep");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("array of numbers") << QByteArray("[1, 2, 3]") << "entry 1 that is not an object";
        QTest::newRow("string for a vector") << QByteArray(R"([{"set": {"light.position": "abc"}}])") << "light.position";
        QTest::newRow("strings in a vector") << QByteArray(R"([{"label": "v", "set": {"light.position": ["a", "b", "c"]}}])")
                                             << "entry 1: light.position: arrays must hold numbers";
        QTest::newRow("two numbers for a vector") << QByteArray(R"([{"set": {"camera.target": [1, 2]}}])") << "camera.target";
        QTest::newRow("null value") << QByteArray(R"([{"set": {"light.fov": 60}}, {"set": {"bias.slope": null}}])") << "entry 2: bias.slope";
        QTest::newRow("set is not an object") << QByteArray(R"([{"label": "x", "set": [1]}])") << "entry 1 whose \"set\"";
        QTest::newRow("label is not a string") << QByteArray(R"([{"label": 5}])") << "entry 1 whose \"label\"";
        QTest::newRow("misspelt member") << QByteArray(R"([{"lable": "x", "set": {}}])") << "unknown member 'lable'";
        QTest::newRow("object without configurations") << QByteArray(R"({"configs": []})") << "\"configurations\"";
        QTest::newRow("empty") << QByteArray("[]") << "no configurations";
        QTest::newRow("unknown key") << QByteArray(R"([{"set": {"bias.sloppy": 1}}])") << "bias.sloppy";
        QTest::newRow("not JSON") << QByteArray("[{") << "not valid JSON";
    }

    void sweepFilesAreChecked()
    {
        QFETCH(QByteArray, sweep);
        QFETCH(QString, mentions);
        const QString file = m_dir.filePath("checked-sweep.json");
        QVERIFY(writeFile(file, sweep));
        const QString out = m_dir.filePath("never-report");
        const Run r = shadowlab({"report", "--sweep", file, "--out", out});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(mentions), qPrintable(r.err));
        QVERIFY2(r.ms < 10000, qPrintable(QString("took %1 ms").arg(r.ms)));
        QVERIFY(!QFile::exists(out));
    }

    // --- sizes -----------------------------------------------------------------------------

    void sizesOutsideACommandsLimitsAreRefused_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("mentions");
        const QString out = m_dir.filePath("never.png");
        QTest::newRow("screenshot 300x200") << QStringList{"screenshot", "--size", "300x200", "--out", out} << "the minimum is";
        QTest::newRow("screenshot 1x1") << QStringList{"screenshot", "--size", "1x1", "--out", out} << "the minimum is";
        QTest::newRow("screenshot 200x100") << QStringList{"screenshot", "--size", "200x100", "--out", out} << "the minimum is";
        QTest::newRow("screenshot --compare 300x400") << QStringList{"screenshot", "--compare", "--size", "300x400", "--out", out}
                                                      << "in compare mode; the minimum is";
        QTest::newRow("screenshot 16384x16384") << QStringList{"screenshot", "--size", "16384x16384", "--out", out} << "the maximum is 4096x4096";
        QTest::newRow("report 8192x8192") << QStringList{"report", "--size", "8192x8192", "--out", m_dir.filePath("never")}
                                          << "the maximum is 3840x2160";
        QTest::newRow("render 16384x16384") << QStringList{"render", "--size", "16384x16384", "--out", out} << "the maximum is 8192x8192";
        QTest::newRow("bench 9000x10") << QStringList{"bench", "--size", "9000x10"} << "the maximum is 8192x8192";
    }

    void sizesOutsideACommandsLimitsAreRefused()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, mentions);
        const Run r = shadowlab(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--size") && r.err.contains(mentions), qPrintable(r.err));
        QVERIFY2(r.ms < 15000, qPrintable(QString("took %1 ms").arg(r.ms)));
        QVERIFY(!QFile::exists(m_dir.filePath("never.png")) && !QFile::exists(m_dir.filePath("never")));
    }

    void screenshotAtTheNamedMinimumWorks_data()
    {
        QTest::addColumn<bool>("compare");
        QTest::newRow("single") << false;
        QTest::newRow("compare") << true;
    }

    void screenshotAtTheNamedMinimumWorks()
    {
        QFETCH(bool, compare);
        const QString out = m_dir.filePath(compare ? "minimum-compare.png" : "minimum.png");
        QStringList arguments{"screenshot", "--size", "1x1", "--out", out};
        if (compare)
            arguments << "--compare";
        const Run refused = shadowlab(arguments);
        const QRegularExpressionMatch minimum = QRegularExpression("the minimum is (\\d+)x(\\d+)").match(refused.err);
        QVERIFY2(minimum.hasMatch(), qPrintable(refused.err));
        arguments[2] = minimum.captured(1) + "x" + minimum.captured(2);
        const Run r = shadowlab(arguments);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(QImage(out).size(), QSize(minimum.captured(1).toInt(), minimum.captured(2).toInt()));
    }

    // --- version and platform --------------------------------------------------------------

    void versionIsPrinted_data()
    {
        QTest::addColumn<QString>("flag");
        QTest::newRow("--version") << "--version";
        QTest::newRow("-v") << "-v";
    }

    void versionIsPrinted()
    {
        QFETCH(QString, flag);
        const Run r = shadowlab({flag});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith(QStringLiteral("shadowlab " SHADOWLAB_VERSION "\n")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("\nLicence: MIT ")) && r.out.contains("NO WARRANTY"), qPrintable(r.out));
    }

    void unknownPlatformIsAClearError_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("environment");
        QTest::newRow("-platform bogus") << QStringList{"-platform", "bogus"} << QString();
        QTest::newRow("-platform bogus render") << QStringList{"-platform", "bogus", "render", "--out", m_dir.filePath("never.png")} << QString();
        QTest::newRow("QT_QPA_PLATFORM=bogus") << QStringList{"render", "--out", m_dir.filePath("never.png")} << "bogus";
        QTest::newRow("-platform xcb with no display") << QStringList{"-platform", "xcb", "render", "--out", m_dir.filePath("never.png")}
                                                       << QString();
    }

    void unknownPlatformIsAClearError()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, environment);
        Options options;
        if (!environment.isEmpty())
            options.env["QT_QPA_PLATFORM"] = environment;
        options.env["DISPLAY"] = std::nullopt;
        options.env["WAYLAND_DISPLAY"] = std::nullopt;
        const Run r = shadowlab(arguments, options);
        QCOMPARE(r.exitCode, 2);
        if (arguments.contains("xcb"))
            QVERIFY2(r.err.contains("'xcb' needs a display"), qPrintable(r.err));
        else
            QVERIFY2(r.err.contains("no Qt platform 'bogus'") && r.err.contains("egl"), qPrintable(r.err));
        QVERIFY(!QFile::exists(m_dir.filePath("never.png")));
    }

    void headlessBackendIsChosenWithNoDisplay_data()
    {
        QTest::addColumn<std::optional<QString>>("platform");
        QTest::addColumn<std::optional<QString>>("forced");
        QTest::addColumn<QString>("backend");
        // No display and nothing asked for: the headless platform, EGL first.
        QTest::newRow("nothing set") << std::optional<QString>() << std::optional<QString>() << "egl-surfaceless";
        QTest::newRow("egl") << std::optional<QString>("egl") << std::optional<QString>() << "egl-surfaceless";
        QTest::newRow("egl device") << std::optional<QString>("egl") << std::optional<QString>() << "egl-device";
#ifdef SHADOWLAB_HAVE_OSMESA
        QTest::newRow("SHADOWLAB_HEADLESS=osmesa") << std::optional<QString>() << std::optional<QString>("osmesa") << "osmesa";
        QTest::newRow("osmesa") << std::optional<QString>("osmesa") << std::optional<QString>() << "osmesa";
#endif
    }

    void headlessBackendIsChosenWithNoDisplay()
    {
        QFETCH(std::optional<QString>, platform);
        QFETCH(std::optional<QString>, forced);
        QFETCH(QString, backend);
        Options options;
        options.env["DISPLAY"] = std::nullopt;
        options.env["WAYLAND_DISPLAY"] = std::nullopt;
        options.env["QT_QPA_PLATFORM"] = platform;
        options.env["SHADOWLAB_HEADLESS"] = forced;
        // The EGL device path (a GPU with no display) is taken where surfaceless Mesa is
        // missing; Mesa's software device stands in for the GPU here.
        options.env["SHADOWLAB_EGL_PLATFORM"] = backend == u"egl-device" ? std::optional<QString>("device") : std::nullopt;
        const QString out = m_dir.filePath("backend-" + backend + ".png");
        const Run r = shadowlab({"render", "--size", "96x64", "--out", out}, options);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("headless platform: " + backend + ", llvmpipe"), qPrintable(r.out));
        const QImage image(out);
        QCOMPARE(image.size(), QSize(96, 64));
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 4)
            for (int x = 0; x < image.width(); x += 4)
                colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 10); // a scene, not a cleared buffer
    }
};

QTEST_GUILESS_MAIN(TestCliFiles)
#include "tst_CliFiles.moc"
