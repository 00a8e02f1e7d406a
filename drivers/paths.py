"""Where the drivers read and write, with no AUTO import (fig06, sweep's
make-time `targets` and the plot steps need none).

Run directories (with each figure's cached result), figures and tables go
under MLG_RUN_ROOT (default build/); `make regress` points it at
build/regress/ so that build/<fig>/ stays as it was.
"""
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build")
RUN_ROOT = os.path.abspath(os.environ.get("MLG_RUN_ROOT", BUILD))
FIGURES_DIR = os.path.join(RUN_ROOT, "figures")
TABLES_DIR = os.path.join(RUN_ROOT, "tables")


def rundir(name):
    """$MLG_RUN_ROOT/<name> (default build/<name>), created if needed.  Not
    claimed here: autoglue.run claims it (locks and empties it) for the
    process that runs AUTO in it, while others may read its finished runs."""
    path = os.path.join(RUN_ROOT, name)
    os.makedirs(path, exist_ok=True)
    return path
