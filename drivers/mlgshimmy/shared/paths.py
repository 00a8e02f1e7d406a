"""Where the drivers read and write (no AUTO import: the plot steps and
make's `targets` need none).

Run directories (with each figure's cached result), figures and tables go
under $MLG_RUN_ROOT (default build/), read each time it is asked for, so a
process may set it after importing this module; `make regress` points it
at a private directory so that build/<fig>/ stays as it was.
"""
import os

# the repository: this file is drivers/mlgshimmy/shared/paths.py in it
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
BUILD = os.path.join(ROOT, "build")
# the part of a figure this process computes alone (set by jobs.parts), for
# what is counted per part
PART_ENV = "MLG_PART"


def run_root() -> str:
    """$MLG_RUN_ROOT as an absolute path (default build/)."""
    return os.path.abspath(os.environ.get("MLG_RUN_ROOT", BUILD))


def figures_dir() -> str:
    return os.path.join(run_root(), "figures")


def tables_dir() -> str:
    return os.path.join(run_root(), "tables")


def under_root(*parts: str) -> str:
    """$MLG_RUN_ROOT/<parts...> (not created)."""
    return os.path.join(run_root(), *parts)


def rundir(name: str) -> str:
    """$MLG_RUN_ROOT/<name> (default build/<name>), created if needed.  Not
    claimed here: autoglue.run claims it (locks and empties it) for the
    process that runs AUTO in it, while others may read its finished runs."""
    path = under_root(name)
    os.makedirs(path, exist_ok=True)
    return path
