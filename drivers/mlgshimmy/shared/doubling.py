"""Period-doubled orbits: at each period-doubling point (PD) of computed
orbit runs, AUTO switches to the branch of twice the period (ISW = -1)
and follows it across the figure's range (continuation.periodic_from:
its run and retry ladder), up to where it meets the orbits of single
period again.  A PD point of a doubled branch is marked by the figure,
not followed further (a cascade is not chased).

    doubled = follow(rundir, "pd", diagram.branches, "Fstar", (0.02, 3.5), DS=0.002)
    for point, run in doubled: ...   # the PD solution and the run from it
"""
from __future__ import annotations

from typing import Any, List, Sequence, Tuple

from mlgshimmy.shared import continuation as ct

# relative: a PD point this close to a doubled run's end (its BP) is that
# end; AUTO places the two apart by its own tolerances (Fig. 12 at (-10, 20)
# deg: PD2 at F* = 1.05119 on the orbits, the doubled run's BP at 1.05107)
REACHED = 1e-3


def points(diagrams: Sequence[Any]) -> List[Any]:
    """The PD solutions of the runs `diagrams`, in order."""
    return [point for diagram in diagrams for point in diagram("PD")]


def follow(rundir: str, name: str, diagrams: Sequence[Any], parameter: str,
           bounds: Sequence[float], allow_mx: Any = ct.EDGE,
           **steps: Any) -> List[Tuple[Any, Any]]:
    """[(PD point, run <name><k>)] for each PD point of `diagrams`: the
    orbits of twice the period from it, continued in `parameter` until it
    leaves `bounds` or meets the orbits of single period again (their
    branch point, BP, in the doubled period: another PD point, from which
    no second run starts); steps: AUTO constants and the overlay of the
    runs they branch from.  An MX is kept only where the branch ends
    (continuation.EDGE), else the ladder, then an error."""
    out, reached = [], []
    for k, point in enumerate(points(diagrams), 1):
        value = point[parameter]
        if any(abs(value - v) <= REACHED * max(1.0, abs(value)) for v in reached):
            continue
        run = ct.periodic_from(rundir, f"{name}{k}", point, parameter,
                               stop={parameter: list(bounds)}, ISW=-1, STOP=["BP1"],
                               allow_mx=allow_mx, **steps)
        reached += [p[parameter] for p in run("BP")]
        out.append((point, run))
    return out


def describe(parameter: str, doubled: Sequence[Tuple[Any, Any]]) -> List[str]:
    """The table's lines: where each PD point is and where its doubled
    orbits run and end (BP: back on the single-period orbits, at another
    PD point); one line saying there is none otherwise."""
    if not doubled:
        return ["period doubling: none on these orbits"]
    lines = []
    for k, (point, run) in enumerate(doubled, 1):
        values = [v for branch in run for v in branch[parameter]]
        ends = [f"{p['TY name']} at {p[parameter]:.6g}" for p in run()
                if p["TY name"] in ("UZ", "EP", "MX", "BP")]
        lines.append(f"PD{k} at {parameter} = {point[parameter]:.6g} (period "
                     f"{point['T']:.4g} s): orbits of twice the period followed over "
                     f"{parameter} = {min(values):.6g}-{max(values):.6g}, "
                     f"{sum(len(b[parameter]) for b in run)} points, "
                     f"ending in {', '.join(ends) or '-'}")
    return lines
