#!/usr/bin/env python3
"""The explorer on a real (virtual) display, stopped as a logout, a shutdown, `kill` or Ctrl+C
stop it: SIGTERM, SIGINT and SIGHUP each close it with exit code 0 and its session marked as
ended, so the next start offers no restore (tst_SessionRecovery checks the window side in
process). Then the same start with SIGHUP ignored, as `nohup` starts it: the signal changes
nothing and the explorer keeps running. Usage: stop-signal-test.py SHADOWLAB"""
import configparser
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time


log_path = None  # the explorer's output, shown with a failure


def fail(message):
    if log_path and os.path.exists(log_path):
        print(open(log_path, errors="replace").read()[-6000:], file=sys.stderr)
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def wait_for(predicate, seconds, what):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if predicate():
            return
        time.sleep(0.1)
    fail("waited %d s for %s" % (seconds, what))


def session_running(config):
    """The explorer's marker of a running session, as its QSettings file has it (None before
    the first start wrote it)."""
    path = os.path.join(config, "ShadowLab", "ShadowLab.conf")
    if not os.path.exists(path):
        return None
    parser = configparser.RawConfigParser(strict=False)
    try:
        parser.read(path)
        return parser.get("session", "running", fallback=None)
    except configparser.Error:
        return None     # caught mid-rename


def start_display(work):
    """Xvfb on a free display; returns (process, ":N")."""
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", "1", "-screen", "0", "1600x1000x24", "-nolisten", "tcp"],
                            stdout=subprocess.PIPE, stderr=open(os.path.join(work, "xvfb.log"), "w"))
    line = xvfb.stdout.readline().strip()
    if not line:
        fail("Xvfb did not start: " + open(os.path.join(work, "xvfb.log")).read())
    return xvfb, ":" + line.decode()


running = []     # what to stop however the test ends


def main():
    binary = os.path.abspath(sys.argv[1])
    work = tempfile.mkdtemp(prefix="shadowlab-stop-")
    try:
        xvfb, display = start_display(work)
        running.append(xvfb)
        config = os.path.join(work, "config")
        env = {"PATH": "/usr/bin:/bin", "HOME": os.path.join(work, "home"), "XDG_CONFIG_HOME": config, "LANG": "C.UTF-8",
               "DISPLAY": display, "QT_QPA_PLATFORM": "xcb"}
        for name in ("ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS"):
            if name in os.environ:
                env[name] = os.environ[name]
        # On a sanitizer build the leak check is off for this program: at exit the xcb
        # platform's own stack leaks (libdbus's connection, and allocations of Mesa's GLX driver,
        # unloaded by then, so that no suppression can name it). The window's code is checked for
        # leaks in process on the headless platform (tst_MainWindow, tst_SessionRecovery, ...).
        env["ASAN_OPTIONS"] = (env.get("ASAN_OPTIONS", "") + ":detect_leaks=0").lstrip(":")
        os.makedirs(env["HOME"])

        def start(ignore=None):
            def child():
                # As a desktop starts it, whatever this test was started with (nohup, a shell's
                # background job), and then as `nohup` would where the row asks for it.
                for stop in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
                    signal.signal(stop, signal.SIG_DFL)
                if ignore is not None:
                    signal.signal(ignore, signal.SIG_IGN)
            global log_path
            log_path = os.path.join(work, "explorer.log")
            log = open(log_path, "a")
            explorer = subprocess.Popen([binary], env=env, cwd=work, stdout=log, stderr=log, preexec_fn=child)
            running.append(explorer)
            wait_for(lambda: session_running(config) == "true" or explorer.poll() is not None, 120, "the explorer to start its session")
            if explorer.poll() is not None:
                fail("the explorer stopped by itself with %d: %s" % (explorer.returncode, open(log.name).read()))
            time.sleep(1.0)     # its first frames drawn, the session saved once
            return explorer

        for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
            explorer = start()
            explorer.send_signal(sig)
            try:
                code = explorer.wait(60)
            except subprocess.TimeoutExpired:
                explorer.kill()
                fail("%s did not close the explorer within 60 s" % sig.name)
            if code != 0:
                fail("after %s the explorer exited with %d, not 0 (a negative code is the signal that killed it)" % (sig.name, code))
            if session_running(config) != "false":
                fail("after %s the session is still marked as running: the next start would offer a restore" % sig.name)
            print("%s: closed with exit code 0, the session marked as ended" % sig.name)

        # A logout: SIGTERM and SIGHUP together are one request to close, not a second one.
        explorer = start()
        explorer.send_signal(signal.SIGTERM)
        explorer.send_signal(signal.SIGHUP)
        if explorer.wait(60) != 0 or session_running(config) != "false":
            fail("SIGTERM and SIGHUP together (a logout) did not close the explorer with 0 and its session ended (%d)" % explorer.returncode)
        print("SIGTERM and SIGHUP together: closed with exit code 0, the session marked as ended")

        explorer = start(ignore=signal.SIGHUP)
        explorer.send_signal(signal.SIGHUP)
        time.sleep(2.0)
        if explorer.poll() is not None:
            fail("started ignoring SIGHUP (nohup), the explorer still stopped on it (%d)" % explorer.returncode)
        explorer.send_signal(signal.SIGTERM)
        if explorer.wait(60) != 0:
            fail("the explorer started under nohup did not close with 0 on SIGTERM")
        print("SIGHUP ignored under nohup; SIGTERM then closed it with 0")
        print("PASS")
    finally:
        for process in reversed(running):
            if process.poll() is None:
                process.kill()
                process.wait(10)
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
