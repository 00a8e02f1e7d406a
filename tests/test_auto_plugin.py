"""The AUTO plugin (models/mlg.c) on the MLG model: constants agree with the
library, JAC=1 and JAC=0 give the same special points, the `figures` Hopf
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

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from mlgshimmy.shared import autoglue  # noqa: E402
from mlgshimmy.shared import branches  # noqa: E402
from mlgshimmy.shared import continuation as ct  # noqa: E402
from mlgshimmy.shared import mlgmodel  # noqa: E402
from mlgshimmy.shared import paths  # noqa: E402
from mlgshimmy.shared import simulator  # noqa: E402
from mlgshimmy.shared import spectrum  # noqa: E402
from check import check, check_close  # noqa: E402

RUNDIR = os.path.join(autoglue.BUILD, "tests", "auto-plugin")


def constants_agree():
    """constants/c.mlg names every PAR slot of the library, the period and the
    measures of MLG_MEASURES; its unames follow the library's states."""
    c = autoglue.init().parseC.parseC(ct.CONSTANTS)
    parnames = {int(k): v for k, v in c["parnames"]}
    unames = {int(k): v for k, v in c["unames"]}
    ours = {k + 1: name for k, name in enumerate(mlgmodel.PARNAMES) if name is not None}
    ours[11] = "T"
    ours.update({mlgmodel.MEASURES_FIRST_PAR + k: name for k, name in enumerate(mlgmodel.MEASURES)})
    for k, name in sorted(ours.items()):
        check(f"constants: c.mlg parnames has PAR({k}) = {name}", parnames.get(k) == name,
              f"c.mlg has {parnames.get(k)!r}")
    extra = {k: v for k, v in parnames.items() if k not in ours}
    check("constants: c.mlg parnames names nothing the library does not", not extra,
          f"unknown to the library: {extra}")
    check("constants: drivers use the library's measures", ct.MEASURES == mlgmodel.MEASURES,
          f"continuation {ct.MEASURES}, library {mlgmodel.MEASURES}")
    check("constants: unames match the library's state order",
          [unames.get(i + 1) for i in range(mlgmodel.NX)] == mlgmodel.UNAMES,
          f"c.mlg {unames}, library {mlgmodel.UNAMES}")
    continuation = [name for name in mlgmodel.PARNAMES[:10] if name is not None]
    check("PAR layout: PAR(1-10) hold only continuation parameters (no switch)",
          not set(continuation) & {"strut_variant", "eom_terms", "tyre_forces"},
          f"PAR(1-10): {continuation}")


def model_validates():
    """Model(...) validates at construction; every PAR parameter has a rule
    (-3 and NaN are outside every parameter's range); epsilon as given."""
    for name in [n for n in mlgmodel.PARNAMES if n not in (None, mlgmodel.CONSTANTS_FILE)]:
        for bad in (-3.0, math.nan):
            try:
                mlgmodel.Model("figures", **{name: bad})
                check(f"Model: {name} = {bad} rejected", False, "accepted")
            except ValueError as exc:
                check(f"Model: {name} = {bad} rejected naming {name}", name in str(exc), str(exc))
    for values, name in (({"Fstar": -1}, "Fstar"), ({"V": "abc"}, "V"), ({"k_relax": None},
                                                                          "k_relax")):
        try:
            mlgmodel.Model("figures", **values)
            check(f"Model: {values} rejected", False, "accepted")
        except ValueError as exc:
            check(f"Model: {values} rejected naming {name}", name in str(exc), str(exc))
    for values, epsilon in (({"eps_abs": 0.1}, 0.1), ({"eps_rel": 0.3}, 0.3), ({}, 0.1),
                            ({"eps_abs": 0.1, "eps_rel": 0.2}, 0.3)):
        got = 1e3 * mlgmodel.Model("figures", yfp=1.0, **values).epsilon_m()
        check_close(f"Model: yfp = 1 mm, {values}: epsilon = {epsilon} mm", got, epsilon,
                    abs=1e-12)


CLUI_RUN = textwrap.dedent("""
    import math, sys
    sys.path.insert(0, {drivers!r})
    import autoglue; from autoglue import auto
    from mlgshimmy.shared import mlgmodel
    m = mlgmodel.Model("figures", Fstar=1.0, V=10.0)
    par = dict(m.par(), **{bad})
    auto.run(e={model!r}, c=auto.parseC.parseC({constants!r}), PAR=par, U=m.equilibrium(),
             ICP=["V", "psi_amp"], DS={ds}, DSMAX=2, UZSTOP={{"V": [-20, 20]}}, NMX=50)
""")


