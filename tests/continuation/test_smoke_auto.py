"""Smoke test of the whole chain: Makefile-built model with a static library,
run by AUTO-07p through drivers/mlgshimmy/shared/autoglue.py.

The model (tests/smoke/smoke.c) is a Hopf normal form whose Hopf point
p = sqrt(2) comes from tests/smoke/shift.c, linked as a static library. Past
it the orbits are circles of radius sqrt(p - sqrt(2)) with period 2 pi.
"""
import math
import os

import pytest

import helpers
from mlgshimmy.shared import autoglue, autosession, diagrams, runerror
from mlgshimmy.shared import paths

HERE = os.path.join(helpers.ROOT, "tests")
MODEL = os.path.join(paths.BUILD, "tests", "smoke", "smoke")
CONSTANTS = os.path.join(HERE, "smoke", "c.smoke")
HOPF = math.sqrt(2.0)


@pytest.fixture(scope="module")
def equilibria(tmp_path_factory):
    """(run directory, the eq diagram, mtime of the model .exe before the run)."""
    rundir = str(tmp_path_factory.mktemp("smoke-run"))
    built = os.stat(MODEL + ".exe").st_mtime_ns
    eq = autoglue.run(rundir, "eq", constants=CONSTANTS, e=MODEL, expect=["HB"])
    return rundir, eq, built


@pytest.fixture(scope="module")
def uz(equilibria):
    """The orbit at the UZ point p = sqrt(2) + 1 of the branch from the HB."""
    hb = equilibria[1]("HB1")
    po = autoglue.run(equilibria[0], "po", data=hb, constants=CONSTANTS, e=MODEL,
                      expect=["UZ"], IRS=hb["LAB"], IPS=2, ICP=["p", "period", "xmax"],
                      UZSTOP={"p": HOPF + 1.0})
    return po("UZ1")


def raises_run_error(func):
    try:
        func()
    except runerror.RunError as exc:
        return str(exc)
    return None


def test_equilibria_hb_at_sqrt_2(equilibria):
    """The run ends without MX and finds the HB (autoglue.run raises
    otherwise), at p = sqrt(2)."""
    helpers.assert_close(equilibria[1]("HB1")["p"], HOPF, abs=1e-6)


def test_auto_used_the_makefile_built_executable(equilibria):
    assert os.stat(MODEL + ".exe").st_mtime_ns == equilibria[2], \
        f"{MODEL}.exe was rebuilt by AUTO"


def test_autoglue_detects_a_missing_lp(equilibria):
    message = raises_run_error(lambda: diagrams.check_diagram(equilibria[1], "eq", ["LP"]))
    assert message and "LP" in message, f"RunError message: {message!r}"


def test_autoglue_detects_mx(equilibria):
    """b.eq with the UZ point (label 3) retyped as MX (type -9)."""
    rundir = equilibria[0]
    lines = []
    with open(os.path.join(rundir, "b.eq")) as f:
        for line in f:
            fields = line.split()
            if len(fields) > 4 and fields[0] != "0" and fields[3] == "3":
                fields[2] = "-9"
                line = " ".join(fields) + "\n"
            lines.append(line)
    doctored = os.path.join(rundir, "b.eq-mx")
    with open(doctored, "w") as f:
        f.writelines(lines)
    bd = autosession.init().bifDiag.bifDiag(doctored)
    message = raises_run_error(lambda: diagrams.check_diagram(bd, "eq-mx"))
    assert message and "MX" in message and "label 3" in message, \
        f"RunError message: {message!r}"


def test_orbits_uz_at_p(uz):
    """The orbit run ends without MX and finds the UZ (autoglue.run raises
    otherwise), at p = sqrt(2) + 1."""
    helpers.assert_close(uz["p"], HOPF + 1.0, abs=1e-6)


def test_orbits_radius_1_at_p_sqrt_2_plus_1(uz):
    # On the circle of radius 1 the L2 norm is exactly the radius; PAR(21)
    # (getp MAX, PVLS) is a maximum over mesh points, so slightly below 1.
    helpers.assert_close(uz["L2-NORM"], 1.0, abs=1e-6)


def test_orbits_pvls_measure_max_x(uz):
    helpers.assert_close(uz["xmax"], 1.0, abs=1e-3)


def test_orbits_period_2_pi(uz):
    helpers.assert_close(uz["period"], 2 * math.pi, abs=1e-5)
