"""The one palette of every figure and study: each colour named by what it
shows.  Okabe and Ito's colour-blind-safe set, told apart by lightness in
grey scale as well; families of curves from viridis (sequence); maps of a
quantity from viridis, or cividis where the sign matters (a difference
from the paper's gear).  mlg.mplstyle beside this file puts CYCLE, the
fonts and the number formats into every figure (shared.draw applies it).
tests/figures/test_figure_style.py holds figures and studies to it: no colour is
named anywhere else.
"""
from __future__ import annotations

from typing import Any, List, Tuple

import matplotlib
import numpy

# stability, the first thing every diagram tells
STABLE, UNSTABLE = "#0b3d91", "#e69f00"
NEUTRAL = "0.25"        # text-like lines: markers' edges, reference lines
MARKER = "black"        # the special points' markers (H, S, P, TR)
OPEN = "white"          # the face of an open marker
GUIDE = "0.65"          # a reference drawn behind the data (another gear, a boundary)
SHADE = "0.9"           # a background band (the operating region)
BAND = "0.85"           # a highlighted interval (the smoothing width, the freeplay gap)
# curves of bifurcation points in two parameters, dot-dashed as in the paper
HOPF = "#009e73"        # Hopf curves
FOLD = "black"          # folds of orbits
PITCHFORK = "black"     # pitchforks and folds of stationary states (dotted)
TORUS = "#cc79a7"       # torus (Neimark-Sacker) curves and points
DOUBLED = "#009988"     # orbits of twice the period, born at period doublings
LIFTOFF = "#d55e00"     # the wheel lift-off edge, a model's domain ending
ALLOWED = "#a6dba0"     # straight rolling stable: what a criterion allows (a fill)
ALLOWED_PART = "#f0e442"   # what only one of two readings allows
TYRE = "#d55e00"        # tyre contact patches in the gear's drawings
ON_FILL = "white"       # a thin line drawn over coloured regions
# what a time simulation settles on (shared.attractor's kinds; the atlas,
# Fig. 18's regions): light fills, so that curves and text on them stay legible
ATTRACTOR = {"straight": ALLOWED, "yaw": "#9ecae1", "low": "#fdd49e", "high": "#f4a582",
             "quasi": "#c2a5cf", "domain": "0.7", "unsettled": "#f7f7b0"}
# a line or marker of each kind, dark enough on white and on the fills above
ATTRACTOR_EDGE = {"straight": "black", "yaw": "#08519c", "low": "#b35806", "high": "#b2182b",
                  "quasi": "#762a83", "domain": "black", "unsettled": "#8c6d00"}
# Fig. 11's regions, by the shimmy stable there (shared.regions' kinds in
# its order; straight and yawed rolling are patterns over the fill): none
# unshaded, each alone in its ATTRACTOR fill, low and high together in one
# of their own
REGION = {(): "white", ("low",): ATTRACTOR["low"], ("high",): ATTRACTOR["high"],
          ("low", "high"): "#dfc27d", ("quasi",): ATTRACTOR["quasi"],
          ("liftoff",): ATTRACTOR["domain"]}
# a line plot's default colours, in order (mlg.mplstyle's axes.prop_cycle)
CYCLE = (STABLE, UNSTABLE, HOPF, TORUS, "#56b4e9", LIFTOFF, NEUTRAL)
SEQUENCE_MAP = "viridis"
DIVERGING_MAP = "cividis"


def sequence(n: int) -> List[Tuple[float, float, float, float]]:
    """n colours in order (a family of curves: eps, y_fp, V) from viridis,
    its light yellow end left out (it vanishes on white)."""
    return [matplotlib.colormaps[SEQUENCE_MAP](x) for x in numpy.linspace(0.0, 0.82, n)]


def categories(n: int) -> List[Tuple[float, float, float, float]]:
    """n colours for categories in no order (the codes of a region map),
    from matplotlib's tab20; ValueError beyond its 20."""
    if n > 20:
        raise ValueError(f"palette.categories: {n} categories, at most 20")
    return [matplotlib.colormaps["tab20"](k / 20) for k in range(n)]


def text_on(fill: Any) -> str:
    """Black or white, whichever reads better on the colour `fill`
    (relative luminance above 0.4: black)."""
    r, g, b = matplotlib.colors.to_rgb(fill)
    luminance = 0.2126 * r + 0.7152 * g + 0.0722 * b
    return "black" if luminance > 0.4 else "white"
