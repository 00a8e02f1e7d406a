"""Helpers shared by the Python tests (plain functions; pytest finds the
tests themselves)."""
import os
import time


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
