"""Fig. 8 of Howcroft et al. (section IV.A): shimmy growing from the unstable
straight-rolling equilibrium at V = 300 m/s, F* = 0.2, zero freeplay.

Runs build/bin/mlg_simulate for 15 s from the equilibrium with psi perturbed
by 1e-3 rad, and plots psi, delta, beta (deg) and eta (mm) against t, each with
a zoom of the last second on the right.  Writes build/fig08/fig08.csv,
build/fig08/summary.txt (the simulator's summary: solver statistics and the
settled amplitudes over the last second) and build/figures/fig08.{png,pdf}.
Exits non-zero if the simulation fails.
"""
from __future__ import annotations

import os
import sys
from typing import Any, Dict, Mapping

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from mlgshimmy.shared import draw  # noqa: E402
from mlgshimmy.shared import gear  # noqa: E402
from mlgshimmy.shared import paths  # noqa: E402
from mlgshimmy.shared import simulator  # noqa: E402
from mlgshimmy.shared import jobs

# What make, make help, make submit and the report know of this figure
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "fig08": {
        "help": "Fig. 8: time simulation, V = 300 m/s, F* = 0.2 (CVODE)",
        "time": "5 s",
        "cached": False,
        "needs": ["simulator"],
        "redraw": "--plot",
        "report": ("Time simulation at V = 300 m/s, F* = 0.2: the oscillation grows and "
                   "settles on the orbit of Fig. 7(a); beta and eta oscillate weakly (IV.A)."),
    },
}

OUT_DIR = os.path.join(paths.run_root(), "fig08")
FIG_DIR = paths.figures_dir()

V, FSTAR, T_END, DT_OUT, PSI0 = 300.0, 0.2, 15.0, 1e-3, 1e-3

# (state, label, factor): angles in degrees, as every figure draws them
ROWS = [("psi", r"$\psi$ [deg]", draw.DEG), ("delta", r"$\delta$ [deg]", draw.DEG),
        ("beta", r"$\beta$ [deg]", draw.DEG), ("eta", r"$\eta$ [mm]", 1e3)]


def simulate(csv_path: str) -> Dict[str, float]:
    """Run the simulator; return its summary as a dict of floats."""
    try:
        return simulator.simulate(csv_path, "--set", "figures", "--V", V, "--Fstar", FSTAR,
                                  "--yfp", 0, "--t-end", T_END, "--dt-out", DT_OUT,
                                  "--psi0", PSI0, params=gear.simulator_params())
    except simulator.SimulationError as exc:
        sys.exit(f"fig08: {exc}")


def plot(data: Mapping[str, Any], path_stem: str) -> None:
    t = data["t"]
    zoom = t >= T_END - 1.0
    fig, axes = plt.subplots(len(ROWS), 2, figsize=(10, 8.5), sharex="col",
                             gridspec_kw={"width_ratios": [3, 1]})
    for (name, label, factor), (full, last) in zip(ROWS, axes):
        full.plot(t, factor * data[name], lw=0.4, color=draw.STABLE)
        last.plot(t[zoom], factor * data[name][zoom], lw=0.8, color=draw.STABLE)
        full.set_ylabel(label)
    axes[-1, 0].set_xlabel("t [s]")
    axes[-1, 1].set_xlabel("t [s] (last second)")
    axes[-1, 1].set_xlim(T_END - 1.0, T_END)
    draw.figure_title(fig, rf"Fig. 8: V = {V:g} m/s, $F^*$ = {FSTAR:g}, $y_{{fp}}$ = 0 "
                           rf"($\psi$ perturbed by {draw.sci(PSI0, 1)} rad "
                           "at t = 0)" + gear.suffix())
    fig.tight_layout()
    draw.save(fig, os.path.basename(path_stem))


def main(redraw: bool) -> None:
    """Simulate, then plot; with redraw (--plot, `make fig08-plot`) only plot
    the simulation already in OUT_DIR."""
    os.makedirs(OUT_DIR, exist_ok=True)
    os.makedirs(FIG_DIR, exist_ok=True)
    csv_path = os.path.join(OUT_DIR, "fig08.csv")
    summary_path = os.path.join(OUT_DIR, "summary.txt")
    if redraw:
        if not (os.path.exists(csv_path) and os.path.exists(summary_path)):
            sys.exit(f"fig08: no simulation in {OUT_DIR} to redraw (run `make fig08`)")
        with open(summary_path) as f:
            lines = [line.strip() for line in f if line.strip()]
    else:
        summary = simulate(csv_path)
        lines = [f"{key} {value:.10g}" for key, value in summary.items()]
    data = np.genfromtxt(csv_path, delimiter=",", names=True)
    if data["t"][-1] < T_END - 1e-9:
        sys.exit(f"fig08: simulation stopped at t = {data['t'][-1]} s")
    plot(data, os.path.join(FIG_DIR, "fig08"))

    if not redraw:
        jobs.write_text(summary_path, "\n".join(lines) + "\n")
    print("fig08: settled oscillation over the last second "
          "(amplitude = half peak-to-peak):")
    print("\n".join("  " + line for line in lines))
    if not redraw:
        print(f"fig08: wrote {os.path.relpath(summary_path, paths.ROOT)}")


if __name__ == "__main__":
    main(sys.argv[1:] == ["--plot"])
