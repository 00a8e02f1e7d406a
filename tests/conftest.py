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


import pytest  # noqa: E402


@pytest.fixture(autouse=True, scope="module")
def _claims_stay_in_their_module():
    """A run directory claimed in this process (rundirs.claim) is listed
    in MLG_RUN_CLAIMED for its child processes; a module's claims must not
    reach the next module's subprocesses."""
    before = os.environ.get("MLG_RUN_CLAIMED")
    yield
    if before is None:
        os.environ.pop("MLG_RUN_CLAIMED", None)
    else:
        os.environ["MLG_RUN_CLAIMED"] = before
