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
A cell with a start that did not settle has no code and counts as a
disagreement ("not settled").  The codes are compared on the bits in
COMPARED: Fig. 11 sets the yaw bit over the whole band between the
pitchforks, where the yawed equilibria exist, without their stability, while
the atlas sets it only where a start settles on one; cells whose yaw bits
differ are counted apart ("yaw_differs").
"""
import numpy

from mlgshimmy.shared import regions

CODES = regions.ATTRACTORS
SCALE = (600.0, 3.5)      # V [m/s], F*: the plane's extent
NEAR = 0.01               # distance to a curve, in units of SCALE
COMPARED = ~CODES["yaw"]  # bits compared (see above)


def cell_code(cell):
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


def code_name(code, names=None):
    """A code spelt out: its region name from Fig. 11 if it has one, else
    the attractor kinds joined by "+"."""
    if code is None:
        return "not settled"
    if names and str(code) in names:
        return names[str(code)]
    return " + ".join(k for k, bit in CODES.items() if code & bit) or "none"


def region_at(region_map, v, fstar):
    """Fig. 11's region code at the grid point nearest (v, fstar)."""
    i = int(numpy.argmin(numpy.abs(numpy.asarray(region_map["Fstar"]) - fstar)))
    j = int(numpy.argmin(numpy.abs(numpy.asarray(region_map["V"]) - v)))
    return int(region_map["code"][i][j])


def curve_distance(curves, v, fstar):
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


def compare(cells, fig11):
    """Every cell sorted into on a curve / agrees / disagrees, and the
    fraction of the cells off the curves that agree."""
    region_map, curves = fig11["region_map"], fig11["edge_curves"]
    names = region_map.get("names", {})
    out = {"criterion": f"a cell is on a curve if an edge curve of Fig. 11 passes within "
                        f"{NEAR:g} of it in (V / {SCALE[0]:g} m/s, F* / {SCALE[1]:g})",
           "compared_bits": "all but off-centre yaw (see yaw_differs)",
           "on_curve": [], "agree": [], "disagree": [], "yaw_differs": []}
    for c in cells:
        atlas, region = cell_code(c), region_at(region_map, c["V"], c["Fstar"])
        distance, curve = curve_distance(curves, c["V"], c["Fstar"])
        entry = {"V": c["V"], "Fstar": c["Fstar"], "atlas": atlas, "fig11": region,
                 "atlas_name": code_name(atlas, names), "fig11_name": code_name(region, names),
                 "curve": curve, "curve_distance": round(distance, 4)}
        if distance < NEAR:
            out["on_curve"].append(entry)
            continue
        if atlas is not None and (atlas ^ region) & CODES["yaw"]:
            out["yaw_differs"].append(entry)
        if atlas is not None and atlas & COMPARED == region & COMPARED:
            out["agree"].append(entry)
        else:
            out["disagree"].append(entry)
    off = len(out["agree"]) + len(out["disagree"])
    out["off_curve"] = off
    out["fraction"] = len(out["agree"]) / off if off else None
    return out


def report(result):
    """Text lines: the fraction and every disagreeing cell."""
    lines = [f"atlas vs Fig. 11: {len(result['agree'])} of {result['off_curve']} cells off the "
             f"curves agree ({100 * (result['fraction'] or 0):.1f} %); "
             f"{len(result['on_curve'])} cells on a curve not compared ({result['criterion']}); "
             f"yaw bit not compared, it differs in {len(result['yaw_differs'])} cells"]
    for e in result["disagree"]:
        lines.append(f"  disagree V = {e['V']:g}, F* = {e['Fstar']:g}: atlas {e['atlas_name']}, "
                     f"Fig. 11 {e['fig11_name']} (nearest curve {e['curve']}, "
                     f"{e['curve_distance']:.3f})")
    return lines
