#include "IsolatedImport.h"

#include "ImportPayload.h"
#include "ModelImporter.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QFile>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLocale>
#include <QProcess>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>

#include <fcntl.h>

#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace shadowlab {

namespace {

constexpr int kPollMs = 20;             // how soon a cancel or an overrun is noticed
constexpr int kStartTimeoutMs = 10000;
constexpr auto kWorkerName = "shadowlab-import-worker";

// What the worker's environment keeps: enough to find its libraries and Qt's image plugins.
QProcessEnvironment workerEnvironment([[maybe_unused]] const ImportLimits& limits)
{
    const QProcessEnvironment parent = QProcessEnvironment::systemEnvironment();
    QProcessEnvironment env;
    for (const char* name : {"PATH", "LANG", "LC_ALL", "LD_LIBRARY_PATH", "QT_PLUGIN_PATH", "TMPDIR", "ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS"}) {
        const QString key = QString::fromLatin1(name);
        if (parent.contains(key))
            env.insert(key, parent.value(key));
    }
#if defined(__SANITIZE_ADDRESS__)
    // A sanitizer build of the worker dies as a release build does, so that the parent sees
    // the same death and says the same thing:
    // - a fault is left to the kernel (handle_segv=0 and the like), not caught, reported and
    //   turned into exit code 1: the parent names the signal;
    // - AddressSanitizer reserves terabytes of address space, so the limit on it (RLIMIT_AS)
    //   cannot apply. Its limit on resident memory stands in: past it, malloc returns null
    //   (allocator_may_return_null), and an allocation that cannot return null (operator new)
    //   is reported and aborts (abort_on_error) instead of exiting with 1. So a worker over the
    //   limit dies of SIGABRT, "crashed (signal 6)", where a release build would mostly refuse
    //   with "needs more memory than the import memory limit"; either way nothing is changed.
    // Its reports still reach the test log: readProgress() passes them on.
    env.insert(QStringLiteral("ASAN_OPTIONS"),
               env.value(QStringLiteral("ASAN_OPTIONS"))
                   + QStringLiteral(":handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_sigill=0:handle_abort=0:abort_on_error=1"
                                    ":allocator_may_return_null=1:soft_rss_limit_mb=%1")
                         .arg(limits.memoryMiB));
#endif
    return env;
}

QString signalName(int signal)
{
    const char* description = strsignal(signal);
    return description ? QString::fromLocal8Bit(description).toLower() : QStringLiteral("unknown signal");
}

// Progress lines on the worker's standard error: "progress 0.42".
void readProgress(QProcess& process, QByteArray& pending, const ImportControl& control)
{
    pending += process.readAllStandardError();
    if (pending.size() > (1 << 16))
        pending = pending.right(1 << 12);   // a chatty worker cannot grow this
    qsizetype newline;
    while ((newline = pending.indexOf('\n')) >= 0) {
        const QByteArray line = pending.left(newline).trimmed();
        pending.remove(0, newline + 1);
#if defined(__SANITIZE_ADDRESS__)
        if (!line.startsWith("progress "))
            std::fprintf(stderr, "import worker: %s\n", line.constData());   // a sanitizer's report, into the test's log
#endif
        if (!control.progress || !line.startsWith("progress "))
            continue;
        bool ok = false;
        const double fraction = line.mid(9).toDouble(&ok);
        if (ok && std::isfinite(fraction))
            control.progress(std::clamp(fraction, 0.0, 1.0));
    }
}

constexpr int kAnswerFd = 3;

// Above the low descriptors, so that dup2() to kAnswerFd in the child always makes a copy
// (dup2 onto itself would keep close-on-exec set).
int openAnswerFile()
{
    const int fd = memfd_create("shadowlab-import-answer", MFD_CLOEXEC | MFD_ALLOW_SEALING);
    if (fd < 0)
        return fd;
    const int moved = fcntl(fd, F_DUPFD_CLOEXEC, 10);
    close(fd);
    return moved;
}

// An anonymous file in memory, closed on exec (the worker gets a copy at kAnswerFd); its
// contents are mapped, not copied, when the worker is done.
struct AnswerFile {
    int fd = openAnswerFile();
    void* mapping = nullptr;
    std::size_t size = 0;