def clui(name, bad, ds=1.0, files=None):
    """A plain auto.run through AUTO's CLUI in a directory of its own (holding
    `files`, {name: text}), PAR overridden by `bad`: (exit status, the
    model's output lines, rundir, all output lines)."""
    rundir = os.path.join(RUNDIR, "clui", name)
    shutil.rmtree(rundir, ignore_errors=True)
    os.makedirs(rundir)
    for filename, text in (files or {}).items():
        with open(os.path.join(rundir, filename), "w") as out:
            out.write(text)
    code = CLUI_RUN.format(drivers=os.path.join(paths.ROOT, "drivers"), model=ct.MODEL,
                           constants=ct.CONSTANTS, bad=bad, ds=ds)
    proc = subprocess.run([sys.executable, "-c", code], cwd=rundir, capture_output=True,
                          text=True)
    lines = (proc.stdout + proc.stderr).splitlines()
    return proc.returncode, [line for line in lines if line.startswith("mlg")], rundir, lines


def bad_starts_stop():
    """Invalid starting parameters through AUTO's CLUI stop the run: a
    Python error, one message naming the parameter as the model's first
    line, no solution saved; a step leaving the domain later is quiet."""
    cases = {"yfp": "{'yfp': -1.0}", "eps": "{'yfp': 1.0, 'eps_abs': 0.0, 'eps_rel': 0.0}",
             "strut_variant": "{'strut_variant': 7}", "eom_terms": "{'eom_terms': 5}",
             "rho": "{'rho': 2.0}", "V": "{'V': math.nan}"}
    for name, bad in cases.items():
        status, messages, rundir, lines = clui(name, bad)
        first = lines[1] if len(lines) > 1 else ""
        check(f"CLUI: {bad} ends the run with an error", status != 0, f"exit status {status}")
        check(f"CLUI: {bad}: one message, naming {name}, right after AUTO's start line",
              len(messages) == 1 and first == messages[0] and name in first
              and "invalid starting parameters" in first, f"lines {lines[:3]}, model {messages}")
        saved = os.path.join(rundir, "fort.8")
        check(f"CLUI: {bad}: no solution saved", not os.path.exists(saved)
              or os.path.getsize(saved) == 0, f"{saved}: {os.path.getsize(saved)} bytes")
    status, messages, rundir, lines = clui("leaves", "{}", ds=-1.0)
    with open(os.path.join(rundir, "fort.7")) as diagram:
        last = [line.split() for line in diagram if not line.startswith("   0")][-1]
    check("CLUI: steps to V < 0 are rejected (AUTO halves its step to MX at V >= 0)",
          last[2] == "-9" and 0.0 <= float(last[4]) < 1e-3, f"last point {last[:5]}")
    check("CLUI: ... and without a message", status == 0 and not messages,
          f"exit status {status}, model lines {messages}")
    try:
        autoglue.run(os.path.join(RUNDIR, "autoglue-bad"), "bad", constants=ct.CONSTANTS,
                     e=ct.MODEL, PAR=dict(ct.Start("figures").PAR, eom_terms=5),
                     U=ct.Start("figures").U)
        check("autoglue: invalid starting parameters raise RunError", False, "no error")
    except autoglue.RunError as exc:
        check("autoglue: invalid starting parameters raise RunError", True, str(exc))


def constants_reach_auto():
    """A constant set from Python reaches AUTO's FUNC: with k_relax = 0.9
    AUTO's Hopf point at F* = 1 is the library's eigenvalue-scan value
    (360.56 m/s; 346.10 with the default 0.7)."""
    scan = [v for v, kind, _ in spectrum.stability_changes("figures", "V", [300.0, 340.0, 380.0],
                                                     Fstar=1.0, k_relax=0.9) if kind == "HB"]
    start = ct.Start("figures", Fstar=1.0, V=0.0, k_relax=0.9)
    hb = ct.equilibria(RUNDIR, "eq_krelax", start, stop={"V": 400.0}, expect=["HB"])("HB1")
    print(f"# k_relax = 0.9: AUTO's Hopf at {hb['V']:.4f} m/s, eigenvalue scan {scan}")
    check("constants: k_relax = 0.9 reaches AUTO (one Hopf crossing in the scan)", len(scan) == 1,
          f"scan {scan}")
    if scan:
        check_close("constants: AUTO's Hopf with k_relax = 0.9 is the eigenvalue scan's",
                    hb["V"], scan[0], rel=1e-5)
    check_close("constants: the k_relax = 0.9 Hopf is the library's 360.56 m/s", hb["V"], 360.56,
                abs=0.01)
    for text, why in (("k_relax 0.9\nnonsense 1\n", "line 2: no constant named nonsense"),
                      ("V 3\n", "V is PAR(1)"), ("k_relax\n", "expected \"name value\""),
                      (None, "cannot read mlg.constants.7")):
        files = {} if text is None else {"mlg.constants.7": text}
        status, messages, _, _ = clui("file", "{'constants': 7}", files=files)
        check(f"constants file {text!r} refused: {why}", status != 0 and len(messages) == 1
              and why in messages[0], f"exit {status}, model lines {messages}")


