"""One figure style (#40): every figure and study takes its colours from
shared/draw/palette.py and its style from shared/draw/mlg.mplstyle (through
shared.draw), saves through draw.save, and draws no text over other text.

The quick figures are drawn here from scratch (fig06, fig07, fig08, fig09,
fig15: about 40 s), Fig. 11 from a made-up result by
tests/figures/test_fig11_legend.py; draw.save reports any overlap in every figure
`make` draws as well.
Run: /usr/bin/python3 -m pytest -q tests/figures/test_figure_style.py
"""
import os
import re
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from helpers import ROOT  # noqa: E402
from mlgshimmy.shared import draw  # noqa: E402
from mlgshimmy.shared.draw import overlap, palette  # noqa: E402

PACKAGE = os.path.join(ROOT, "drivers", "mlgshimmy")
# where colours may be named: the palette itself
NAMED_HERE = {os.path.join("shared", "draw", "palette.py")}
COLOUR = re.compile(
    r"""["']#[0-9a-fA-F]{3,8}["']"""                           # "#0b3d91"
    r"""|["']tab:\w+["']"""                                    # "tab:blue"
    r"""|\b(?:color|colors|c|fc|ec|mfc|mec|facecolor|edgecolor)\s*=\s*["'](?!none["'])[^"']+["']"""
    r"""|\bcmap\s*=\s*["']\w+["']"""                           # cmap="viridis"
    r"""|colormaps\[\s*["']\w+["']\s*\]"""
    r"""|\.plot\([^)]*,\s*["'][bgrcmykw][-:.o^sDvx*]*["']\s*[,)]""")   # "k--" 


def modules():
    for where, _, files in os.walk(PACKAGE):
        for name in files:
            if name.endswith(".py"):
                path = os.path.join(where, name)
                yield os.path.relpath(path, PACKAGE), path


def test_no_colour_is_named_outside_the_palette():
    found = []
    for name, path in modules():
        if name in NAMED_HERE:
            continue
        for number, line in enumerate(open(path), 1):
            code = line.split("#", 1)[0] if not re.search(r"""["']#""", line) else line
            for match in COLOUR.finditer(code):
                found.append(f"{name}:{number}: {match.group(0)}")
    assert found == []


def test_figures_are_saved_through_draw_save():
    direct = [name for name, path in modules()
              if not name.startswith(os.path.join("shared", "draw"))
              and "savefig(" in open(path).read()]
    assert direct == []


def test_the_style_file_cycles_the_palette():
    draw.plt.style.use(draw.STYLE)
    cycle = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
    assert [matplotlib.colors.to_hex(c) for c in cycle] == \
        [matplotlib.colors.to_hex(c) for c in palette.CYCLE]
    assert matplotlib.rcParams["axes.formatter.useoffset"] is False


@pytest.mark.parametrize("fill, text", [("white", "black"), (palette.STABLE, "white"),
                                        (matplotlib.colormaps["viridis"](0.95), "black"),
                                        (matplotlib.colormaps["viridis"](0.05), "white")])
def test_text_on_a_fill_reads(fill, text):
    assert palette.text_on(fill) == text


def test_overlapping_text_is_found_and_apart_text_is_not():
    fig, ax = plt.subplots()
    ax.set(title="title", xlabel="V [m/s]", xlim=(0, 1))
    ax.text(0.5, 0.5, "S2")
    assert overlap.overlaps(fig) == []
    ax.text(0.51, 0.5, "S3")
    assert overlap.overlaps(fig) == [("S2", "S3")]
    plt.close(fig)


@pytest.mark.parametrize("figure", ["fig06", "fig07", "fig08", "fig09", "fig15"])
def test_a_quick_figure_draws_no_text_over_text(figure, tmp_path):
    env = dict(os.environ, MLG_RUN_ROOT=str(tmp_path), MPLBACKEND="Agg",
               PYTHONPATH=os.path.join(ROOT, "drivers"))
    env.pop(os.environ.get("MLG_CLAIMED_ENV", "MLG_CLAIMED"), None)
    proc = subprocess.run([sys.executable, "-m", f"mlgshimmy.figures.{figure}"], cwd=ROOT,
                          env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert (tmp_path / "figures" / f"{figure}.png").is_file()
    assert [line for line in proc.stdout.splitlines() if "overlapping text" in line] == []
