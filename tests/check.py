"""Minimal helpers for Python test programs (protocol of tests/run_tests.py)."""
import math
import os
import time


def check(name, cond, detail=""):
    """Print `ok <name>` or `not ok <name> - <detail>`; return cond."""
    if cond:
        print(f"ok {name}", flush=True)
    else:
        print(f"not ok {name} - {detail}", flush=True)
    return bool(cond)


def approx(a, b, rel=0.0, abs=0.0):
    """True when |a - b| <= max(rel * max(|a|, |b|), abs)."""
    return math.isclose(a, b, rel_tol=rel, abs_tol=abs)


def check_close(name, value, expected, rel=0.0, abs=0.0):
    """check() that value equals expected within rel/abs tolerance."""
    return check(name, approx(value, expected, rel, abs),
                 f"got {value!r}, expected {expected!r} (rel {rel}, abs {abs})")


def wait_until_claimed(rundir, process, seconds=120):
    """Wait until the Popen `process` holds the run directory rundir
    (autoglue.claim writes its pid into .<dir>.lock beside it), so that a
    second process started next meets the lock however loaded the machine."""
    parent, base = os.path.split(os.path.abspath(rundir))
    lock = os.path.join(parent, f".{base}.lock")
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline and process.poll() is None:
        if os.path.exists(lock):
            with open(lock) as f:
                if f"process {process.pid} " in f.read():
                    return
        time.sleep(0.05)
