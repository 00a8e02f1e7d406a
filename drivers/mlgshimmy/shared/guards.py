"""The CPU guards of the AUTO runs known to stall (autoglue.run(time_limit=...):
Fig. 11's FOLD_TIME_LIMIT, shared.torus's CURVE_TIME_LIMIT, 120 s each),
scaled by MLG_CPU_GUARD_SCALE (default 1, so the guards and the figures stay
as they are; 2 or 3 on nodes that are slower per core, docs/cluster.md),
read and checked here only, at autosession.init() and at each guarded run.
A guard counts CPU, not wall, time."""
import math
import os
import signal
from typing import Optional

from mlgshimmy.shared import children

CPU_GUARD_SCALE_ENV = "MLG_CPU_GUARD_SCALE"


class BadSetting(ValueError):
    """An environment setting of the runs that is not valid (named)."""


def cpu_guard_scale() -> float:
    """MLG_CPU_GUARD_SCALE, checked: the factor on every CPU guard (1 unless
    set)."""
    text = os.environ.get(CPU_GUARD_SCALE_ENV, "").strip()
    if not text:
        return 1.0
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and 0.1 <= value <= 1000):
        raise BadSetting(f"{CPU_GUARD_SCALE_ENV}={text!r} must be a number from 0.1 to 1000 "
                         "(the factor on the 120 s CPU guards of the AUTO runs that may "
                         "stall; 2 or 3 for slow nodes, docs/cluster.md)")
    return value


def cpu_guard(seconds: Optional[float]) -> Optional[float]:
    """A CPU guard of `seconds` (None: none) times MLG_CPU_GUARD_SCALE."""
    return None if seconds is None else seconds * cpu_guard_scale()


def _cpu_seconds(pid):
    """CPU time (user + system) a process has used, from /proc/<pid>/stat."""
    with open(f"/proc/{pid}/stat") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


class CPULimit:
    """While active, kills this process's children (the AUTO executable) once
    one has used `seconds` of CPU time (None: no limit).  A stall guard on
    CPU, not wall, time: a loaded machine must not cut short a run that an
    idle one finishes, or the figure would depend on the load."""

    def __init__(self, seconds):
        self.seconds, self.fired = seconds, False

    def __enter__(self):
        if self.seconds:
            signal.signal(signal.SIGALRM, self._check)
            signal.setitimer(signal.ITIMER_REAL, 1.0, 1.0)
        return self

    def __exit__(self, *exc):
        if self.seconds:
            signal.setitimer(signal.ITIMER_REAL, 0)

    def _check(self, signum, frame):
        for pid in children.of_this_process():
            try:
                if _cpu_seconds(pid) > self.seconds:
                    os.kill(pid, signal.SIGKILL)
                    self.fired = True
            except (OSError, ValueError, IndexError):
                continue
