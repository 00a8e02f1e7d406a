"""The attractor atlas against Fig. 11's regions: cell by cell, away from
the curves that bound the regions.

Fig. 11's cached result (jobs.read("fig11"), plain JSON, no AUTO) holds
"region_map" {"V", "Fstar", "code" (rows per F*), "names"} and
"edge_curves" [{"name", "kind", "V", "Fstar"}].  A region code is the OR of
the bits in CODES over the attractors that coexist there; a cell's code is
the OR over the end states its starts reached (cell_code).

A cell is "on a curve" if an edge curve passes within NEAR of it, measured
in V / 600 m/s and F* / 3.5 (the plane drawn as a unit square; NEAR = 0.01
is 6 m/s or 0.035): there one grid point cannot say on which side it lies.
The edge of Fig. 11's off-centre-yaw region (where a stable yawed
equilibrium exists: an eigenvalue grid, its edges the pitchforks or folds
of the yawed states and their Hopf points in V) counts as a curve too,
measured on region_map (yaw_edge_distance).  A cell with a start that did
not settle has no code and counts as a disagreement ("not settled").  Every
bit is compared, off-centre yaw included; a disagreement names the bits
that differ ("differs").
"""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import regions

CODES = regions.ATTRACTORS
SCALE = (600.0, 3.5)      # V [m/s], F*: the plane's extent
NEAR = 0.01               # distance to a curve, in units of SCALE


def cell_code(cell: Mapping[str, Any]) -> Optional[int]:
    """The OR of the cell's end states (CODES), or None if one is unsettled.
    Leaving the domain counts only where no start settled in it (lift-off
    as the region's fate): beside settled states it is a large start's
    transient lifting a wheel, not a region of Fig. 11."""
    states = list(cell["starts"].values())
    kinds = [s["kind"] for s in states]
    if "unsettled" in kinds:
        return None
    settled = [k for k in kinds if k != "domain"]
    return regions.code(settled or kinds)


def code_name(code: Optional[int], names: Optional[Mapping[str, str]] = None) -> str:
    """A code spelt out: its region name from Fig. 11 if it has one, else
    the attractor kinds joined by "+"."""
    if code is None:
        return "not settled"
    if names and str(code) in names:
        return names[str(code)]
    return " + ".join(k for k, bit in CODES.items() if code & bit) or "none"


def region_at(region_map: Mapping[str, Any], v: float, fstar: float) -> int:
    """Fig. 11's region code at the grid point nearest (v, fstar)."""
    i = int(numpy.argmin(numpy.abs(numpy.asarray(region_map["Fstar"]) - fstar)))
    j = int(numpy.argmin(numpy.abs(numpy.asarray(region_map["V"]) - v)))
    return int(region_map["code"][i][j])


def curve_distance(curves: Sequence[Mapping[str, Any]], v: float,
                   fstar: float) -> Tuple[float, Optional[str]]:
    """(distance, curve name) of the nearest edge curve to (v, fstar), in
    units of SCALE; a polyline's segments count, not only its vertices."""
    best = (numpy.inf, None)
    p = numpy.array([v / SCALE[0], fstar / SCALE[1]])
    for curve in curves:
        xy = numpy.column_stack([numpy.asarray(curve["V"], float) / SCALE[0],
                                 numpy.asarray(curve["Fstar"], float) / SCALE[1]])
        xy = xy[numpy.all(numpy.isfinite(xy), axis=1)]
        if len(xy) == 0:
            continue
        if len(xy) == 1:
            d = float(numpy.hypot(*(xy[0] - p)))
        else:
            a, b = xy[:-1], xy[1:]
            ab = b - a
            t = numpy.clip(numpy.einsum("ij,ij->i", p - a, ab)
                           / numpy.maximum(numpy.einsum("ij,ij->i", ab, ab), 1e-30), 0, 1)
            d = float(numpy.min(numpy.hypot(*(a + t[:, None] * ab - p).T)))
        if d < best[0]:
            best = (d, curve["name"])
    return best


def yaw_edge_distance(region_map: Mapping[str, Any], v: float, fstar: float) -> float:
    """Distance (in units of SCALE) from (v, fstar) to the nearest grid point
    of region_map whose yaw bit differs from the one at (v, fstar); inf if
    the bit is the same everywhere."""
    F, V = numpy.asarray(region_map["Fstar"], float), numpy.asarray(region_map["V"], float)
    yaw = (numpy.asarray(region_map["code"]) & CODES["yaw"]) != 0
    other = yaw != bool(region_at(region_map, v, fstar) & CODES["yaw"])
    if not other.any():
        return numpy.inf
    i, j = numpy.nonzero(other)
    return float(numpy.min(numpy.hypot((V[j] - v) / SCALE[0], (F[i] - fstar) / SCALE[1])))


def compare(cells: Sequence[Mapping[str, Any]], fig11: Mapping[str, Any]) -> Dict[str, Any]:
    """Every cell sorted into on a curve / agrees / disagrees, and the
    fraction of the cells off the curves that agree."""
    region_map, curves = fig11["region_map"], fig11["edge_curves"]
    names = region_map.get("names", {})
    out = {"criterion": f"a cell is on a curve if an edge curve of Fig. 11 passes within "
                        f"{NEAR:g} of it in (V / {SCALE[0]:g} m/s, F* / {SCALE[1]:g})",
           "compared_bits": "all, off-centre yaw included",
           "on_curve": [], "agree": [], "disagree": []}
    for c in cells:
        atlas, region = cell_code(c), region_at(region_map, c["V"], c["Fstar"])
        distance, curve = curve_distance(curves, c["V"], c["Fstar"])
        yaw_edge = yaw_edge_distance(region_map, c["V"], c["Fstar"])
        if yaw_edge < distance:
            distance, curve = yaw_edge, "yaw edge"
        entry = {"V": c["V"], "Fstar": c["Fstar"], "atlas": atlas, "fig11": region,
                 "atlas_name": code_name(atlas, names), "fig11_name": code_name(region, names),
                 "curve": curve, "curve_distance": round(distance, 4)}
        if distance < NEAR:
            out["on_curve"].append(entry)
            continue
        if atlas == region:
            out["agree"].append(entry)
        else:
            entry["differs"] = "unsettled" if atlas is None else code_name(atlas ^ region)
            out["disagree"].append(entry)
    off = len(out["agree"]) + len(out["disagree"])
    out["off_curve"] = off
    out["fraction"] = len(out["agree"]) / off if off else None
    return out


def report(result: Mapping[str, Any]) -> List[str]:
    """Text lines: the fraction and every disagreeing cell."""
    lines = [f"atlas vs Fig. 11: {len(result['agree'])} of {result['off_curve']} cells off the "
             f"curves agree ({100 * (result['fraction'] or 0):.1f} %); "
             f"{len(result['on_curve'])} cells on a curve not compared ({result['criterion']}); "
             f"bits compared: {result['compared_bits']}"]
    for e in result["disagree"]:
        lines.append(f"  disagree V = {e['V']:g}, F* = {e['Fstar']:g}: atlas {e['atlas_name']}, "
                     f"Fig. 11 {e['fig11_name']} (differ in {e['differs']}; nearest curve "
                     f"{e['curve']}, {e['curve_distance']:.3f})")
    return lines
