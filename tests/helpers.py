"""Helpers shared by the Python tests (plain functions; pytest finds the
tests themselves)."""
import math
import os
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def wait_until_claimed(rundir, process, seconds=120):
    """Wait until the Popen `process` holds the run directory rundir
    (rundirs.claim writes its pid into .<dir>.lock beside it), so that a
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


def make_variable(name):
    """A variable the Makefile exports to `make test` (tests/regression/
    regression.mk): from the environment when run by make, else asked of
    make itself, so that pytest run by hand checks the same value."""
    if name in os.environ:
        return os.environ[name]
    proc = subprocess.run(["make", "-s", "--no-print-directory",
                           f"--eval=print-test-variable: ; @echo $({name})",
                           "print-test-variable"], cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 0, f"make cannot print {name}: {proc.stderr.strip()}"
    return proc.stdout.strip()


def assert_close(value, expected, rel=0.0, abs=0.0):
    """The tests' one tolerance check: |value - expected| <= max(rel *
    max(|value|, |expected|), abs), naming both values when it fails."""
    assert math.isclose(value, expected, rel_tol=rel, abs_tol=abs), \
        f"got {value!r}, expected {expected!r} (rel {rel}, abs {abs})"
