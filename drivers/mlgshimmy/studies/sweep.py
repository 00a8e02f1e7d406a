"""Sweep over side-stay angles: the critical shimmy speed on a (rho, mu) grid.

Each grid point is an independent job with its own run directory
build/sweep/rho<deg>_mu<deg>/: the first Hopf point in V of straight rolling
(zero freeplay, F* = 1, `figures` set, complete equations eom_terms = 2),
written to result.json there with its provenance (shared.jobs.grid: git
commit, AUTO version, parameter set, settings()).  Subcommands of
`python3 -m mlgshimmy.studies.sweep` (angles in degrees, lists
comma-separated; the default grid is 3 x 3):

  check   [--rho L --mu L]    validate every grid point (no AUTO run)
  targets [--rho L --mu L]    the result files, for make
  jobs    [--rho L --mu L] [--missing]
                              one shell command per grid point (--missing:
                              per point without a valid result), for GNU
                              parallel or a Slurm array (docs/cluster.md)
  status  [--rho L --mu L]    every point without a valid result, by index
  point rho<deg>_mu<deg>      run one grid point
  summary [--rho L --mu L] [--mixed-provenance]
                              plot build/figures/sweep_critical_speed.*

`make sweep` (with -j N for N jobs at once) runs check, every point, summary.
"""
from __future__ import annotations

import os
import time
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import geometry
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs import grid as jobgrid

# What make, make help, make submit and the report know of this study
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "sweep": {
        "help": "critical speed over a (rho, mu) grid (SWEEP_RHO, SWEEP_MU: 3 x 3)",
        "time": "20 s",
        "grid": "SWEEP_GRID_ARGS",
        "report": {
            "command": "make sweep",
            "text": "The critical shimmy speed over a grid of side-stay angles.",
            "tables": [],
            "figures": ["figures/sweep_critical_speed.png"],
        },
    },
}
axis = jobgrid.axis

DEFAULT_GRID = "-10,0,10"
V_START, V_STOP = ct.V_MIN, ct.V_MAX


def settings() -> Dict[str, Any]:
    """What a point's result depends on besides its angles, the code, the
    model and AUTO (jobs.provenance records those and the thread count)."""
    return {"parameters": {k: v for k, v in parameters(0.0, 0.0).items()
                           if k not in ("rho", "mu")},
            "V_scan": [V_START, V_STOP, len(ct.SPEED_SCAN)]}


POINTS = jobgrid.Plane("rho", "mu", "sweep", "figures", settings)   # rho<deg>_mu<deg>


def grid(args: Any) -> List[Tuple[float, float]]:
    rhos = axis(args.rho, "SWEEP_RHO (--rho)", "angles in degrees")
    mus = axis(args.mu, "SWEEP_MU (--mu)", "angles in degrees")
    return jobgrid.plane(rhos, mus)


def parameters(rho: float, mu: float, eom_terms: int = 2) -> Dict[str, float]:
    return {"Fstar": 1.0, "yfp": 0.0, **geometry.model_angles(rho, mu, eom_terms)}


def problem(point: Tuple[float, float]) -> Optional[str]:
    """Why the grid point (rho, mu) cannot be run, or None."""
    rho, mu = point
    try:
        mlgmodel.Model("figures", V=V_START, **parameters(rho, mu)).check()
    except ValueError as exc:
        return f"rho = {rho:g} deg, mu = {mu:g} deg: {exc}"
    return None


def run_point(name: str) -> None:
    rho, mu = POINTS.parse(name)
    started = time.monotonic()
    values = parameters(rho, mu)
    ct.Start("figures", V=V_START, **values)                 # validates first
    hopf = ct.hopf_points(paths.rundir(os.path.join("sweep", name)), "hb", "figures", "V",
                          ct.SPEED_SCAN, limit=1, **values)
    result = {"rho_deg": rho, "mu_deg": mu, "critical_V": hopf[0]["V"] if hopf else None,
              "seconds": round(time.monotonic() - started, 2)}
    POINTS.write(rho, mu, result)
    print(f"sweep: {name}: critical speed "
          + (f"{result['critical_V']:.3f} m/s" if hopf else f"> {V_STOP:g} m/s"))


def summary(points: Sequence[Tuple[float, float]], results: Sequence[Mapping[str, Any]],
            provenance: Optional[Mapping[str, Any]]) -> None:
    """The points' critical speeds (results: their records, every point's
    checked present and of one provenance by shared.jobs.grid) and the plot."""
    import matplotlib.pyplot as plt
    import numpy

    from mlgshimmy.shared import draw
    from mlgshimmy.shared.draw.angle_map import angle_map
    rhos = sorted({rho for rho, _ in points})
    mus = sorted({mu for _, mu in points})
    speed = numpy.full((len(mus), len(rhos)), numpy.nan)
    for (rho, mu), result in zip(points, results):
        value = result["critical_V"]
        speed[mus.index(mu), rhos.index(rho)] = numpy.nan if value is None else value
        print(f"sweep: rho = {rho:6g} deg, mu = {mu:6g} deg: critical speed "
              + (f"{value:.3f} m/s" if value is not None else f"> {V_STOP:g} m/s"))
    fig, ax = plt.subplots(figsize=(5.5, 4.5))
    mesh = angle_map(ax, rhos, mus, speed,
                     lambda v: "> 600" if numpy.isnan(v) else f"{v:.1f}")
    fig.colorbar(mesh, label="critical shimmy speed [m/s]")
    ax.set_title("First Hopf point of straight rolling\n"
                 "zero freeplay, F* = 1, our calibrated parameter set,\n"
                 + geometry.EOM_WORDS[2])
    draw.save(fig, "sweep_critical_speed")


def main() -> None:
    jobgrid.main("sweep", __doc__.splitlines()[0], "point", POINTS,
                 [("--rho", DEFAULT_GRID, "rho values [deg], comma-separated"),
                  ("--mu", DEFAULT_GRID, "mu values [deg], comma-separated")],
                 grid, run_job=run_point, problem=problem, summary=summary)


if __name__ == "__main__":
    main()
