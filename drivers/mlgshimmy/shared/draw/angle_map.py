"""A quantity over a (rho, mu) grid of side-stay angles as labelled cells: the
sweep's critical speed and each panel of the design map; and the limit of a
colour scale of changes that several such maps share."""
from __future__ import annotations

from typing import Any, Callable, Iterable, Optional, Sequence

import numpy

from mlgshimmy.shared.draw import palette

CHANGE_STEPS = (5.0, 10.0, 20.0, 50.0)   # [%]: the limits a shared scale of changes takes
# A grid with more cells than this along an axis is drawn without its
# numbers (they would not be legible: the table holds them), and with every
# k-th angle named so that at most this many are.
MAX_LABELLED = 11


def angle_map(ax: Any, rhos: Sequence[float], mus: Sequence[float], values: numpy.ndarray,
              text: Callable[[float], str], cmap: Any = palette.SEQUENCE_MAP,
              norm: Any = None, numbers: Optional[numpy.ndarray] = None,
              fontsize: float = 8) -> Any:
    """values[i, j] at (rhos[j], mus[i]) [deg] as one cell each (evenly
    spaced whatever the angles' spacing), coloured by `norm` (a matplotlib
    Normalize, which several maps may share; default: the values' range)
    and labelled text(number), numbers[i, j] (default: the values), in a
    colour readable on its fill (white where the value is not finite), up
    to MAX_LABELLED cells along each axis.  Returns the image, for a colour
    bar."""
    numbers = values if numbers is None else numbers
    mesh = ax.imshow(values, origin="lower", aspect="auto", cmap=cmap, norm=norm,
                     extent=(-0.5, len(rhos) - 0.5, -0.5, len(mus) - 0.5))
    labelled = max(len(rhos), len(mus)) <= MAX_LABELLED
    for i in range(len(mus)) if labelled else ():
        for j in range(len(rhos)):
            v = values[i, j]
            fill = mesh.cmap(mesh.norm(v)) if numpy.isfinite(v) else "white"
            ax.text(j, i, text(numbers[i, j]), ha="center", va="center", fontsize=fontsize,
                    color=palette.text_on(fill))
    for set_ticks, angles in ((ax.set_xticks, rhos), (ax.set_yticks, mus)):
        every = -(-len(angles) // MAX_LABELLED)
        named = range(0, len(angles), every)
        set_ticks(list(named), [f"{angles[k]:g}" for k in named])
    ax.set_xlabel(r"$\rho$ [deg]")
    ax.set_ylabel(r"$\mu$ [deg]")
    ax.grid(False)
    return mesh


def change_limit(changes: Iterable[numpy.ndarray]) -> float:
    """The limit L [%] of one scale -L..L shared by maps of changes: the
    least of CHANGE_STEPS that holds the largest finite |change|, else the
    last (beyond it the colours saturate)."""
    largest = max((float(numpy.max(numpy.abs(c[numpy.isfinite(c)])))
                   for c in changes if numpy.isfinite(c).any()), default=0.0)
    return next((step for step in CHANGE_STEPS if largest <= step), CHANGE_STEPS[-1])
