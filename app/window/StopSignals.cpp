#include "StopSignals.h"

#include <QApplication>
#include <QSocketNotifier>

#include <array>
#include <cerrno>
#include <csignal>
#include <stdexcept>

#include <sys/socket.h>
#include <unistd.h>

namespace shadowlab {

namespace {

constexpr std::array kStopSignals{SIGTERM, SIGINT, SIGHUP};

// What the handler may touch: a descriptor and the signal being handled, nothing of Qt's.
volatile std::sig_atomic_t g_writeSocket = -1;
volatile std::sig_atomic_t g_stopping = 0;      // the first signal's number while closing
struct sigaction g_previous[std::size(kStopSignals)];
bool g_installed[std::size(kStopSignals)] = {};

extern "C" void onStopSignal(int signal)
{
    if (g_stopping == signal) {
        // The same signal again while closing (the close hangs, or Ctrl+C pressed twice): stop
        // now. Another signal is not a second request: a logout sends SIGTERM and SIGHUP at once.
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    if (g_stopping)
        return;
    g_stopping = signal;
    const int saved = errno;
    const char number = char(signal);
    [[maybe_unused]] const ssize_t written = ::write(g_writeSocket, &number, 1);
    errno = saved;
}

} // namespace

StopSignals::StopSignals()
{
    if (g_writeSocket >= 0)
        throw std::logic_error("one StopSignals at a time");
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, m_sockets) != 0)
        throw std::runtime_error("cannot make the socket pair that stop signals are passed through");
    g_writeSocket = m_sockets[0];
    g_stopping = 0;
    m_notifier = new QSocketNotifier(m_sockets[1], QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &StopSignals::readSignal);
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    for (int signal : kStopSignals)
        sigaddset(&action.sa_mask, signal);    // one handler at a time
    action.sa_flags = SA_RESTART;
    for (std::size_t i = 0; i < kStopSignals.size(); ++i) {
        ::sigaction(kStopSignals[i], nullptr, &g_previous[i]);
        // A signal the explorer was started ignoring stays ignored: `nohup` asks for it with
        // SIGHUP, and a shell without job control with SIGINT for what it runs in the background.
        g_installed[i] = g_previous[i].sa_handler != SIG_IGN;
        if (g_installed[i])
            ::sigaction(kStopSignals[i], &action, nullptr);
    }
}

StopSignals::~StopSignals()
{
    for (std::size_t i = 0; i < kStopSignals.size(); ++i) {
        if (g_installed[i])
            ::sigaction(kStopSignals[i], &g_previous[i], nullptr);
    }
    g_writeSocket = -1;
    delete m_notifier;     // before the descriptor it watches
    ::close(m_sockets[0]);
    ::close(m_sockets[1]);
}

void StopSignals::readSignal()
{
    char number = 0;
    if (::read(m_sockets[1], &number, 1) != 1)
        return;
    m_notifier->setEnabled(false);
    emit stopping(int(number));
    // As the user closing them: the main window's closeEvent saves the session and stops the
    // import worker; the last window closed ends exec() with 0.
    QApplication::closeAllWindows();
}

} // namespace shadowlab
