"""The child processes of this process (the AUTO executable, the simulator):
listed from /proc, and stopped with this process on SIGTERM or SIGHUP.

Python's default for those signals ends the process at once and leaves its
children running: `make` interrupted while AUTO ran left mlg.exe computing
with nobody to read it.  stop_with_this_process() (autosession.init,
simulator.run) installs a handler that sends the same signal to each child,
then ends this process by that signal as before.
"""
import os
import signal
import threading
from typing import Callable, List

STOPPING = (signal.SIGTERM, signal.SIGHUP)


def living(where: Callable[[List[str]], bool]) -> List[int]:
    """The pids of the living processes (no zombies) whose /proc/<pid>/stat
    fields after the command (state, ppid, pgrp, session, ...) satisfy where."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as stat:
                fields = stat.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if fields[0] != "Z" and where(fields):
            found.append(int(entry))
    return found


def of_this_process() -> List[int]:
    """The pids of this process's living children."""
    return living(lambda fields: int(fields[1]) == os.getpid())


def _stop(signum, frame):
    for pid in of_this_process():
        try:
            os.kill(pid, signum)
        except OSError:
            pass
    signal.signal(signum, signal.SIG_DFL)
    os.kill(os.getpid(), signum)


def stop_with_this_process() -> None:
    """Install the handler for SIGTERM and SIGHUP where they have the default
    action (a signal ignored, as under nohup, or handled otherwise is left
    so).  Only the main thread can set handlers; elsewhere nothing changes."""
    if threading.current_thread() is not threading.main_thread():
        return
    for signum in STOPPING:
        if signal.getsignal(signum) == signal.SIG_DFL:
            signal.signal(signum, _stop)
