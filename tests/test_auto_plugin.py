"""The AUTO plugin (models/mlg.c) on the MLG model: constants agree with the
library, JAC=1 and JAC=0 give the same special points, the `figures` Hopf
speed at F* = 1 is the paper's 346.1 m/s, the Hopf is supercritical, and the
periodic orbit at V = 300 m/s, F* = 0.2 matches the time simulation."""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
import autoglue  # noqa: E402
import diagrams as dg  # noqa: E402
import mlgmodel  # noqa: E402
from check import approx, check, check_close  # noqa: E402

RUNDIR = os.path.join(autoglue.BUILD, "tests", "auto-plugin")


def constants_agree():
    c = autoglue.auto.parseC.parseC(dg.CONSTANTS)
    parnames = {int(k): v for k, v in c["parnames"]}
    unames = {int(k): v for k, v in c["unames"]}
    ours = {k + 1: name for k, name in enumerate(mlgmodel.PARNAMES) if name is not None}
    check("constants: parnames of PAR(1-10) and PAR(13) match c/parameters.h",
          len(ours) == 11 and all(parnames.get(k) == name for k, name in ours.items()),
          f"c.mlg {parnames}, library {ours}")
    check("constants: unames match the library's state order",
          [unames.get(i + 1) for i in range(mlgmodel.NX)] == mlgmodel.UNAMES,
          f"c.mlg {unames}, library {mlgmodel.UNAMES}")


def hopf_and_jacobian_parity():
    start = dg.Start("figures", Fstar=1.0, V=0.0)
    eq = {}
    for jac in (1, 0):
        eq[jac] = dg.equilibria(RUNDIR, f"eq_jac{jac}", start, stop={"V": 400.0},
                                expect=["HB"], JAC=jac)
    hb1, hb0 = eq[1]("HB1"), eq[0]("HB1")
    check_close("figures set: Hopf at F* = 1 is the paper's 346.1 m/s", hb1["V"], 346.1,
                abs=0.05)
    check_close("JAC=1 vs JAC=0: Hopf speed", hb1["V"], hb0["V"], rel=1e-6)

    po = {}
    for jac in (1, 0):
        po[jac] = dg.periodic_from(RUNDIR, f"po_jac{jac}", eq[jac]("HB1"), stop={"V": 370.0},
                                   UZR={"V": [355.0, 365.0]}, expect=["UZ"], JAC=jac,
                                   NMX=200)
    for label in ("UZ1", "UZ2"):
        a, b = po[1](label), po[0](label)
        for measure in ("V", "psi_amp", "delta_amp", "freq"):
            check_close(f"JAC=1 vs JAC=0: periodic {label} {measure}", a[measure], b[measure],
                        rel=1e-6)

    branch = po[1][0]
    stable = dg.stable_mask(branch)
    beyond = [v > hb1["V"] for v in branch["V"][1:]]
    check("supercritical Hopf: orbits exist past the Hopf speed, where straight rolling is "
          "unstable", all(beyond), f"V along the branch {list(branch['V'][:5])}")
    check("supercritical Hopf: the orbits born there are stable", bool(stable[1:10].all()),
          f"stability of the first points {list(stable[:10])}")


def orbit_matches_simulation():
    """Fig. 7 orbit vs Fig. 8 simulation at V = 300 m/s, F* = 0.2 (settled)."""
    start = dg.Start("figures", Fstar=0.2, V=0.0)
    eq = dg.equilibria(RUNDIR, "eq_F0.2", start, stop={"V": 400.0}, expect=["HB"])
    orbit = dg.periodic_from(RUNDIR, "po_F0.2", eq("HB1"), stop={"V": 300.0},
                             expect=["UZ"])("UZ1")
    simulate = os.path.join(autoglue.BUILD, "bin", "mlg_simulate")
    out = subprocess.run([simulate, "--V", "300", "--Fstar", "0.2", "--t-end", "60",
                          "--dt-out", "2e-4", "--out", os.path.join(RUNDIR, "sim.csv")],
                         capture_output=True, text=True, check=True).stdout
    summary = dict(line.split(None, 1) for line in out.splitlines() if line.strip())
    sim_psi, sim_freq = float(summary["psi_amplitude_rad"]), float(summary["frequency_hz"])
    print(f"# V = 300, F* = 0.2: AUTO psi amplitude {orbit['psi_amp']:.6e} rad, "
          f"simulation (last second of 60 s) {sim_psi:.6e} rad; "
          f"frequency {orbit['freq']:.6f} vs {sim_freq:.6f} Hz")
    check_close("orbit vs simulation: psi amplitude", sim_psi, orbit["psi_amp"], rel=1e-3)
    check_close("orbit vs simulation: frequency", sim_freq, orbit["freq"], rel=1e-4)


def invalid_parameters_rejected():
    try:
        dg.Start("figures", yfp=-1.0)
        check("invalid parameters rejected before AUTO runs", False, "no error")
    except ValueError as exc:
        check("invalid parameters rejected before AUTO runs", "yfp" in str(exc), str(exc))


def main():
    os.makedirs(RUNDIR, exist_ok=True)
    constants_agree()
    invalid_parameters_rejected()
    try:
        hopf_and_jacobian_parity()
        orbit_matches_simulation()
    except autoglue.RunError as exc:
        check("AUTO runs complete", False, str(exc))


if __name__ == "__main__":
    main()
