"""The attractor atlas drawn over (V, F*): (a) what the cells settle on,
(b) the largest settled torsion amplitude.  Called by the atlas's `summary`."""
from __future__ import annotations

from typing import Any, List, Mapping, Sequence

import numpy

from mlgshimmy.shared.draw import palette

# one colour per kind (palette.ATTRACTOR); a cell with several kinds takes
# the colour of the first in PAINT (its most shimmy-like attractor; leaving
# the domain or not settling only when nothing settled) and a marker per
# other kind, in the kind's edge colour
COLOURS = palette.ATTRACTOR
PAINT = ("quasi", "high", "low", "yaw", "straight", "unsettled", "domain")
MARKERS = {kind: (marker, palette.ATTRACTOR_EDGE[kind]) for kind, marker in
           (("straight", "o"), ("yaw", "s"), ("low", "^"), ("high", "v"), ("quasi", "D"),
            ("domain", "x"), ("unsettled", "*"))}


def edges(values: Sequence[float]) -> numpy.ndarray:
    """Cell edges half way between grid values (the outer ones mirrored)."""
    v = numpy.asarray(values, float)
    if len(v) == 1:
        return numpy.array([v[0] - 0.5, v[0] + 0.5])
    mid = 0.5 * (v[1:] + v[:-1])
    return numpy.concatenate([[2 * v[0] - mid[0]], mid, [2 * v[-1] - mid[-1]]])


def kinds_of(cell: Mapping[str, Any]) -> List[str]:
    return [part.split(" x")[0] for part in cell["label"].split(" + ")]


def plot(cells: Sequence[Mapping[str, Any]], names: Mapping[str, str],
         order: Sequence[str]) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch
    from matplotlib.lines import Line2D
    vs = sorted({c["V"] for c in cells})
    fs = sorted({c["Fstar"] for c in cells})
    ev, ef = edges(vs), edges(fs)
    amplitude = numpy.full((len(fs), len(vs)), numpy.nan)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(15, 6.2), sharey=True)
    used = set()
    for c in cells:
        i, j = fs.index(c["Fstar"]), vs.index(c["V"])
        kinds = kinds_of(c)
        main = next(k for k in PAINT if k in kinds)
        used.update(kinds)
        ax.add_patch(plt.Rectangle((ev[j], ef[i]), ev[j + 1] - ev[j], ef[i + 1] - ef[i],
                                   facecolor=COLOURS[main], edgecolor=palette.BAND, lw=0.3))
        others = [k for k in kinds if k != main]
        for n, kind in enumerate(others):
            marker, colour = MARKERS[kind]
            x = ev[j] + (n + 1) * (ev[j + 1] - ev[j]) / (len(others) + 1)
            ax.plot(x, c["Fstar"], marker=marker, color=colour, ms=3.2, mfc="none"
                    if kind == "straight" else colour, mew=0.6, ls="none")
        settled = [s["amplitude_rad"] for s in c["starts"].values()
                   if s["kind"] not in ("domain", "unsettled")]
        if settled:
            amplitude[i, j] = max(max(settled), 1e-6)
    ax.set_xlim(ev[0], ev[-1])
    ax.set_ylim(ef[0], ef[-1])
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel("F*")
    ax.set_title("(a) end states (colour: the most shimmy-like attractor;\n"
                 "markers: the other end states of the cell)", fontsize=10)
    handles = [Patch(facecolor=COLOURS[k], edgecolor=palette.GUIDE, label=names[k])
               for k in order if k in used]
    handles += [Line2D([], [], marker=MARKERS[k][0], color=MARKERS[k][1], ls="none",
                       mfc="none" if k == "straight" else MARKERS[k][1],
                       label=f"also {names[k]}") for k in order if k in used]
    mesh = bx.pcolormesh(ev, ef, amplitude, cmap=palette.SEQUENCE_MAP,
                         norm=matplotlib.colors.LogNorm(vmin=1e-6, vmax=0.3))
    fig.colorbar(mesh, ax=bx, label=r"largest settled $\psi$ amplitude [rad] "
                 r"(stationary: $10^{-6}$)")
    bx.set_xlabel("V [m/s]")
    bx.set_title("(b) largest torsion amplitude over the starts", fontsize=10)
    fig.legend(handles=handles, loc="lower center", ncol=7, fontsize=8, frameon=False)
    fig.suptitle(r"Attractor atlas by time simulation: $y_{fp}$ = 1 mm, $\varepsilon$ = 0.1 mm")
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    from mlgshimmy.shared import draw
    draw.save(fig, "atlas")


def overlay(cells: Sequence[Mapping[str, Any]], agreement: Mapping[str, Any],
            fig11: Mapping[str, Any]) -> None:
    """The atlas cells over Fig. 11's regions and edge curves: which agree,
    which do not (annotated with the atlas's code), which lie on a curve."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch
    from matplotlib.lines import Line2D
    region_map = fig11["region_map"]
    names = region_map.get("names", {})
    code = numpy.asarray(region_map["code"], int)
    present = sorted(set(code.ravel().tolist()))
    index = numpy.searchsorted(present, code)
    colours = palette.categories(len(present))
    fig, ax = plt.subplots(figsize=(14, 8))
    ax.pcolormesh(edges(region_map["V"]), edges(region_map["Fstar"]), index,
                  cmap=matplotlib.colors.ListedColormap(colours), alpha=0.45,
                  vmin=-0.5, vmax=len(present) - 0.5, rasterized=True)
    for curve in fig11["edge_curves"]:
        ax.plot(curve["V"], curve["Fstar"], color=palette.NEUTRAL, lw=0.8)
    styles = {"agree": ("o", palette.HOPF, "agrees with Fig. 11"),
              "disagree": ("X", palette.LIFTOFF, "disagrees (atlas code written beside)"),
              "on_curve": ("o", palette.GUIDE, "on a curve: not compared")}
    for group, (marker, colour, _) in styles.items():
        for e in agreement[group]:
            ax.plot(e["V"], e["Fstar"], marker=marker, color=colour, ms=6 if group ==
                    "disagree" else 4, mfc=colour if group != "on_curve" else "none", ls="none")
            if group == "disagree":
                ax.annotate(str(e["atlas"]) if e["atlas"] is not None else "?",
                            (e["V"], e["Fstar"]), xytext=(4, 3), textcoords="offset points",
                            fontsize=7, color=colour)
    handles = [Patch(facecolor=colours[k], alpha=0.45, label=f"{c}: {names.get(str(c), c)}")
               for k, c in enumerate(present)]
    handles += [Line2D([], [], marker=m, color=col, ls="none", label=text)
                for m, col, text in styles.values()]
    handles.append(Line2D([], [], color=palette.NEUTRAL, lw=0.8, label="Fig. 11's edge curves"))
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1), fontsize=7,
              frameon=False)
    ax.set_xlim(0, 600)
    ax.set_ylim(0, 3.5)
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel("F*")
    fraction = agreement["fraction"]
    ax.set_title(f"Atlas over Fig. 11's regions: {len(agreement['agree'])} of "
                 f"{agreement['off_curve']} cells off the curves agree"
                 + (f" ({100 * fraction:.1f} %)" if fraction is not None else ""), fontsize=10)
    fig.tight_layout()
    from mlgshimmy.shared import draw
    draw.save(fig, "atlas_fig11")
