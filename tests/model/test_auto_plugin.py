"""The AUTO plugin (models/mlg.c) on the MLG model (the names AUTO reads:
tests/model/test_declarations.py): PAR(1-10) hold only continuation
parameters, JAC=1 and JAC=0 give the same special points, the `figures` Hopf
speed at F* = 1 is the paper's 346.1 m/s, the Hopf is supercritical, the
periodic orbit at V = 300 m/s, F* = 0.2 matches the time simulation, a
constant set from Python reaches AUTO, and bad input stops every entry point
(Model, AUTO's CLUI, autoglue) with a message naming the parameter."""
import math
import os
import shutil
import subprocess
import sys
import textwrap

import pytest

from mlgshimmy.shared import autoglue, rundirs, runerror
from mlgshimmy.shared import branches
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import paths
from mlgshimmy.shared import simulator
from mlgshimmy.shared import spectrum

DRIVERS = os.path.join(paths.ROOT, "drivers")


@pytest.fixture(scope="module")
def root(tmp_path_factory):
    """The module's scratch directory (AUTO runs in root/runs, CLUI runs in
    root/clui/<name>); the run directories this process claims are not
    passed on to later tests' child processes."""
    path = tmp_path_factory.mktemp("auto-plugin")
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        yield str(path)


@pytest.fixture(scope="module")
def rundir(root):
    return os.path.join(root, "runs")


# --- constants and parameters --------------------------------------------------

def test_constants_par_1_to_10_hold_only_continuation_parameters():
    continuation = [name for name in mlgmodel.PARNAMES[:10] if name is not None]
    assert not set(continuation) & {"strut_variant", "eom_terms", "tyre_forces"}, \
        f"a switch in PAR(1-10): {continuation}"


def test_invalid_parameters_rejected_before_auto_runs():
    with pytest.raises(ValueError) as error:
        ct.Start("figures", yfp=-1.0)
    assert "yfp" in str(error.value), str(error.value)


def test_model_validates_every_par_parameter_by_name():
    """Model(...) validates at construction; every PAR parameter has a rule
    (-3 and NaN are outside every parameter's range)."""
    wrong = []
    for name in [n for n in mlgmodel.PARNAMES if n not in (None, mlgmodel.CONSTANTS_FILE)]:
        for bad in (-3.0, math.nan):
            try:
                mlgmodel.Model("figures", **{name: bad})
                wrong.append(f"{name} = {bad} accepted")
            except ValueError as exc:
                if name not in str(exc):
                    wrong.append(f"{name} = {bad} rejected without naming it: {exc}")
    assert not wrong, "; ".join(wrong)


@pytest.mark.parametrize("values, name", (({"Fstar": -1}, "Fstar"), ({"V": "abc"}, "V"),
                                          ({"k_relax": None}, "k_relax")))
def test_model_rejects_a_bad_value_naming_it(values, name):
    with pytest.raises(ValueError) as error:
        mlgmodel.Model("figures", **values)
    assert name in str(error.value), str(error.value)


@pytest.mark.parametrize("values, epsilon", (({"eps_abs": 0.1}, 0.1), ({"eps_rel": 0.3}, 0.3),
                                             ({}, 0.1), ({"eps_abs": 0.1, "eps_rel": 0.2}, 0.3)))
def test_model_epsilon_as_given(values, epsilon):
    got = 1e3 * mlgmodel.Model("figures", yfp=1.0, **values).epsilon_m()
    assert math.isclose(got, epsilon, abs_tol=1e-12), \
        f"yfp = 1 mm, {values}: epsilon {got!r} mm, not {epsilon}"


# --- bad input through AUTO's CLUI and autoglue --------------------------------

CLUI_RUN = textwrap.dedent("""
    import math
    from mlgshimmy.shared import autosession, mlgmodel
    auto = autosession.init()
    m = mlgmodel.Model("figures", Fstar=1.0, V=10.0)
    par = dict(m.par(), **{bad})
    auto.run(e={model!r}, c=auto.parseC.parseC({constants!r}), PAR=par, U=m.equilibrium(),
             ICP=["V", "psi_amp"], DS={ds}, DSMAX=2, UZSTOP={{"V": [-20, 20]}}, NMX=50)
""")


def clui(root, name, bad, ds=1.0, files=None):
    """A plain auto.run through AUTO's CLUI in a directory of its own (holding
    `files`, {name: text}), PAR overridden by `bad`: (exit status, the
    model's output lines, rundir, all output lines)."""
    rundir = os.path.join(root, "clui", name)
    shutil.rmtree(rundir, ignore_errors=True)
    os.makedirs(rundir)
    for filename, text in (files or {}).items():
        with open(os.path.join(rundir, filename), "w") as out:
            out.write(text)
    code = CLUI_RUN.format(model=ct.MODEL, constants=ct.CONSTANTS, bad=bad, ds=ds)
    proc = subprocess.run([sys.executable, "-c", code], cwd=rundir, capture_output=True,
                          text=True, env=dict(os.environ, PYTHONPATH=DRIVERS))
    lines = (proc.stdout + proc.stderr).splitlines()
    return proc.returncode, [line for line in lines if line.startswith("mlg")], rundir, lines