def hopf_and_jacobian_parity():
    start = ct.Start("figures", Fstar=1.0, V=0.0)
    eq = {}
    for jac in (1, 0):
        eq[jac] = ct.equilibria(RUNDIR, f"eq_jac{jac}", start, stop={"V": 400.0},
                                expect=["HB"], JAC=jac)
    hb1, hb0 = eq[1]("HB1"), eq[0]("HB1")
    check_close("figures set: Hopf at F* = 1 is the paper's 346.1 m/s", hb1["V"], 346.1,
                abs=0.05)
    check_close("JAC=1 vs JAC=0: Hopf speed", hb1["V"], hb0["V"], rel=1e-6)

    po = {}
    for jac in (1, 0):
        po[jac] = ct.periodic_from(RUNDIR, f"po_jac{jac}", eq[jac]("HB1"), stop={"V": 370.0},
                                   UZR={"V": [355.0, 365.0]}, expect=["UZ"], JAC=jac,
                                   NMX=200)
    for label in ("UZ1", "UZ2"):
        a, b = po[1](label), po[0](label)
        for measure in ("V", "psi_amp", "delta_amp", "freq"):
            check_close(f"JAC=1 vs JAC=0: periodic {label} {measure}", a[measure], b[measure],
                        rel=1e-6)

    branch = po[1][0]
    stable = branches.stable_mask(branch)
    beyond = [v > hb1["V"] for v in branch["V"][1:]]
    check("supercritical Hopf: orbits exist past the Hopf speed, where straight rolling is "
          "unstable", all(beyond), f"V along the branch {list(branch['V'][:5])}")
    check("supercritical Hopf: the orbits born there are stable", bool(stable[1:10].all()),
          f"stability of the first points {list(stable[:10])}")


def orbit_matches_simulation():
    """Fig. 7 orbit vs Fig. 8 simulation at V = 300 m/s, F* = 0.2 (settled)."""
    start = ct.Start("figures", Fstar=0.2, V=0.0)
    eq = ct.equilibria(RUNDIR, "eq_F0.2", start, stop={"V": 400.0}, expect=["HB"])
    orbit = ct.periodic_from(RUNDIR, "po_F0.2", eq("HB1"), stop={"V": 300.0},
                             expect=["UZ"])("UZ1")
    summary = simulator.simulate(os.path.join(RUNDIR, "sim.csv"), "--V", 300, "--Fstar", 0.2,
                                 "--t-end", 60, "--dt-out", 2e-4)
    sim_psi, sim_freq = summary["psi_amplitude_rad"], summary["frequency_hz"]
    print(f"# V = 300, F* = 0.2: AUTO psi amplitude {orbit['psi_amp']:.6e} rad, "
          f"simulation (last second of 60 s) {sim_psi:.6e} rad; "
          f"frequency {orbit['freq']:.6f} vs {sim_freq:.6f} Hz")
    check_close("orbit vs simulation: psi amplitude", sim_psi, orbit["psi_amp"], rel=1e-3)
    check_close("orbit vs simulation: frequency", sim_freq, orbit["freq"], rel=1e-4)


def invalid_parameters_rejected():
    try:
        ct.Start("figures", yfp=-1.0)
        check("invalid parameters rejected before AUTO runs", False, "no error")
    except ValueError as exc:
        check("invalid parameters rejected before AUTO runs", "yfp" in str(exc), str(exc))


def main():
    os.makedirs(RUNDIR, exist_ok=True)
    constants_agree()
    invalid_parameters_rejected()
    model_validates()
    try:
        bad_starts_stop()
        constants_reach_auto()
        hopf_and_jacobian_parity()
        orbit_matches_simulation()
    except autoglue.RunError as exc:
        check("AUTO runs complete", False, str(exc))


if __name__ == "__main__":
    main()
