"""Helpers shared by the Python tests (plain functions; pytest finds the
tests themselves)."""
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
