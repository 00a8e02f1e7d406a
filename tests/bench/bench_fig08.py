"""Benchmark: wall time of the Fig. 8 simulation (V = 300 m/s, F* = 0.2,
y_fp = 0, 15 s, output every 1 ms) with build/bin/mlg_simulate.

Prints the best of three integration wall times as measured by the simulator
(CSV writing included, equilibrium solve excluded) and the solver counts.
"""
import os
import sys
import tempfile

from mlgshimmy.shared import simulator   # PYTHONPATH=drivers (make bench sets it)

REPEATS = 3


def run_once(csv):
    try:
        return simulator.simulate(csv, "--V", 300, "--Fstar", 0.2, "--yfp", 0, "--t-end", 15,
                                  "--dt-out", 1e-3, "--psi0", 1e-3)
    except simulator.SimulationError as exc:
        sys.exit(f"bench_fig08: {exc}")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        runs = [run_once(os.path.join(tmp, "fig08.csv")) for _ in range(REPEATS)]
    best = min(runs, key=lambda r: r["wall_time_s"])
    print(f"fig08 simulation (15 s, CVODE BDF, analytic Jacobian): "
          f"best of {REPEATS} {best['wall_time_s']:.3f} s wall; "
          f"{best['steps']:.0f} steps, {best['rhs_evals']:.0f} RHS, "
          f"{best['jac_evals']:.0f} Jacobian evaluations")


if __name__ == "__main__":
    main()
