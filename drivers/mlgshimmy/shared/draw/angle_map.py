"""A quantity over a (rho, mu) grid of side-stay angles as labelled cells: the
sweep's critical speed and each panel of the design map."""
from __future__ import annotations

from typing import Any, Callable, Optional, Sequence

import numpy

from mlgshimmy.shared.draw import palette


def angle_map(ax: Any, rhos: Sequence[float], mus: Sequence[float], values: numpy.ndarray,
              text: Callable[[float], str], cmap: Any = palette.SEQUENCE_MAP,
              vmin: Optional[float] = None, vmax: Optional[float] = None) -> Any:
    """values[i, j] at (rhos[j], mus[i]) [deg] as one cell each (evenly
    spaced whatever the angles' spacing), each labelled text(value) in a
    colour readable on its fill (white where the value is not finite).
    Returns the image, for a colour bar."""
    mesh = ax.imshow(values, origin="lower", aspect="auto", cmap=cmap, vmin=vmin, vmax=vmax,
                     extent=(-0.5, len(rhos) - 0.5, -0.5, len(mus) - 0.5))
    for i in range(len(mus)):
        for j in range(len(rhos)):
            v = values[i, j]
            fill = mesh.cmap(mesh.norm(v)) if numpy.isfinite(v) else "white"
            ax.text(j, i, text(v), ha="center", va="center", fontsize=8,
                    color=palette.text_on(fill))
    ax.set_xticks(range(len(rhos)), [f"{r:g}" for r in rhos])
    ax.set_yticks(range(len(mus)), [f"{m:g}" for m in mus])
    ax.set_xlabel(r"$\rho$ [deg]")
    ax.set_ylabel(r"$\mu$ [deg]")
    ax.grid(False)
    return mesh
