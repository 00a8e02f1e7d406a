"""Fig. 11's region map: the plane cut by the curves, each piece labelled
by the attractors the slices' samples find there (shared.regions)."""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.figures.fig11.plane import F_GRID, FREEPLAY, GEOMETRY, V_GRID, V_MAX, V_MIN
from mlgshimmy.figures.fig11.tori import torus_speed
from mlgshimmy.shared import jobs
from mlgshimmy.shared import regions
from mlgshimmy.shared import yawed

ATTRACTORS, NAMES = regions.ATTRACTORS, regions.ATTRACTOR_NAMES
BAND = "; stable off-centre yaw equilibria"
PIECE_DISAGREEMENT = 0.05   # a piece whose samples disagree more than this is reported
REGION_ALPHA = 0.8          # the regions' fills under the curves


def slice_codes(orbits: Mapping[str, Sequence[Tuple[float, float]]]) -> numpy.ndarray:
    """The orbit bits ("low", "high") along V_GRID on one slice, from its
    stable V-intervals (stable_orbits)."""
    out = numpy.zeros(len(V_GRID), dtype=int)
    for kind, intervals in orbits.items():
        for lo, hi in intervals:
            out[(V_GRID >= lo) & (V_GRID <= hi)] |= ATTRACTORS[kind]
    return out


def slice_row(Fstar: float) -> int:
    return int(numpy.argmin(numpy.abs(F_GRID - Fstar)))


def curve_list(drawn: Mapping[str, Any], pitchforks: Sequence[float],
               lift: Optional[Mapping[str, Any]] = None) -> List[Dict[str, Any]]:
    """Every curve that bounds a region: [{"name", "kind", "V", "Fstar"}]
    (the pitchfork lines as two points each; the lift-off edge if any), and
    the tongue's torus curve (kind "tongue": it bounds no region of the map,
    region_map leaves it out; the tongue is a few m/s wide)."""
    out = []
    for kind in ("hopf", "fold", "torus", "tongue"):
        for n, diagram in enumerate(drawn.get(kind, [])):
            for m, branch in enumerate(jobs.loaded(diagram)):
                out.append({"name": f"{kind}{n + 1}.{m + 1}", "kind": kind,
                            "V": branch["V"], "Fstar": branch["Fstar"]})
    out += [{"name": f"pitchfork{n + 1}", "kind": "pitchfork", "V": [V_MIN, V_MAX],
             "Fstar": [f, f]} for n, f in enumerate(pitchforks)]
    if lift:
        out.append({"name": "liftoff", "kind": "liftoff", "V": lift["V"],
                    "Fstar": lift["Fstar"]})
    return out


def yaw_stable(parameter_set: str = "figures") -> numpy.ndarray:
    """[F*, V] on F_GRID x V_GRID: True where a stable off-centre yawed
    equilibrium exists (shared.yawed: the stationary states off straight
    rolling, on both sides, and the eigenvalues of the exact Jacobian there;
    the band between the pitchforks at the paper's gear, up to the Hopf
    points of the yawed states in V, 123-138 m/s)."""
    return yawed.stable_grid(parameter_set, F_GRID, V_GRID, FREEPLAY, **GEOMETRY)