    AnswerFile() = default;
    AnswerFile(const AnswerFile&) = delete;
    AnswerFile& operator=(const AnswerFile&) = delete;
    ~AnswerFile()
    {
        if (mapping)
            munmap(mapping, size);
        if (fd >= 0)
            close(fd);
    }
    // The bytes the worker wrote, valid while this lives; empty when there are none.
    QByteArray contents(qint64 limit)
    {
        // Sealed first: nothing the worker left behind can shrink the file under the mapping
        // (a read past its end would be SIGBUS here) or change it while it is decoded.
        struct stat info {};
        if (mapping || fcntl(fd, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_WRITE | F_SEAL_SEAL) != 0
            || fstat(fd, &info) != 0 || info.st_size <= 0 || info.st_size > limit)
            return QByteArray();
        size = std::size_t(info.st_size);
        mapping = mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);   // one fault, not one a page
        if (mapping == MAP_FAILED) {
            mapping = nullptr;
            return QByteArray();
        }
        return QByteArray::fromRawData(static_cast<const char*>(mapping), qsizetype(size));
    }
};

// Runs in the worker between fork and exec, so only async-signal-safe calls: its limits, its own
// process group (stopping it stops whatever it started), death with its parent, and the answer
// file at kAnswerFd.
void limitWorker(const ImportLimits& limits, qint64 outputLimit, int answerFd)
{
    const auto cap = [](int resource, rlim_t soft, rlim_t hard) {
        const rlimit limit{soft, hard};
        setrlimit(resource, &limit);
    };
#if !defined(__SANITIZE_ADDRESS__)
    cap(RLIMIT_AS, rlim_t(limits.memoryMiB) << 20, rlim_t(limits.memoryMiB) << 20);
#endif
    const rlim_t cpu = rlim_t(std::ceil(limits.timeSeconds)) + 2;
    cap(RLIMIT_CPU, cpu, cpu + 1);     // SIGXCPU at the soft limit, SIGKILL a second later
    cap(RLIMIT_CORE, 0, 0);
    cap(RLIMIT_FSIZE, rlim_t(outputLimit), rlim_t(outputLimit));     // its answer is the one file it writes
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    setpgid(0, 0);
    if (dup2(answerFd, kAnswerFd) < 0)    // dup2 clears close-on-exec on the copy only
        _exit(71);
}

// What a worker killed by `signal` tells the user.
SceneFileError deathRefusal(const QString& path, int signal, const ImportLimits& limits)
{
    if (signal == SIGXFSZ)
        return SceneFileError(path, QStringLiteral("the importer sent back more than %1 MiB, the import output limit, and was stopped; "
                                                   "nothing was changed").arg(limits.outputMiB));
    if (signal == SIGXCPU)
        return SceneFileError(path, QStringLiteral("the importer used more than %1 s of processor time on it and was stopped; the file is "
                                                   "damaged or very large; nothing was changed").arg(std::ceil(limits.timeSeconds) + 2),
                              SceneFileError::Limit::Time);
    return SceneFileError(path, QStringLiteral("the importer crashed reading it (signal %1, %2): the file is damaged or not what its name "
                                               "says; nothing was changed").arg(signal).arg(signalName(signal)));
}

QByteArray boundIdentity(const QString& path, const QByteArray& claimed)
{
    QCryptographicHash hash(QCryptographicHash::Sha256);
    QFile file(path);
    if (file.open(QIODevice::ReadOnly))
        hash.addData(&file);
    hash.addData(claimed);
    return hash.result().toHex();
}

// Where this build put the worker, for the programs of the build tree (the tests' executables
// sit apart from it). An installed program never reaches back into the tree it was built in,
// so an install that misplaces the worker fails where it is tested, not on a user's machine.
QString buildTreeWorker()
{
#ifdef SHADOWLAB_IMPORT_WORKER_BUILD
    // Without a QCoreApplication there is no program path to ask; every program of ours has one.
    const QString buildDir = QFileInfo(QStringLiteral(SHADOWLAB_BUILD_DIR)).canonicalFilePath();
    const bool inBuildTree = !QCoreApplication::instance()
        || (!buildDir.isEmpty() && (QCoreApplication::applicationDirPath() + u'/').startsWith(buildDir + u'/'));
    if (inBuildTree)
        return QStringLiteral(SHADOWLAB_IMPORT_WORKER_BUILD);
#endif
    return QString();
}