@pytest.mark.parametrize("name, bad", (
    ("yfp", "{'yfp': -1.0}"), ("eps", "{'yfp': 1.0, 'eps_abs': 0.0, 'eps_rel': 0.0}"),
    ("strut_variant", "{'strut_variant': 7}"), ("eom_terms", "{'eom_terms': 5}"),
    ("rho", "{'rho': 2.0}"), ("V", "{'V': math.nan}")))
def test_clui_bad_start_stops_the_run_naming_the_parameter(root, name, bad):
    """Invalid starting parameters through AUTO's CLUI stop the run: a
    Python error, one message naming the parameter as the model's first
    line, no solution saved."""
    status, messages, rundir, lines = clui(root, name, bad)
    first = lines[1] if len(lines) > 1 else ""
    assert status != 0, f"{bad}: exit status {status}"
    assert len(messages) == 1 and first == messages[0] and name in first \
        and "invalid starting parameters" in first, f"{bad}: lines {lines[:3]}, model {messages}"
    saved = os.path.join(rundir, "fort.8")
    assert not os.path.exists(saved) or os.path.getsize(saved) == 0, \
        f"{bad}: {saved}: {os.path.getsize(saved)} bytes"


def test_clui_steps_leaving_the_domain_are_rejected_quietly(root):
    """Steps to V < 0 are rejected (AUTO halves its step to MX at V >= 0),
    without a message."""
    status, messages, rundir, lines = clui(root, "leaves", "{}", ds=-1.0)
    with open(os.path.join(rundir, "fort.7")) as diagram:
        last = [line.split() for line in diagram if not line.startswith("   0")][-1]
    assert last[2] == "-9" and 0.0 <= float(last[4]) < 1e-3, f"last point {last[:5]}"
    assert status == 0 and not messages, f"exit status {status}, model lines {messages}"


def test_autoglue_invalid_starting_parameters_raise_run_error(root):
    with pytest.raises(runerror.RunError):
        autoglue.run(os.path.join(root, "autoglue-bad"), "bad", constants=ct.CONSTANTS,
                     e=ct.MODEL, PAR=dict(ct.Start("figures").PAR, eom_terms=5),
                     U=ct.Start("figures").U)


# --- a constant set from Python reaches AUTO -----------------------------------

@pytest.fixture(scope="module")
def k_relax_hopf(rundir):
    """With k_relax = 0.9: the eigenvalue scan's Hopf crossings in V and
    AUTO's Hopf point at F* = 1."""
    scan = [v for v, kind, _ in spectrum.stability_changes(
        "figures", "V", [300.0, 340.0, 380.0], Fstar=1.0, k_relax=0.9) if kind == "HB"]
    start = ct.Start("figures", Fstar=1.0, V=0.0, k_relax=0.9)
    hb = ct.equilibria(rundir, "eq_krelax", start, stop={"V": 400.0}, expect=["HB"])("HB1")
    print(f"# k_relax = 0.9: AUTO's Hopf at {hb['V']:.4f} m/s, eigenvalue scan {scan}")
    return scan, hb


def test_constants_k_relax_reaches_auto(k_relax_hopf):
    """A constant set from Python reaches AUTO's FUNC: with k_relax = 0.9
    AUTO's Hopf point at F* = 1 is the library's eigenvalue-scan value
    (360.56 m/s; 346.10 with the default 0.7)."""
    scan, hb = k_relax_hopf
    assert len(scan) == 1, f"not one Hopf crossing in the scan: {scan}"
    assert math.isclose(hb["V"], scan[0], rel_tol=1e-5), \
        f"AUTO's Hopf {hb['V']!r}, the eigenvalue scan's {scan[0]!r}"
    assert math.isclose(hb["V"], 360.56, abs_tol=0.01), hb["V"]


@pytest.mark.parametrize("text, why", (
    ("k_relax 0.9\nnonsense 1\n", "line 2: no constant named nonsense"),
    ("V 3\n", "V is PAR(1)"), ("k_relax\n", "expected \"name value\""),
    (None, "cannot read mlg.constants.7")))
def test_constants_file_refused_with_its_reason(root, text, why):
    files = {} if text is None else {"mlg.constants.7": text}
    status, messages, _, _ = clui(root, "file", "{'constants': 7}", files=files)
    assert status != 0 and len(messages) == 1 and why in messages[0], \
        f"constants file {text!r}: exit {status}, model lines {messages}"


# --- JAC=1 against JAC=0, the Hopf point at F* = 1 -----------------------------

