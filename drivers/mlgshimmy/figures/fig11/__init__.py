"""Fig. 11: the (V, F*) plane with +-1 mm of freeplay (epsilon = 0.1 y_fp):
the Hopf curves of straight rolling, the curves of folds of periodic orbits,
the pitchfork lines, and the zero-freeplay Hopf curve; regions shaded by the
attractors that coexist there.

The curves are AUTO continuations started from the Fig. 10 special points
(F* = 1), the torus curve of the large-amplitude orbits (AUTO, from a
torus point at F* = 0.5625) and the edges of two tongues of instability
left of it (other Floquet pairs, from F* = 0.8125 and 0.9375; they bound no
region).  The
regions are bounded by those curves and by the edges of the straight-rolling stability grid (exact Jacobian
eigenvalues); they are labelled, not bounded, by the stable low- (< 8 Hz) and high-frequency orbits
of one-parameter diagrams in V (continuation.speed_diagram and the
large-amplitude family) on a set of loads (shared.regions).  The wheel lift-off
region is bounded by its edge located by simulation (liftoff).  result.json
holds the map ("region_map": V, Fstar, code per F* row, names) and the
curves bounding it ("edge_curves") for the attractor atlas."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence

import numpy

from mlgshimmy.figures.fig11.curves import (slice_hopf_curves, stage_switch, stored_curves,
                                            upper_fold_curves)
from mlgshimmy.figures.fig11 import located
from mlgshimmy.figures.fig11.ends import (FOLD_TOL, closing_segments, explained, joins_outside,
                                          mx_ends, on_hopf_locus)
from mlgshimmy.figures.fig11.liftoff_edge import (LIFTOFF_ENDS, LIFTOFF_LOADS, liftoff_edge,
                                                  liftoff_end, liftoff_speed)
from mlgshimmy.figures.fig11.orbits import (large_family, slice_diagram, stable_orbits,
                                            straight_rolling_stable)
from mlgshimmy.figures.fig11.plane import F_GRID, SLICES, V_GRID, on_curves
from mlgshimmy.figures.fig11.regions import (ATTRACTORS, BAND, PIECE_DISAGREEMENT, curve_list,
                                                region_map, region_name, slice_codes, yaw_stable)
from mlgshimmy.figures.fig11.tori import PINNED, TONGUE_TOL, tongue_curve, tongue_parts, torus_curves
from mlgshimmy.shared import codim2
from mlgshimmy.shared import jobs
from mlgshimmy.shared import liftoff


def parts() -> Dict[str, Any]:
    """The large-amplitude family, the curves from F* = 1, the lift-off
    speeds, the eigenvalue grid and one diagram in V per slice load:
    independent jobs; the torus curve and the tongue edges after the
    large part (from its diagrams in V), the fold curves from the slices'
    folds (upper_folds) after the slices, those from the slices' Hopf
    points (slice_hopf) after the fold curves and the lift-off edge's ends
    after the speeds.  Listed as make -jN should start them: the longest
    chains of parts first (large then torus, curves then upper_folds).
    The lift-off speeds and the two grids, independent and short, wait for
    the chains' inputs (jobs.Needs' after), so that make starts the torus
    and fold-curve parts as soon as those are done, not after the short
    parts (rho = -10, mu = 20 deg: the torus part, 421 s, started 150 s
    after its inputs)."""
    slice_parts = [f"slice_{Fstar:.4f}" for Fstar in SLICES]
    # with side-stay angles the torus part starts curves from the slices too
    work = {"large": large_family,
            "torus": jobs.Needs(["large"] + ([] if PINNED else slice_parts),
                                lambda p: torus_curves(p["large"]))}
    work.update({part: jobs.Needs(["large"], lambda _, part=part: tongue_curve(part))
                 for part in tongue_parts()})
    work["curves"] = stored_curves
    work["upper_folds"] = jobs.Needs(["curves"] + slice_parts, upper_fold_curves)
    work["slice_hopf"] = jobs.Needs(["curves", "upper_folds"], slice_hopf_curves)
    # the short independent parts wait for the long chains' inputs (jobs.Needs' after)
    chains = ["large", "curves"] + slice_parts
    liftoff_parts = [f"liftoff_{Fstar:.2f}" for Fstar in LIFTOFF_LOADS]
    work.update({part: jobs.Needs((), lambda _, Fstar=Fstar: liftoff_speed(Fstar), after=chains)
                 for part, Fstar in zip(liftoff_parts, LIFTOFF_LOADS)})
    work.update({part: jobs.Needs(liftoff_parts, lambda p, part=part: liftoff_end(p, part))
                 for part in LIFTOFF_ENDS})
    work["grid"] = jobs.Needs((), lambda _: straight_rolling_stable(), after=chains)
    work["yaw"] = jobs.Needs((), lambda _: yaw_stable(), after=chains)
    work.update({part: lambda Fstar=Fstar: slice_diagram(Fstar)
                 for part, Fstar in zip(slice_parts, SLICES)})
    return work


def compute(parts: Mapping[str, Any]) -> Dict[str, Any]:
    """The parts assembled: the curves, the torus points on the slices, the
    lift-off edge, and the region map bounded by the curves (region_map)."""
    stored = parts["curves"]
    slices = {Fstar: parts[f"slice_{Fstar:.4f}"] for Fstar in SLICES}
    large = parts["large"]
    orbits = [(Fstar, slice_codes(stable_orbits(part["branches"]
                                                + large.get(f"{Fstar:.4f}", []))))
              for Fstar, part in slices.items()]
    drawn = {kind: stored[kind] for kind in ("hopf", "fold", "zero")}
    drawn["hopf"] += parts["slice_hopf"]["curves"]
    drawn["fold"] += parts["upper_folds"]["curves"]
    drawn["torus"] = parts["torus"]["curves"]
    drawn["tongue"] = [curve for part in tongue_parts() for curve in parts[part]["curves"]] \
        + parts["torus"].get("tongue", [])
    switch = stage_switch()
    special = located.points(drawn)
    drawn["fold"] = located.past_gh(drawn["fold"], special, FOLD_TOL, switch)
    drawn["fold"] = located.retraced_past_gh(drawn["fold"], special, FOLD_TOL)
    pitchforks = stored["pitchfork"][1] + stored.get("stationary_folds", [])
    lift = liftoff_edge([parts[f"liftoff_{Fstar:.2f}"] for Fstar in LIFTOFF_LOADS],
                        [parts[part]["Fstar"] for part in LIFTOFF_ENDS])
    edges = curve_list(drawn, pitchforks, lift)
    joins, stops = mx_ends(drawn)
    joins = joins_outside(joins, switch)
    ends = explained(stops, switch, lift, [jobs.loaded(d) for d in drawn["fold"]],
                     at_gh=located.at_gh(special, FOLD_TOL))
    located.l2_signs(special, drawn["fold"], ends["generalised_hopf"])
    heuristic = explained(stops, switch, lift, at_gh=on_hopf_locus)["generalised_hopf"]
    notes = located.lines(special, switch) + gh_ends_compared(heuristic, ends["generalised_hopf"])
    edges += closing_segments(ends["liftoff"], lift)
    found, check = region_map(numpy.asarray(parts["grid"], dtype=bool), orbits, edges,
                              numpy.asarray(parts["yaw"], dtype=bool), lift)
    for row, col, n, votes in check["pieces"]:
        if n - max(votes.values()) > PIECE_DISAGREEMENT * n:
            print(f"REPORTED: fig11 region near V = {V_GRID[col]:.1f}, F* = {F_GRID[row]:.2f}: "
                  f"slice samples {votes} (labelled by the majority)")
    print(f"fig11: {check['disagree']} of {check['samples']} slice samples disagree with "
          "their region's label")
    for kind, why in (("stage_switch", "inside the oleo stage switch"),
                      ("generalised_hopf", "at a located generalised Hopf point"),
                      ("on_fold", "on a fold curve"),
                      ("liftoff", "at the lift-off edge"),
                      ("orbit_switch", "where its orbit grazes the oleo stage switch"),
                      ("open", "")):
        for stop in ends[kind]:
            print(f"{'' if why else 'REPORTED: '}fig11 {stop['curve']} stops (MX) "
                  f"{why + ' ' if why else ''}at V = {stop['V']:.4g}, F* = {stop['Fstar']:.4g}")
    names = {str(v): ((region_name(v & ~ATTRACTORS["yaw"]) if v & ~ATTRACTORS["yaw"] else "")
                      + (BAND if v & ATTRACTORS["yaw"] else "")).lstrip("; ")
             for v in numpy.unique(found).tolist()}
    # the tongue points that its continued edge passes through are drawn by
    # it (a tighter tolerance: the edge is nearly flat, dV/dF* ~ 850 m/s)
    tongue = [jobs.loaded(d) for d in drawn["tongue"]]
    points = [p for p in parts["torus"]["points"] if not on_curves(p, tongue, TONGUE_TOL)]
    return {"numbers": numbers(pitchforks, stored, drawn, points, lift, check, ends, special),
            "curves": drawn, "torus_points": points, "codim2": special, "codim2_notes": notes,
            "pitchfork": stored["pitchfork"], "mx_joins": joins,
            **({"stationary_folds": stored["stationary_folds"]}
               if "stationary_folds" in stored else {}),
            "mx_stops": ends["open"], "stage_switch_ends": ends["stage_switch"],
            "orbit_switch_ends": ends["orbit_switch"],
            "liftoff_ends": ends["liftoff"], "stage_switch": switch,
            "generalised_hopf_ends": ends["generalised_hopf"], "on_fold_ends": ends["on_fold"],
            "edge_curves": edges, "region_check": check,
            "liftoff": lift and {"points": lift["points"], "t_end": liftoff.T_END,
                                 "psi0": liftoff.PSI0},
            "region_map": {"V": V_GRID, "Fstar": F_GRID, "code": found, "names": names}}


def gh_ends_compared(on_locus: Sequence[Mapping[str, Any]],
                     at_gh: Sequence[Mapping[str, Any]]) -> List[str]:
    """Lines comparing the fold curves' ends named GH by a located point
    (`at_gh`) with those the Hopf-locus test (ends.GH_RATE) names
    (`on_locus`; ends inside the stage switch are neither)."""
    both = [s for s in on_locus if s in at_gh]
    lines = [f"fold curve ends on the Hopf locus (GH_RATE): {len(on_locus)}; at a located GH "
             f"point (within {FOLD_TOL:g}): {len(at_gh)}; both: {len(both)}"]
    lines += [f"{s['curve']} ends at V = {s['V']:.5g}, F* = {s['Fstar']:.5g} on the Hopf locus "
              "with no GH point located there: reported as a stop" for s in on_locus
              if s not in at_gh]
    lines += [f"{s['curve']} ends at V = {s['V']:.5g}, F* = {s['Fstar']:.5g} at a located GH "
              "point off the Hopf locus test" for s in at_gh if s not in on_locus]
    return lines


def numbers(pitchforks: Sequence[float], stored: Mapping[str, Any], drawn: Mapping[str, Any],
            points: Sequence[Mapping[str, Any]], lift: Optional[Mapping[str, Any]],
            check: Mapping[str, Any], ends: Mapping[str, Any],
            special: Sequence[Mapping[str, Any]]) -> Dict[str, Any]:
    """The figure's table (shared.paper.report; a side-stay geometry's
    beside the baseline's): the pitchfork loads (with side-stay angles the
    folds of the yawed states they became), the lift-off edge, how many
    curves of each kind, the torus points on none, the slice samples that
    disagree with their region and the MX stops on drawn curves (those
    inside the stage switch and at the lift-off edge apart)."""
    out = {f"pitchfork {k + 1} F*": f for k, f in enumerate(stored["pitchfork"][1])}
    if "stationary_folds" in stored:
        out.update({f"pitchfork {k + 1} F*": None for k in range(2)})
        out.update({f"yawed-state fold {k + 1} F*": f
                    for k, f in enumerate(stored["stationary_folds"])})
    if lift:
        V, F = numpy.array(lift["points"]).T
        out.update({"lift-off: least V [m/s]": float(V.min()),
                    "lift-off on V = 600 from F*": float(F[0]),
                    "lift-off on V = 600 up to F*": float(F[-1])})
    out.update({f"{kind} curves": len(drawn[kind]) for kind in ("hopf", "fold", "torus", "tongue")})
    out.update({"torus points on no curve": len(points),
                "slice samples off their region": check["disagree"],
                "MX stops on drawn curves": len(ends["open"]),
                "curve ends inside the stage switch": len(ends["stage_switch"]),
                "fold curve ends at a generalised Hopf point": len(ends["generalised_hopf"]),
                "torus curve ends on a fold curve": len(ends["on_fold"]),
                "curve ends at the lift-off edge": len(ends["liftoff"]),
                "curve ends where its orbit grazes the stage switch": len(ends["orbit_switch"])})
    out.update({f"{kind} points on the Hopf curves": sum(p["type"] == kind for p in special)
                for kind in codim2.TYPES})
    return out
