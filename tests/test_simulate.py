"""Tests of build/bin/mlg_simulate (CVODE time simulation of the MLG model).

The expected behaviour comes from the linearisation at straight rolling for
the `figures` parameter set (eigenvalues of mlg_rhs_jacobian at the
equilibrium): at V = 100 m/s, F* = 1 every mode decays (the Hopf point is at
V = 346.1 m/s); at V = 300 m/s, F* = 0.2 the shimmy pair 0.41 +- 238.6i rad/s
(38 Hz) is unstable (at F* = 0.2 the Hopf lies between 250 and 300 m/s) and
grows into the limit cycle of Fig. 8.
"""
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from check import check  # noqa: E402
from mlgshimmy.shared import simulator  # noqa: E402


def simulate(tmp, name, *args):
    """Run the simulator; return (exit status, summary dict, samples, stderr)."""
    csv = os.path.join(tmp, name + ".csv")
    proc = simulator.run(csv, *args)
    summary, data = {}, None
    if proc.returncode == 0:
        summary = simulator.summary(proc.stdout)
        data = np.genfromtxt(csv, delimiter=",", names=True)
    return proc.returncode, summary, data, proc.stderr


def half_range(data, name, t0, t1):
    """Half peak-to-peak of a state for t0 <= t <= t1."""
    window = (data["t"] >= t0) & (data["t"] <= t1)
    return 0.5 * np.ptp(data[name][window])


def main():
    with tempfile.TemporaryDirectory() as tmp:
        # (a) zero perturbation: the exact equilibrium stays put for 1 s
        status, summary, data, err = simulate(tmp, "rest", "--V", "100", "--Fstar", "1",
                                              "--psi0", "0", "--t-end", "1")
        if check("rest: runs", status == 0, err.strip()):
            states = data.dtype.names[1:]
            deviation = max(np.max(np.abs(data[s] - data[s][0])) for s in states)
            check("rest: equilibrium held for 1 s (max deviation < 1e-9)",
                  deviation < 1e-9, f"max deviation {deviation:.3g}")
            check("rest: analytic Jacobian used (no finite-difference RHS calls)",
                  summary["jac_evals"] > 0 and summary["fd_rhs_evals"] == 0,
                  f"jac_evals {summary['jac_evals']}, fd_rhs_evals {summary['fd_rhs_evals']}")

        # (b) stable: V = 100, F* = 1, psi0 = 1e-3 decays (shimmy mode -1.84 rad/s:
        # expected factor ~exp(-1.84 * 2.5) = 0.01 from [0, 0.5] to [2.5, 3] s)
        status, summary, data, err = simulate(tmp, "stable", "--V", "100", "--Fstar", "1",
                                              "--psi0", "1e-3", "--t-end", "3")
        if check("stable: runs", status == 0, err.strip()):
            early, late = half_range(data, "psi", 0.0, 0.5), half_range(data, "psi", 2.5, 3.0)
            check("stable: psi perturbation decays (late/early < 0.05)",
                  late < 0.05 * early, f"psi half-range {early:.3g} -> {late:.3g}")

        # (c) unstable: V = 300, F* = 0.2, psi0 = 1e-4 grows at the shimmy rate
        # 0.41 /s (linear regime): expected ratio exp(0.41 * 2) = 2.27 between
        # [0.5, 1] and [2.5, 3] s, accepted in [1.8, 2.8]; frequency 38 Hz.
        status, summary, data, err = simulate(tmp, "unstable", "--V", "300", "--Fstar", "0.2",
                                              "--psi0", "1e-4", "--t-end", "3")
        if check("unstable: runs", status == 0, err.strip()):
            early, late = half_range(data, "psi", 0.5, 1.0), half_range(data, "psi", 2.5, 3.0)
            ratio = late / early
            check("unstable: psi grows at the linear shimmy rate (ratio in [1.8, 2.8])",
                  1.8 <= ratio <= 2.8, f"psi half-range {early:.3g} -> {late:.3g}, "
                  f"ratio {ratio:.3f}")
            check("unstable: shimmy frequency 38 +- 0.5 Hz",
                  abs(summary["frequency_hz"] - 38.0) < 0.5,
                  f"frequency {summary['frequency_hz']:.3f} Hz")
            check("unstable: torsional shimmy (psi amplitude > 3 x delta amplitude)",
                  summary["psi_amplitude_rad"] > 3 * summary["delta_amplitude_rad"],
                  f"psi {summary['psi_amplitude_rad']:.3g}, "
                  f"delta {summary['delta_amplitude_rad']:.3g}")

        # (d) invalid parameters: exit status 2 with a message naming the parameter
        status, _, _, err = simulate(tmp, "invalid", "--yfp", "-1", "--t-end", "0.1")
        check("invalid: --yfp -1 rejected naming yfp", status == 2 and "yfp" in err,
              f"exit status {status}, stderr {err.strip()!r}")

        # (d2) no output window or no steps: exit status 2 naming the option
        for args, option in ((["--t-end", "1e20", "--dt-out", "1"], "--t-end"),
                             (["--dt-out", "inf"], "--dt-out"),
                             (["--t-end", "0.01", "--dt-out", "0.1"], "--dt-out"),
                             (["--t-end", "nan"], "--t-end")):
            status, _, _, err = simulate(tmp, "window", *args)
            check(f"invalid: {' '.join(args)} refused naming {option}",
                  status == 2 and option in err, f"exit status {status}, stderr {err.strip()!r}")

        # (d3) epsilon is what was given: one part alone sets the other to 0
        # (defaults eps_abs = 0, eps_rel = 0.1); the summary prints epsilon in mm
        for args, epsilon in ((["--eps-abs", "0.1"], 0.1), (["--eps-rel", "0.3"], 0.3),
                              (["--param", "eps_abs=0.05"], 0.05), ([], 0.1),
                              (["--eps-abs", "0.1", "--eps-rel", "0.2"], 0.3)):
            status, summary, _, err = simulate(tmp, "epsilon", "--yfp", "1", "--t-end", "0.01",
                                               *args)
            got = summary.get("epsilon_mm")
            check(f"epsilon: yfp 1 {' '.join(args)} runs at epsilon = {epsilon} mm (1e-12)",
                  status == 0 and abs(got - epsilon) <= 1e-12, f"exit {status}, epsilon {got}, "
                  f"stderr {err.strip()!r}")

        # (e) a state outside the model's domain stops the run with its reason
        status, _, _, err = simulate(tmp, "domain", "--psi0", "1.5", "--t-end", "0.1")
        check("domain: psi0 = 1.5 rad stops with a lift-off error",
              status == 1 and "lifts off" in err, f"exit status {status}, stderr {err.strip()!r}")


if __name__ == "__main__":
    main()
