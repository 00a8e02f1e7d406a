"""The one place the tests set the path: pytest itself finds the package
through pyproject.toml (pythonpath); the subprocesses the tests start (the
drivers as `python3 -m`, make) get it here, as make gives it to them."""
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DRIVERS = os.path.join(ROOT, "drivers")

if DRIVERS not in os.environ.get("PYTHONPATH", "").split(os.pathsep):
    os.environ["PYTHONPATH"] = os.pathsep.join(
        [DRIVERS] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p])
os.environ.setdefault("MPLBACKEND", "Agg")