// Starts the worker on `path`, under `control`'s limits, with `answerFd` as its fd 3.
void startWorker(QProcess& process, const QString& program, const QString& path, const ImportControl& control, int answerFd)
{
    const ImportLimits limits = control.limits;
    const qint64 outputLimit = qint64(limits.outputMiB) << 20;
    process.setProgram(program);
    process.setArguments({QFileInfo(path).absoluteFilePath(), QStringLiteral("--answer-fd"), QString::number(kAnswerFd)});
    process.setProcessEnvironment(workerEnvironment(limits));
    process.setStandardInputFile(QProcess::nullDevice());
    process.setStandardOutputFile(QProcess::nullDevice());
    process.setWorkingDirectory(QDir::tempPath());
    process.setChildProcessModifier([limits, outputLimit, answerFd] { limitWorker(limits, outputLimit, answerFd); });
    process.start(QIODevice::ReadOnly);
    if (!process.waitForStarted(kStartTimeoutMs))
        throw SceneFileError(path, QStringLiteral("cannot be read: the import worker did not start (%1); reinstall ShadowLab").arg(process.errorString()));
}

// Waits for the worker, passing on its progress; stops it (and whatever it started) when the
// user cancels or it runs past the time limit.
void waitForWorker(QProcess& process, const QString& path, const ImportControl& control)
{
    const qint64 timeLimitMs = qint64(control.limits.timeSeconds * 1000.0);
    QElapsedTimer clock;
    clock.start();
    QByteArray pendingProgress;
    const qint64 pid = process.processId();
    const auto stop = [&process, pid] {
        ::kill(pid_t(-pid), SIGKILL);
        process.kill();
        process.waitForFinished(-1);
    };
    while (!process.waitForFinished(kPollMs)) {
        readProgress(process, pendingProgress, control);
        if (control.cancel && control.cancel->load()) {
            stop();
            throw ImportCancelled(path);
        }
        if (clock.elapsed() > timeLimitMs) {
            stop();
            throw SceneFileError(path, QStringLiteral("took longer than %1 s to read, the import time limit, and was stopped; the file is "
                                                      "damaged or very large — raise the time limit if it is only large; nothing was changed")
                                           .arg(control.limits.timeSeconds),
                                 SceneFileError::Limit::Time);
        }
        if (process.state() == QProcess::NotRunning)
            break;
    }
    readProgress(process, pendingProgress, control);
    ::kill(pid_t(-pid), SIGKILL);   // anything the worker left running in its group
}

// The scene in the finished worker's answer, or the refusal that says why there is none.
Scene sceneFromAnswer(const QString& path, const QProcess& process, AnswerFile& answerFile, const ImportLimits& limits)
{
    if (process.exitStatus() == QProcess::CrashExit)
        throw deathRefusal(path, process.exitCode(), limits);   // the exit code of a crash is its signal
    const QByteArray answer = answerFile.contents(qint64(limits.outputMiB) << 20);
    if (process.exitCode() != 0 && answer.isEmpty())
        throw SceneFileError(path, QStringLiteral("the importer stopped without an answer (exit code %1): the file is damaged or not what "
                                                  "its name says; nothing was changed").arg(process.exitCode()));
    if (answer.isEmpty())
        throw SceneFileError(path, QStringLiteral("the importer stopped without an answer; the file is damaged or not what its name says; "
                                                  "nothing was changed"));
    ImportReply reply = decodeImportReply(answer, path);
    if (reply.kind == ImportReplyKind::Scene) {
        // The name and the cache key are the parent's to say, not the answer's: the file's own
        // path, and the worker's hash of what it read bound to the parent's hash of the file.
        reply.scene.name = QFileInfo(path).absoluteFilePath();
        reply.scene.identity = boundIdentity(path, reply.scene.identity);
    }
    if (reply.kind == ImportReplyKind::OutOfMemory)
        throw SceneFileError(path, QStringLiteral("needs more memory to read than the import memory limit of %1 MiB (%2); the file is "
                                                  "damaged or very large — raise the memory limit if it is only large; nothing was changed")
                                       .arg(limits.memoryMiB).arg(reply.message),
                             SceneFileError::Limit::Memory);
    if (reply.kind == ImportReplyKind::Refusal)
        throw SceneFileError(path, reply.message);
    return std::move(reply.scene);
}

} // namespace

QString importWorkerProgram()
{
    if (const QString overridden = qEnvironmentVariable("SHADOWLAB_IMPORT_WORKER"); !overridden.isEmpty())
        return overridden;  // checked, and named in the refusal, where it is started
    QStringList candidates;
    if (QCoreApplication::instance()) {
        const QDir dir(QCoreApplication::applicationDirPath());
        candidates << dir.filePath(QLatin1String(kWorkerName)) << dir.filePath(QStringLiteral("../libexec/shadowlab/") + QLatin1String(kWorkerName));
    }
    if (const QString built = buildTreeWorker(); !built.isEmpty())
        candidates << built;
    for (const QString& candidate : candidates) {
        if (QFileInfo(candidate).isExecutable())
            return QFileInfo(candidate).absoluteFilePath();
    }
    return QString();
}