@pytest.fixture(scope="module")
def jac_runs(rundir):
    """Straight rolling at F* = 1 to its Hopf point and the orbits born
    there, with AUTO's Jacobian from the plugin (JAC=1) and by differences
    (JAC=0): ({jac: equilibria}, {jac: orbits})."""
    start = ct.Start("figures", Fstar=1.0, V=0.0)
    eq = {jac: ct.equilibria(rundir, f"eq_jac{jac}", start, stop={"V": 400.0},
                             expect=["HB"], JAC=jac) for jac in (1, 0)}
    po = {jac: ct.periodic_from(rundir, f"po_jac{jac}", eq[jac]("HB1"), stop={"V": 370.0},
                                UZR={"V": [355.0, 365.0]}, expect=["UZ"], JAC=jac, NMX=200)
          for jac in (1, 0)}
    return eq, po


def test_hopf_at_unit_load_is_the_papers_346_1_m_s(jac_runs):
    eq, _ = jac_runs
    assert math.isclose(eq[1]("HB1")["V"], 346.1, abs_tol=0.05), eq[1]("HB1")["V"]


def test_jacobian_jac1_and_jac0_same_hopf_speed(jac_runs):
    eq, _ = jac_runs
    hb1, hb0 = eq[1]("HB1"), eq[0]("HB1")
    assert math.isclose(hb1["V"], hb0["V"], rel_tol=1e-6), f"JAC=1 {hb1['V']!r}, JAC=0 {hb0['V']!r}"


@pytest.mark.parametrize("label", ("UZ1", "UZ2"))
@pytest.mark.parametrize("measure", ("V", "psi_amp", "delta_amp", "freq"))
def test_jacobian_jac1_and_jac0_same_periodic_orbits(jac_runs, label, measure):
    _, po = jac_runs
    a, b = po[1](label), po[0](label)
    assert math.isclose(a[measure], b[measure], rel_tol=1e-6), \
        f"periodic {label} {measure}: JAC=1 {a[measure]!r}, JAC=0 {b[measure]!r}"


def test_hopf_supercritical(jac_runs):
    """Orbits exist past the Hopf speed, where straight rolling is unstable,
    and the orbits born there are stable."""
    eq, po = jac_runs
    branch = po[1][0]
    stable = branches.stable_mask(branch)
    assert all(v > eq[1]("HB1")["V"] for v in branch["V"][1:]), \
        f"V along the branch {list(branch['V'][:5])}"
    assert bool(stable[1:10].all()), f"stability of the first points {list(stable[:10])}"


def test_runs_carry_the_librarys_measures(jac_runs):
    """The drivers ask AUTO for the library's measures: the branches carry
    every one of mlgmodel.MEASURES.  (continuation.MEASURES, which the old
    test compared with the library's, is gone: should it come back, it
    must be the library's list.)"""
    eq, po = jac_runs
    assert getattr(ct, "MEASURES", mlgmodel.MEASURES) == mlgmodel.MEASURES, \
        f"continuation {ct.MEASURES}, library {mlgmodel.MEASURES}"
    for run in (eq[1], po[1]):
        missing = [m for m in mlgmodel.MEASURES if m not in run[0].coordnames]
        assert not missing, f"columns {run[0].coordnames} lack {missing}"


# --- the orbit against the time simulation -------------------------------------

def test_orbit_matches_simulation(rundir, tmp_path):
    """Fig. 7 orbit vs Fig. 8 simulation at V = 300 m/s, F* = 0.2 (settled)."""
    start = ct.Start("figures", Fstar=0.2, V=0.0)
    eq = ct.equilibria(rundir, "eq_F0.2", start, stop={"V": 400.0}, expect=["HB"])
    orbit = ct.periodic_from(rundir, "po_F0.2", eq("HB1"), stop={"V": 300.0},
                             expect=["UZ"])("UZ1")
    summary = simulator.simulate(str(tmp_path / "sim.csv"), "--V", 300, "--Fstar", 0.2,
                                 "--t-end", 60, "--dt-out", 2e-4)
    sim_psi, sim_freq = summary["psi_amplitude_rad"], summary["frequency_hz"]
    print(f"# V = 300, F* = 0.2: AUTO psi amplitude {orbit['psi_amp']:.6e} rad, "
          f"simulation (last second of 60 s) {sim_psi:.6e} rad; "
          f"frequency {orbit['freq']:.6f} vs {sim_freq:.6f} Hz")
    assert math.isclose(sim_psi, orbit["psi_amp"], rel_tol=1e-3), \
        f"psi amplitude: simulation {sim_psi!r}, orbit {orbit['psi_amp']!r}"
    assert math.isclose(sim_freq, orbit["freq"], rel_tol=1e-4), \
        f"frequency: simulation {sim_freq!r}, orbit {orbit['freq']!r}"
