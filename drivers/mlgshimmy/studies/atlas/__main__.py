"""Attractor atlas: what a time simulation settles on over the (V, F*) plane
of Fig. 11 (y_fp = 1 mm, epsilon = 0.1 mm (freeplay.NOMINAL), `figures` set).

Every grid cell is an independent job with its own directory
$MLG_RUN_ROOT/atlas/V<v>_F<f>/ (default build/) and result file
result.json there, computed by studies.atlas.cell (the starts, time
limits and simulations; shared.attractor classifies) and recorded with its
provenance (shared.jobs.grid: git commit, AUTO version, parameter set,
settings()).  `check` runs the simulator for 1 ms per cell, so bad
parameters stop the grid before any cell runs, with the simulator's
message naming them.  Subcommands of `python3 -m mlgshimmy.studies.atlas`
(axes as in shared.jobs.grid: "a,b,c" or "start:stop:step"; the default is
DEFAULT_V x DEFAULT_FSTAR):

  check   [--V L --Fstar L]   validate every cell (no simulation)
  targets [--V L --Fstar L]   the result files, for make
  jobs    [--V L --Fstar L] [--missing]
                              one shell command per cell (--missing: per
                              cell without a valid result), for GNU
                              parallel or a Slurm array (docs/cluster.md)
  status  [--V L --Fstar L]   every cell without a valid result, by index
  cell V<v>_F<f>              simulate and classify one cell
  summary [--V L --Fstar L] [--mixed-provenance]
                              summary.txt, summary.json and the plot
                              build/figures/atlas.{png,pdf}

`make atlas` (with -j N for N cells at once) runs check, every cell, summary.
"""
from __future__ import annotations

import json
import os
import sys
import tempfile
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

from mlgshimmy.shared import freeplay, jobs, gear
from mlgshimmy.shared import simulator
from mlgshimmy.shared.jobs import grid as jobgrid
from mlgshimmy.studies.atlas import cell as atlas_cell
from mlgshimmy.studies.atlas import compare as atlas_compare
axis = jobgrid.axis


def settings() -> Dict[str, Any]:
    """What a cell's result depends on besides (V, F*), the code and the
    simulator (recorded in its provenance)."""
    return {"freeplay": atlas_cell.FREEPLAY, "starts": atlas_cell.STARTS,
            "stages_s": atlas_cell.STAGES, "settle_s": atlas_cell.SETTLE,
            "window_s": atlas_cell.WINDOW,
            "dt_out_s": atlas_cell.DT_OUT}


CELLS = jobgrid.Plane("V", "F", "atlas", "figures", settings, "cells")   # V<v>_F<F*>

# 18 x 13 cells: every region of Fig. 11 holds at least one (the stable
# straight-rolling band at F* = 1 lies between 28.3 and 41.5 m/s: V = 30, 40;
# the off-centre-yaw band between F* = 0.037 and 0.408: 0.1, 0.2, 0.3)
DEFAULT_V = "5,10,20,30,40,50,70,100,150:600:50"
DEFAULT_FSTAR = "0.02,0.1,0.2,0.3,0.5,0.8,1,1.4,1.8,2.2,2.6,3,3.5"


def grid(args: Any) -> List[Tuple[float, float]]:
    vs = axis(args.V, "ATLAS_V (--V)", "speeds in m/s")
    fstars = axis(args.Fstar, "ATLAS_FSTAR (--Fstar)", "loads F*")
    return [(v, f) for f, v in jobgrid.plane(fstars, vs)]


def problem(point: Tuple[float, float]) -> Optional[str]:
    """Why the cell (V, F*) cannot be run, or None: a 1 ms run validates the
    parameters and finds the equilibrium."""
    v, fstar = point
    with tempfile.TemporaryDirectory() as tmp:
        proc = simulator.run(os.path.join(tmp, "c.csv"),
                             *atlas_cell.simulator_args(v, fstar, 0.0, atlas_cell.DT_OUT))
    return f"V = {v:g} m/s, F* = {fstar:g}: {proc.stderr.strip()}" if proc.returncode else None


def run_cell(name: str) -> None:
    try:
        v, fstar = CELLS.parse(name)
    except ValueError:
        sys.exit(f"atlas: {name!r} is not a cell name V<v>_F<f> (see `python3 -m "
                 "mlgshimmy.studies.atlas targets`)")
    rundir = os.path.dirname(CELLS.result_path(v, fstar))
    os.makedirs(rundir, exist_ok=True)
    result = atlas_cell.cell(v, fstar, rundir)
    # written whole or not at all: make sees a result only when it is complete
    CELLS.write(v, fstar, result)
    print(f"atlas: {name}: {result['label']} ({result['cpu_seconds']:.1f} s CPU)")


