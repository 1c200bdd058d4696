#pragma once

#include <QObject>

class QSocketNotifier;

namespace shadowlab {

// While one lives, a SIGTERM (a logout, a shutdown, `kill`), SIGINT (Ctrl+C in the terminal that
// started the explorer) or SIGHUP (that terminal closed) closes the windows as the user would
// close them: the main window saves the session and marks it as ended, a dialog left open is
// rejected, and the last window closed ends the event loop with exit code 0. The next start
// offers no restore of a "crashed" session. The same signal again while closing stops the
// process at once, as the signal's default does; another one is ignored (a logout sends SIGTERM
// and SIGHUP together). The handler itself only writes the signal's
// number to a socket, which the event loop reads (Qt's "Calling Qt Functions From Unix Signal
// Handlers"). A signal the process was started ignoring (nohup) stays ignored. One at a time; the
// previous handlers come back when it is destroyed.
class StopSignals : public QObject {
    Q_OBJECT

public:
    StopSignals();
    ~StopSignals() override;
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

signals:
    // The signal that asked for the stop, before the window closes.
    void stopping(int signal);

private:
    void readSignal();

    int m_sockets[2] = {-1, -1};
    QSocketNotifier* m_notifier = nullptr;
};

} // namespace shadowlab
