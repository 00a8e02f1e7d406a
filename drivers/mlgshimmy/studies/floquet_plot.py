"""The Floquet multipliers along one periodic-orbit run: why a point is TR.

    make floquet RUN=build/fig10/po3         # any run directory's d.<name>
    python3 -m mlgshimmy.studies.floquet_plot build/fig10/po3

Reads AUTO's d-file of the run (shared.floquet.read: the multipliers of
every point, no AUTO needed) and draws the modulus of each multiplier
against the run's continued parameter, the unit circle as a line, with the
crossings marked: a complex pair leaving or entering it (torus,
Neimark-Sacker: floquet.torus_crossings), a real multiplier through -1
(period doubling) and one other than the trivial multiplier through +1 (a
fold), each between the two points where the count beyond changes.  The figure goes to $MLG_RUN_ROOT/figures/floquet_<run>.png and the
crossings are printed.
"""
from __future__ import annotations

import os
import sys
from typing import Dict, List, Mapping, Sequence, Tuple

import numpy

from mlgshimmy.shared import floquet, paths

# What make, make help, make submit and the report know of this study
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "floquet": {
        "usage": "floquet RUN=<dir>/<run>",
        "help": "Floquet multipliers along one orbit run, torus/PD/fold crossings",
        "time": "2 s",
        "carries": ["RUN"],
    },
}

REAL = floquet.COMPLEX     # |Im mu| up to this: a real multiplier


def real_crossings(steps: Sequence[Tuple[float, numpy.ndarray]], through: float) -> List[float]:
    """Where the number of real multipliers beyond `through` (below -1:
    period doubling; above +1, the trivial multiplier, the one nearest 1,
    left out: a fold) changes between two points: [parameter value], midway
    between them."""
    out, previous = [], None
    for value, mults in steps:
        rest = numpy.delete(mults, numpy.argmin(numpy.abs(mults - 1.0)))
        real = rest[numpy.abs(rest.imag) <= REAL].real
        count = int(numpy.sum(real * through > 1.0))
        if previous is not None and count != previous[1]:
            out.append(0.5 * (previous[0] + value))
        previous = (value, count)
    return out


def crossings(steps: Sequence[Tuple[float, numpy.ndarray]]) -> Dict[str, List[float]]:
    """{"torus": [values], "period doubling": [values], "fold": [values]}."""
    return {"torus": [c["value"] for c in floquet.torus_crossings(steps)],
            "period doubling": real_crossings(steps, -1.0),
            "fold": real_crossings(steps, 1.0)}


def plot(steps: Sequence[Tuple[float, numpy.ndarray]], found: Mapping[str, List[float]],
         title: str, out: str) -> None:
    import matplotlib.pyplot as plt

    from mlgshimmy.shared import draw
    values = numpy.array([v for v, _ in steps])
    moduli = numpy.array([numpy.sort(numpy.abs(m))[::-1] for _, m in steps])
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for k in range(moduli.shape[1]):
        ax.semilogy(values, moduli[:, k], color=draw.STABLE, lw=0.9, alpha=0.8)
    ax.axhline(1.0, color=draw.NEUTRAL, lw=0.8, ls=":")
    styles = {"torus": ("TR", "^"), "period doubling": ("PD", "D"), "fold": ("LP", "s")}
    for kind, values in found.items():
        label, marker = styles[kind]
        if values:
            ax.plot(values, [1.0] * len(values), ls="", marker=marker, mfc=draw.palette.OPEN, mec=draw.NEUTRAL,
                    label=f"{label}: {kind} ({len(values)})")
    ax.set_xlabel("continued parameter")
    ax.set_ylabel("|Floquet multiplier|")
    ax.set_title(title)
    if any(found.values()):
        ax.legend(loc="best", fontsize="small")
    draw.save(fig, out)


def main(argv: Sequence[str]) -> None:
    if len(argv) != 1:
        sys.exit("usage: python3 -m mlgshimmy.studies.floquet_plot <run directory>/<run name> "
                 "(its d-file is <run directory>/d.<run name>)")
    where, name = os.path.split(os.path.abspath(argv[0]))
    path = os.path.join(where, f"d.{name}")
    if not os.path.isfile(path):
        sys.exit(f"floquet: RUN={argv[0]}: no d-file {path} (a periodic-orbit run, e.g. "
                 "RUN=build/fig10/po3 after `make fig10`)")
    steps = [(v, m) for v, m in floquet.read(path) if len(m)]
    if not steps:
        sys.exit(f"floquet: RUN={argv[0]}: {path} holds no Floquet multipliers (not a "
                 "periodic-orbit run)")
    found = crossings(steps)
    for kind, values in found.items():
        print(f"floquet: {name}: {kind}: " + (", ".join(f"{v:.6g}" for v in values) or "none"))
    tag = os.path.relpath(os.path.join(where, name), paths.run_root()).replace(os.sep, "_")
    plot(steps, found, f"Floquet multipliers along {os.path.relpath(path, paths.ROOT)}",
         f"floquet_{tag}")


if __name__ == "__main__":
    main(sys.argv[1:])