std::optional<std::size_t> statedFaceCount(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;    // the worker says why it cannot be read
    const QByteArray head = file.read(64 * 1024);
    const QByteArray lower = QFileInfo(path).suffix().toLower().toLatin1();
    // PLY: "element face N" in the text header, for ASCII and binary bodies alike.
    if (head.startsWith("ply")) {
        const qsizetype end = head.indexOf("end_header");
        for (const QByteArray& line : head.left(end < 0 ? head.size() : end).split('\n')) {
            const QList<QByteArray> words = line.simplified().split(' ');
            if (words.size() == 3 && words[0] == "element" && words[1] == "face") {
                bool ok = false;
                const qulonglong n = words[2].toULongLong(&ok);
                return ok ? std::optional(std::size_t(n)) : std::nullopt;
            }
        }
        return std::nullopt;
    }
    // OFF: "OFF", then "vertices faces edges", on the same line or the first line that is
    // not a comment; three whole numbers, or no count at all.
    if (head.startsWith("OFF")) {
        QList<QByteArray> lines = head.split('\n');
        lines[0] = lines[0].mid(3);
        for (const QByteArray& line : std::as_const(lines)) {
            const QByteArray text = line.simplified();
            if (text.isEmpty() || text.startsWith('#'))
                continue;
            const QList<QByteArray> words = text.split(' ');
            bool ok[3] = {false, false, false};
            if (words.size() >= 3) {
                words[0].toULongLong(&ok[0]);
                words[2].toULongLong(&ok[2]);
            }
            const qulonglong n = words.value(1).toULongLong(&ok[1]);
            return ok[0] && ok[1] && ok[2] ? std::optional(std::size_t(n)) : std::nullopt;
        }
        return std::nullopt;
    }
    // Binary STL: an 80-byte header, a 32-bit count, 50 bytes a triangle; only where the size
    // agrees, as an ASCII STL may begin with any 84 bytes.
    if (lower == "stl" && head.size() >= 84) {
        quint32 n = 0;
        std::memcpy(&n, head.constData() + 80, sizeof n);
        if (quint64(file.size()) == 84 + quint64(n) * 50)
            return std::size_t(n);
    }
    return std::nullopt;
}

Scene importModelIsolated(const QString& path, const ImportControl& control)
{
    control.limits.validate();
    // A count the file's header states is checked before it is read: a file of 10^8 faces is
    // refused at once, not after the worker has spent its time limit on it.
    if (const std::optional<std::size_t> faces = statedFaceCount(path); faces && *faces > kMaxModelTriangles)
        throw SceneFileError(path, QStringLiteral("has %1 faces by its header, more than the %2 triangles ShadowLab loads; decimate it first "
                                                  "(nothing was read, nothing was changed)")
                                       .arg(QLocale(QLocale::English).toString(qulonglong(*faces)), QLocale(QLocale::English).toString(qulonglong(kMaxModelTriangles))));
    const QString program = control.workerProgram.isEmpty() ? importWorkerProgram() : control.workerProgram;
    if (program.isEmpty())
        throw SceneFileError(path, QStringLiteral("cannot be read: the import worker '%1' is missing next to the program; reinstall ShadowLab")
                                       .arg(QLatin1String(kWorkerName)));
    if (!QFileInfo(program).isExecutable())
        throw SceneFileError(path, QStringLiteral("cannot be read: the import worker '%1' is not an executable (check SHADOWLAB_IMPORT_WORKER, "
                                                  "or reinstall ShadowLab)").arg(program));
    // The answer comes back through an anonymous memory file, the worker's fd 3: no copy through a
    // pipe, and the kernel stops the worker (SIGXFSZ) at the output limit.
    AnswerFile answerFile;
    if (answerFile.fd < 0)
        throw SceneFileError(path, QStringLiteral("cannot be read: no memory for the importer's answer (%1)").arg(QString::fromLocal8Bit(strerror(errno))));
    QProcess process;
    startWorker(process, program, path, control, answerFile.fd);
    waitForWorker(process, path, control);
    return sceneFromAnswer(path, process, answerFile, control.limits);
}

} // namespace shadowlab
