"""An interrupted make leaves nothing running (#38): SIGTERM to the top make
of `make regress-fig10` left its sub-make, the driver and mlg.exe running
(bash passes no signal to a child it waits for, and Python's default SIGTERM
ends the driver without its AUTO child).  Each test starts its processes in a
new session and looks for what is left of it in /proc."""
import os
import signal
import subprocess
import sys
import time

import pytest

import helpers
from mlgshimmy.shared import children

ROOT = helpers.ROOT


def session(sid):
    """[(pid, command)] of the living processes of session sid (no zombies)."""
    found = []
    for pid in children.living(lambda fields: int(fields[3]) == sid):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as cmdline:
                command = cmdline.read().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        found.append((pid, command.strip()))
    return found


def until(condition, seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = condition()
        if value:
            return value
        time.sleep(0.1)
    return condition()


@pytest.fixture
def started():
    """Popen in a new session; what is left of each session is killed after."""
    sessions = []

    def start(*args, **kw):
        proc = subprocess.Popen(*args, start_new_session=True, **kw)
        sessions.append(proc.pid)
        return proc
    yield start
    for sid in sessions:
        for pid, _ in session(sid):
            os.kill(pid, signal.SIGKILL)


def test_a_driver_stops_its_child_on_sigterm(started, tmp_path):
    """A driver that has started AUTO (autosession.init installs shared.children's
    handler): its child, here a sleep that never writes (mlg.exe dies of a
    broken pipe only when it next prints), gets the signal too, and the driver
    still ends by it."""
    script = ("import subprocess, sys; from mlgshimmy.shared import autosession; "
              "autosession.init(); child = subprocess.Popen(['sleep', '60']); "
              "print(child.pid, flush=True); child.wait()")
    proc = started([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    child = int(proc.stdout.readline())
    assert [pid for pid, _ in session(proc.pid)] == sorted([proc.pid, child])
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(timeout=10) == -signal.SIGTERM
    assert until(lambda: not session(proc.pid), 5), session(proc.pid)


def test_sigterm_to_make_regress_leaves_nothing_running(started, tmp_path):
    """Fig. 10 (40 s): stopped at its first AUTO run, it cannot have ended by
    itself within the 5 s allowed."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MAKEOVERRIDES")}
    with open(tmp_path / "make.log", "w") as log:
        proc = started(["make", "--no-print-directory", "regress-fig10",
                        f"REGRESS_ROOT={tmp_path}/regress"], cwd=ROOT, env=env,
                       stdout=log, stderr=subprocess.STDOUT)
    running = until(lambda: [c for _, c in session(proc.pid) if c.endswith("mlg.exe")], 120)
    assert running, (tmp_path / "make.log").read_text()[-3000:]
    commands = [c for _, c in session(proc.pid)]
    assert any("-m mlgshimmy.figures.fig10" in c for c in commands), commands
    proc.send_signal(signal.SIGTERM)
    proc.wait(timeout=10)
    left = until(lambda: not session(proc.pid), 5) or session(proc.pid)
    assert left is True, f"left running after SIGTERM to make: {left}"
