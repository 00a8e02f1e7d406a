"""The dependency scan (shared.jobs.depends) needs only the standard library:
the first `make` on a fresh machine runs it before numpy is installed, and
it printed a traceback per figure when run with -m (the package's __init__s
import numpy)."""
import os
import shutil
import subprocess
import sys

import helpers

ROOT = helpers.ROOT
SCRIPT = os.path.join("drivers", "mlgshimmy", "shared", "jobs", "depends.py")
ARGS = ["PYDEPS_fig07", "build/deps/fig07.d", "mlgshimmy.figures.fig07"]


def normal_scan():
    proc = subprocess.run([sys.executable, "-m", "mlgshimmy.shared.jobs.depends", *ARGS],
                          cwd=ROOT, capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "drivers")))
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def test_the_scan_without_site_packages_gives_the_same_files():
    bare = subprocess.run([sys.executable, "-S", "-I", SCRIPT, *ARGS], cwd=ROOT,
                          capture_output=True, text=True)
    assert bare.returncode == 0 and bare.stderr == "", bare.stderr
    assert bare.stdout == normal_scan()
    assert "drivers/mlgshimmy/figures/fig07.py" in bare.stdout
    assert "drivers/mlgshimmy/shared/jobs/cache.py" in bare.stdout


def test_make_writes_the_import_closures_without_numpy(tmp_path):
    """make -n in a fresh copy with a Python that has no site packages (so no
    numpy, as before `make setup`): the .d files are written, no traceback."""
    clone = tmp_path / "repo"
    shutil.copytree(ROOT, clone, ignore=shutil.ignore_patterns("build", ".git", "__pycache__"))
    proc = subprocess.run(["make", "--no-print-directory", "-n", "fig07",
                           f"PYTHON={sys.executable} -S"], cwd=clone, capture_output=True,
                          text=True, env={k: v for k, v in os.environ.items()
                                          if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL",
                                                       "MLG_RUN_ROOT")})
    assert proc.returncode == 0 and "Traceback" not in proc.stderr, proc.stderr[-3000:]
    assert (clone / "build" / "deps" / "fig07.d").read_text() == normal_scan()