def summary(points: Sequence[Tuple[float, float]], cells: Sequence[Mapping[str, Any]],
            provenance: Optional[Mapping[str, Any]]) -> None:
    """summary.txt, summary.json and the plots of the cells (their records,
    every cell's checked present and of one provenance by shared.jobs.grid)."""
    counts = {}
    for c in cells:
        counts[c["label"]] = counts.get(c["label"], 0) + 1
    cpu = [c["cpu_seconds"] for c in cells]
    lines = [f"atlas: {len(cells)} cells, y_fp = {atlas_cell.FREEPLAY['yfp']:g} mm, epsilon = "
             f"{freeplay.epsilon(atlas_cell.FREEPLAY):g} mm; starts " +
             ", ".join(f"{k} psi0 = {v:g} rad" for k, v in atlas_cell.STARTS.items())
             + (f"; {gear.describe()}" if gear.describe() else ""),
             f"CPU per cell: mean {sum(cpu) / len(cpu):.2f} s, max {max(cpu):.2f} s; "
             f"total {sum(cpu):.0f} s", "cells by label:"]
    lines += [f"  {n:5d}  {lab}" for lab, n in sorted(counts.items(), key=lambda x: -x[1])]
    lines.append("V [m/s]  F*  label  |  per start: kind amplitude[rad] frequency[Hz] "
                 "mean[rad] peak spread, its trend [1/s] (modulation [Hz]) [time limit s]; "
                 "domain: the reason, and the state before it")
    for c in cells:
        parts = []
        for start, s in c["starts"].items():
            if s["kind"] == "domain":
                text = f"{start}: domain ({s['reason']})"
                if s.get("before"):
                    text += f" after {start_text(s['before'])}"
                parts.append(text)
                continue
            parts.append(f"{start}: {start_text(s)}")
        lines.append(f"{c['V']:g} {c['Fstar']:g} {c['label']} | " + "; ".join(parts))
    agreement = fig11_agreement(cells)
    if agreement is not None:
        lines += atlas_compare.report(agreement)
    text = "\n".join(lines) + "\n"
    stored = {"provenance": provenance, "cells": cells, "fig11_agreement": agreement}
    for name, content in (("summary.txt", text), ("summary.json", json.dumps(stored, indent=1))):
        jobs.write_text(os.path.join(CELLS.directory, name), content)
    print("\n".join(lines[:3 + len(counts)]))
    if agreement is not None:
        print("\n".join(atlas_compare.report(agreement)))
    print(f"atlas: wrote {CELLS.directory}/summary.txt, summary.json")
    from mlgshimmy.studies.atlas import plot as atlas_plot
    atlas_plot.plot(cells, atlas_cell.NAMES, atlas_cell.KINDS)
    if agreement is not None:
        atlas_plot.overlay(cells, agreement, jobs.read("fig11"))


def start_text(s: Mapping[str, Any]) -> str:
    """One start's end state in a line of summary.txt."""
    text = f"{s['kind']} {s['amplitude_rad']:.4g} {s['frequency_hz']:.3g} {s['mean_rad']:.3g}"
    if s["frequency_hz"] > 0:       # a stationary state has no peaks to spread
        text += f" spread {s['peak_spread']:.2g}"
    if s.get("spread_rate") is not None:
        text += f" {s['trend']} {s['spread_rate']:+.3g}"
    if s.get("unstable_by"):
        text += f", on the orbit {s['unstable_by']} shows unstable"
    if s.get("modulation_hz"):
        text += f" ({s['modulation_hz']:.3g})"
    return text + f" [{s['t_end']:g}]"


def fig11_agreement(cells: Sequence[Mapping[str, Any]]) -> Optional[Dict[str, Any]]:
    """atlas_compare.compare against Fig. 11's cached regions, or None (said
    why) when there is no cached Fig. 11 with a region map."""
    try:
        fig11 = jobs.read("fig11")
    except jobs.MissingResult as exc:
        print(f"atlas: no comparison with Fig. 11: {exc}")
        return None
    if "region_map" not in fig11:
        print("atlas: no comparison with Fig. 11: its cached result has no region_map "
              f"({jobs.path('fig11')}; run `make fig11`)")
        return None
    return atlas_compare.compare(cells, fig11)


def main() -> None:
    jobgrid.main("atlas", __doc__.splitlines()[0], "cell", CELLS,
                 [("--V", DEFAULT_V, "speeds [m/s]"), ("--Fstar", DEFAULT_FSTAR, "loads F*")],
                 grid, run_job=run_cell, problem=problem, summary=summary)


if __name__ == "__main__":
    main()
