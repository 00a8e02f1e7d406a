"""The side-stay drivers: bad angles are rejected before any AUTO run, with a
message naming the parameter; one sweep job gives the critical speed, and
the mirror image (-rho, -mu) gives the same (docs/model.md 8.5, 8.7).  A
sweep grid with two values of one job or a non-number is rejected naming
SWEEP_RHO/SWEEP_MU, and `make clean` never reads the grid; a bad EOM stops
`make sidestay` naming it.  Two side-stay runs that both need the
rho = mu = 0 runs, the second started while the first holds them: the
second waits for the first and then reuses its cached runs, with the same
numbers; the numbers are in a plain-text table and the eom_terms level is
printed."""
import json
import os
import subprocess
import sys

import pytest

import helpers

ROOT = helpers.ROOT
DRIVERS = os.path.join(ROOT, "drivers")


def driver(module, *args, **env):
    """python3 -m mlgshimmy.<module> args, from the repository root (the
    package found through the PYTHONPATH tests/conftest.py sets), with the
    environment variables env."""
    return subprocess.run([sys.executable, "-m", f"mlgshimmy.{module}", *args], cwd=ROOT,
                          capture_output=True, text=True, env=dict(os.environ, **env))


def test_sidestay_rejects_rho_87_before_auto(tmp_path):
    """A degenerate side-stay (rho = 87 deg) stops the driver before any
    AUTO run, naming the parameter; no run directory is made."""
    proc = driver("studies.sidestay", "--rho", "87", "--mu", "0", MLG_RUN_ROOT=str(tmp_path))
    assert proc.returncode != 0 and "parameters rho = 1.51844" in proc.stderr \
        and "degenerate" in proc.stderr, proc.stderr.strip()
    assert not os.path.exists(tmp_path / "sidestay_rho87_mu0"), os.listdir(tmp_path)


def test_sweep_check_rejects_rho_95_naming_rho():
    proc = driver("studies.sweep", "check", "--rho=0,95", "--mu=0")
    assert proc.returncode != 0 and "parameter rho = 1.65806 rad" in proc.stderr, \
        proc.stderr.strip()


