#include "InputFile.h"

#include "MessageText.h"
#include "SettingsError.h"

#include <QFile>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shadowlab {

namespace {

// Closes the descriptor on every way out.
class Descriptor {
public:
    explicit Descriptor(int fd) : m_fd(fd) {}
    ~Descriptor()
    {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return m_fd; }

private:
    int m_fd;
};

} // namespace

QByteArray readInputFile(const QString& path, const QString& what)
{
    const QString name = displayText(path);
    auto fail = [&](const QString& reason) { return SettingsError(QString(), QStringLiteral("cannot read %1 '%2': %3").arg(what, name, reason)); };
    if (path.isEmpty())
        throw SettingsError(QString(), QStringLiteral("%1: no file name given").arg(what));

    // Non-blocking, so opening a FIFO that has no writer returns at once instead of hanging.
    const Descriptor fd(::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (fd.get() < 0)
        throw fail(QString::fromLocal8Bit(std::strerror(errno)));
    struct stat info {};
    if (::fstat(fd.get(), &info) != 0)
        throw fail(QString::fromLocal8Bit(std::strerror(errno)));
    if (S_ISDIR(info.st_mode))
        throw fail(QStringLiteral("it is a folder"));
    if (S_ISREG(info.st_mode) && info.st_size > kMaxInputFileBytes)
        throw fail(QStringLiteral("it holds %1 bytes, more than the limit of %2 (1 MiB)").arg(info.st_size).arg(kMaxInputFileBytes));

    QByteArray bytes;
    char chunk[65536];
    for (;;) {
        const ssize_t n = ::read(fd.get(), chunk, sizeof chunk);
        if (n > 0) {
            if (bytes.size() + n > kMaxInputFileBytes)
                throw fail(QStringLiteral("it holds more than the limit of %1 bytes (1 MiB)").arg(kMaxInputFileBytes));
            bytes.append(chunk, qsizetype(n));
            continue;
        }
        if (n == 0) {
            // End of file; a FIFO whose writer has not opened it yet also reads as empty.
            if (bytes.isEmpty() && S_ISFIFO(info.st_mode)) {
                struct pollfd waiting { fd.get(), POLLIN, 0 };
                const int ready = ::poll(&waiting, 1, kInputWaitMs);
                if (ready == 0)
                    throw fail(QStringLiteral("nothing arrived within %1 s; is anything writing to it?").arg(kInputWaitMs / 1000));
                if (ready > 0 && (waiting.revents & POLLIN))
                    continue;
            }
            return bytes;
        }
        if (errno == EINTR)
            continue;
        if (errno == EAGAIN || errno == EWOULDBLOCK) {
            struct pollfd waiting { fd.get(), POLLIN, 0 };
            const int ready = ::poll(&waiting, 1, kInputWaitMs);
            if (ready == 0)
                throw fail(QStringLiteral("nothing arrived within %1 s; is anything writing to it?").arg(kInputWaitMs / 1000));
            if (ready < 0 && errno != EINTR)
                throw fail(QString::fromLocal8Bit(std::strerror(errno)));
            continue;
        }
        throw fail(QString::fromLocal8Bit(std::strerror(errno)));
    }
}

} // namespace shadowlab