def region_map(sr_stable: numpy.ndarray, orbits: Sequence[Tuple[float, Mapping[str, Any]]],
               edge_curves: Sequence[Mapping[str, Any]], yaw: numpy.ndarray,
               lift: Optional[Mapping[str, Any]] = None) -> Tuple[numpy.ndarray, Dict[str, Any]]:
    """(code [F*, V] on F_GRID x V_GRID, check): the regions bounded by the
    edge curves (and by the edges of the straight-rolling stability grid,
    which are the Hopf curves and pitchforks again, closing them where AUTO
    stopped), each labelled by the attractors the slices find inside it
    (regions.paint).  Straight rolling and off-centre yaw are exact
    (eigenvalue grids sr_stable, yaw: yaw_stable); where a slice finds no stable orbit nor straight
    rolling beyond its first torus curve (torus_speed), the attractor is
    quasi-periodic shimmy (simulations, docs/reproduction.md).  orbits:
    [(slice load, its orbit bits along V_GRID)].  Right of the lift-off
    edge (lift, liftoff_edge) the samples of the slices and of the edge's
    loads say lift-off: the shimmy there grows until a wheel lifts off."""
    samples = numpy.full(sr_stable.shape, -1, dtype=int)
    for Fstar, row in orbits:
        samples[slice_row(Fstar)] = numpy.where(
            (V_GRID >= torus_speed(edge_curves, Fstar)) & (row == 0), ATTRACTORS["quasi"], row)
    if lift:
        F_edge = [f for _, f in lift["points"]]
        for Fstar in [f for f, _ in orbits] + list(F_edge[1:-1]):
            if F_edge[0] <= Fstar <= F_edge[-1]:
                beyond = V_GRID >= numpy.interp(Fstar, lift["Fstar"], lift["V"])
                samples[slice_row(Fstar), beyond] = ATTRACTORS["liftoff"]
    edges = regions.curve_pixels(V_GRID, F_GRID, [(c["V"], c["Fstar"]) for c in edge_curves
                                                    if c["kind"] != "tongue"])
    edges |= regions.boundary_pixels(sr_stable.astype(int))
    painted, check = regions.paint(edges, samples)
    found = painted | numpy.where(sr_stable, ATTRACTORS["straight"], 0) \
        | numpy.where(yaw, ATTRACTORS["yaw"], 0)
    return found, check


def region_name(value: int) -> str:
    """The name of a region code (the result's "names")."""
    names = [NAMES[bit] for bit in sorted(NAMES) if value & bit]
    if not names:
        return "no stable state found"
    return ("" if len(names) == 1 else "coexisting: ") + " / ".join(names)


# the attractors in the legend's words
WORDS = {"straight": "straight rolling", "low": "low-frequency shimmy",
         "high": "high-frequency shimmy", "yaw": "yawed rolling",
         "quasi": "quasi-periodic shimmy", "liftoff": "a wheel lifts off"}
# the map's fill tells the shimmy (or lift-off) stable there; a pattern over
# it, that straight rolling or yawed rolling is stable too
FILLED = ("low", "high", "quasi", "liftoff")
PATTERNS = {"straight": "..", "yaw": "///"}


def filled_kinds(code: int) -> Tuple[str, ...]:
    """The kinds of a region code that its fill tells (FILLED's order)."""
    return tuple(kind for kind in FILLED if code & ATTRACTORS[kind])


def fill_words(kinds: Tuple[str, ...]) -> str:
    """A fill in the reader's words ("low- or high-frequency shimmy",
    "quasi-periodic shimmy or a wheel lifts off"; "no shimmy" for none)."""
    if kinds == ("low", "high"):
        return "low- or high-frequency shimmy"
    return " or ".join(WORDS[kind] for kind in kinds) or "no shimmy"


def shade(ax: Any, found: numpy.ndarray) -> Tuple[Dict[Tuple[str, ...], Any], List[str]]:
    """Paint the map: each pixel filled by the shimmy kinds stable there
    (palette.REGION), dotted where straight rolling is stable too and
    hatched where yawed rolling is (PATTERNS).  Returns ({kinds: fill
    colour} of the fills present, [the kinds of PATTERNS present])."""
    from matplotlib.colors import ListedColormap

    from mlgshimmy.shared.draw import palette
    fills = found & sum(ATTRACTORS[kind] for kind in FILLED)
    values = numpy.unique(fills).tolist()
    extra = iter(palette.categories(20))
    kinds = [filled_kinds(v) for v in values]
    colours = [palette.REGION.get(k) or next(extra) for k in kinds]
    half_V, half_F = 0.5 * (V_GRID[1] - V_GRID[0]), 0.5 * (F_GRID[1] - F_GRID[0])
    ax.imshow(numpy.searchsorted(values, fills), cmap=ListedColormap(colours), vmin=-0.5,
              vmax=len(values) - 0.5, alpha=REGION_ALPHA, origin="lower", aspect="auto",
              interpolation="nearest", extent=(V_GRID[0] - half_V, V_GRID[-1] + half_V,
                                               F_GRID[0] - half_F, F_GRID[-1] + half_F))
    patterned = []
    for kind, hatch in PATTERNS.items():
        inside = ((found & ATTRACTORS[kind]) != 0).astype(float)
        if inside.any():
            ax.contourf(V_GRID, F_GRID, inside, levels=[0.5, 1.5], colors="none",
                        hatches=[hatch])
            patterned.append(kind)
    return dict(zip(kinds, colours)), patterned