@pytest.mark.parametrize("eom", ["7", "x"])
def test_make_sidestay_with_a_bad_eom_stops_before_any_run_naming_eom(eom):
    proc = subprocess.run(["make", "-n", "sidestay", "RHO=10", "MU=10", f"EOM={eom}"],
                          cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode != 0 and f"EOM={eom} must be 0" in proc.stderr \
        and "mlgshimmy.studies.sidestay" not in proc.stdout, \
        (proc.stdout + proc.stderr).strip()[-300:]


@pytest.mark.parametrize("command", ["jobs", "targets"])
@pytest.mark.parametrize("rho, mu, variable, what", [
    ("10,10.0000001", "0", "SWEEP_RHO", "10 and 10.0000001"),
    # (a value listed twice, "5,-5,5", was refused too until f21800e made two
    # spellings of one value one point; two values of one job name still are)
    ("0", "5,-5,5.0000001", "SWEEP_MU", "5 and 5.0000001"),
    ("0,,10", "0", "SWEEP_RHO", "'' is not a number"),
    ("0", "1,x", "SWEEP_MU", "'x' is not a number")])
def test_sweep_grid_rejected_naming_the_variable(command, rho, mu, variable, what):
    proc = driver("studies.sweep", command, f"--rho={rho}", f"--mu={mu}")
    assert proc.returncode != 0 and not proc.stdout and variable in proc.stderr \
        and what in proc.stderr, (proc.stdout + proc.stderr).strip()


# GNU make before 4.4 (Debian bookworm has 4.3) runs $(shell ...) without the
# variables make exports: mk/jobs.mk passes PYTHONPATH to the grid's
# `targets` itself.  The PYTHONPATH that make test exports and
# tests/conftest.py sets would hide a regression here, so both cases run.
@pytest.mark.parametrize("pythonpath", [
    pytest.param(None, id="shell-without-PYTHONPATH"),
    pytest.param(DRIVERS, id="PYTHONPATH-drivers")])
def test_make_sweep_with_a_repeated_point_stops_before_any_job_naming_sweep_rho(pythonpath):
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    if pythonpath:
        env["PYTHONPATH"] = pythonpath
    proc = subprocess.run(["make", "-n", "sweep", "SWEEP_RHO=10,10.0000001"], cwd=ROOT,
                          capture_output=True, text=True, env=env)
    assert proc.returncode != 0 and "SWEEP_RHO" in proc.stderr \
        and "mlgshimmy.studies.sweep point" not in proc.stdout, \
        (proc.stdout + proc.stderr).strip()[-400:]


def test_make_clean_does_not_evaluate_the_sweep_grid(tmp_path):
    """A PYTHON that leaves a mark shows whether make ran it to read the
    grid (not even a bad one)."""
    mark = tmp_path / "called"
    fake = tmp_path / "python"
    fake.write_text(f"#!/bin/sh\ntouch {mark}\n")
    fake.chmod(0o755)
    proc = subprocess.run(["make", "-n", "clean", f"PYTHON={fake}", "SWEEP_RHO=x"],
                          cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 0 and not mark.exists(), proc.stderr.strip()


@pytest.fixture(scope="module")
def sweep_speeds(tmp_path_factory):
    """{point: critical speed} of the sweep jobs rho10_mu10 and
    rho-10_mu-10, run in a scratch $MLG_RUN_ROOT."""
    root = tmp_path_factory.mktemp("sweep-root")
    speeds = {}
    for name in ("rho10_mu10", "rho-10_mu-10"):
        proc = driver("studies.sweep", "point", name, MLG_RUN_ROOT=str(root))
        assert proc.returncode == 0, f"sweep point {name}: {proc.stderr.strip()[-300:]}"
        with open(root / "sweep" / name / "result.json") as f:
            speeds[name] = json.load(f)["critical_V"]
    return speeds


def test_sweep_critical_speed_at_rho_mu_10_is_350_66(sweep_speeds):
    # eigenvalue bisection at rho = mu = 10 deg, eom_terms = 2: 350.664 m/s
    a = sweep_speeds["rho10_mu10"]
    assert abs(a - 350.664) <= 0.05, f"{a:.4f} m/s, expected 350.66 +- 0.05"


def test_sweep_mirror_geometry_has_the_same_critical_speed(sweep_speeds):
    a, b = sweep_speeds["rho10_mu10"], sweep_speeds["rho-10_mu-10"]
    assert abs(a - b) <= 1e-6 * a, f"{a:.6f} vs {b:.6f} m/s (rel 1e-6)"


# mlgshimmy.studies.sidestay with equilibria only (no Hopf points, so no
# orbit or curve runs: seconds, not minutes) and a pause after each geometry,
# in which the process still owns that geometry's run directory.
QUICK_SIDESTAY = """
import sys, time
from mlgshimmy.studies import sidestay
sidestay.hopf_points = lambda rundir, tag, values: []
computed = sidestay.compute
def paused(*args, **kw):
    out = computed(*args, **kw)
    time.sleep(2.0)
    return out
sidestay.compute = paused
sys.argv = ["sidestay.py", "--rho", sys.argv[1], "--mu", sys.argv[1]]
sidestay.main()
"""


@pytest.fixture(scope="module")
def shared_reference(tmp_path_factory):
    """Side-stay runs at 5 and 10 deg in a fresh $MLG_RUN_ROOT, the second
    started while the first holds sidestay_rho0_mu0: (root, out1, err1,
    out2, err2)."""
    root = tmp_path_factory.mktemp("sidestay-root")
    env = dict(os.environ, MLG_RUN_ROOT=str(root))

    def start(angle):
        return subprocess.Popen([sys.executable, "-c", QUICK_SIDESTAY, angle], cwd=ROOT,
                                env=env, text=True, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE)
    first = start("5")
    helpers.wait_until_claimed(os.path.join(root, "sidestay_rho0_mu0"), first)
    second = start("10")
    (out1, err1), (out2, err2) = first.communicate(timeout=300), second.communicate(timeout=300)
    assert first.returncode == 0 and second.returncode == 0, \
        f"sidestay at 5 and 10 deg, the second started while the first holds rho = mu = 0: " \
        f"{(err1 + err2)[-800:]}"
    return root, out1, err1, out2, err2


def test_sidestay_second_run_waits_for_the_first_naming_sidestay_rho0_mu0(shared_reference):
    err2 = shared_reference[4]
    assert "sidestay_rho0_mu0 is in use by process" in err2 and "waiting" in err2, err2[-400:]


def test_sidestay_second_run_reuses_the_cached_rho0_mu0_runs(shared_reference):
    _, out1, _, out2, _ = shared_reference
    assert "reusing the runs" in out2 and "reusing the runs" not in out1 \
        and "sidestay_rho0_mu0: eq_fp0 done" not in out2, out2[-600:]


def test_sidestay_second_run_has_the_same_rho0_mu0_numbers(shared_reference):
    _, out1, _, out2, _ = shared_reference

    def reference(out):
        return [line for line in out.splitlines() if "rho = mu = 0, " in line]
    assert reference(out1) == reference(out2) and len(reference(out1)) == 2, \
        f"{reference(out1)} vs {reference(out2)}"


def test_sidestay_prints_the_eom_terms_level_first(shared_reference):
    out1 = shared_reference[1]
    assert "eom_terms = 2" in out1.splitlines()[0], out1[:200]


def test_sidestay_numbers_in_a_plain_text_table(shared_reference):
    table = os.path.join(shared_reference[0], "tables", "sidestay_rho5_mu5.txt")
    text = open(table).read() if os.path.exists(table) else ""
    assert "Hopf points at V" in text and "$" not in text and "\\" not in text, text[:300]
