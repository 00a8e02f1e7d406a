"""The shared drawing and table helpers (shared.draw, shared.paper): names
of special points placed without overlaps and merged when they coincide,
the smooth curve through stored points, the paper style without titles,
the stability legend, and the status of a number against the paper.

Run: /usr/bin/python3 -m pytest -q tests/figures/test_draw.py
"""
import json

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy  # noqa: E402
import pytest  # noqa: E402

from mlgshimmy.shared import draw, paper  # noqa: E402
from mlgshimmy.shared.draw import labels  # noqa: E402


def texts(ax):
    return [t for t in ax.texts if t.get_text()]


def test_names_of_close_points_do_not_overlap():
    fig, ax = plt.subplots(figsize=(6, 3))
    ax.plot([0, 600], [0, 0], color="k")
    for k, v in enumerate((1.5, 28.3, 41.5, 144.3)):
        draw.mark(ax, v, 0.0 if k != 2 else 0.2, "HB" if k != 2 else "LP",
                  name=f"X{k + 1}")
    ax.set(xlim=(0, 600), ylim=(-1, 16))
    labels.place(fig)
    fig.canvas.draw()
    boxes = [t.get_window_extent() for t in texts(ax)]
    assert [t.get_text() for t in texts(ax)] == ["X1", "X2", "X3", "X4"]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not a.overlaps(b), (a, b)
    plt.close(fig)


def test_coinciding_points_of_one_name_are_named_once():
    fig, ax = plt.subplots()
    for v in (570.2, 572.2, 576.2, 579.8):        # Fig. 10's four torus points
        draw.mark(ax, v, 15.0, "TR")
    draw.mark(ax, 100.0, 5.0, "TR")
    ax.set(xlim=(0, 600), ylim=(0, 16))
    labels.place(fig)
    assert [t.get_text() for t in texts(ax)] == ["TR ×4", "TR"]
    # one marker for the cluster of four, one for the lone point
    assert sum(line.get_visible() for line in ax.get_lines()) == 2
    plt.close(fig)


def test_legend_names_styles_and_marked_kinds():
    fig, ax = plt.subplots()
    draw.plot_stability(ax, [0, 1, 2, 3], [0, 1, 2, 3], [True, True, False, False])
    draw.mark(ax, 1, 1, "HB")
    draw.mark(ax, 2, 2, "TR")
    text = [t.get_text() for t in draw.legend(ax).get_texts()]
    assert text == ["stable", "unstable", "H: Hopf point", "TR: torus (Neimark-Sacker) point"]
    styles = [(line.get_color(), line.get_linestyle()) for line in ax.get_lines()[:2]]
    assert styles == [(draw.STABLE, "-"), (draw.UNSTABLE, "--")]
    plt.close(fig)


def test_unlabelled_stability_changes_away_from_the_start():
    class Branch:
        labels = type("L", (), {"getIndices": lambda self: []})()

        def __init__(self, stable):
            self.mask = stable

        def __len__(self):
            return len(self.mask)

        def stability(self):   # AUTO's convention: last index of each run, < 0 stable
            out, start = [], 0
            for i in range(1, len(self.mask) + 1):
                if i == len(self.mask) or self.mask[i] != self.mask[start]:
                    out.append(-i if self.mask[start] else i)
                    start = i
            return out
    # the flag at the Hopf point itself and a flip 30 points on
    mask = [False] + [True] * 30 + [False] * 10
    assert draw.stability_changes(Branch(mask)) == [30]


def test_smooth_passes_through_every_stored_point():
    xs = numpy.array([233.7, 236.4, 246.3, 272.9, 335.6, 413.6])
    ys = numpy.array([0.298, 0.259, 0.216, 0.170, 0.125, 0.100])
    sx, sy = draw.smooth(xs, ys, (600, 3.5), per_step=10)
    assert len(sx) == 1 + 10 * (len(xs) - 1)
    numpy.testing.assert_allclose(sx[::10], xs, rtol=1e-12)
    numpy.testing.assert_allclose(sy[::10], ys, rtol=1e-12)
    # F* stays monotone between monotone points (no overshoot)
    assert numpy.all(numpy.diff(sy) < 0)


def test_paper_style_drops_the_titles(monkeypatch):
    fig, ax = plt.subplots()
    monkeypatch.setenv("MLG_PAPER_STYLE", "1")
    assert draw.figure_title(fig, "Fig. 7: x") is None
    assert draw.figure_title(ax, "Fig. 9: x") is None
    assert fig._suptitle is None and ax.get_title() == ""
    monkeypatch.setenv("MLG_PAPER_STYLE", "0")
    draw.figure_title(fig, "Fig. 7: x")
    assert fig._suptitle.get_text() == "Fig. 7: x"
    plt.close(fig)


def test_scientific_numbers_for_titles():
    assert draw.sci(3.9e7) == r"$3.9 \times 10^{7}$"
    assert draw.sci(2.5) == "$2.5$"


@pytest.mark.parametrize("printed, ours, expected", [
    (1.5, 1.45816, "agrees"),        # 1.45816 prints as 1.5
    (28.1, 28.3067, "close"),
    (41.5, 41.4912, "agrees"),
    (142.5, 150.0, "off"),
    (142.5, None, "missing"),
])
def test_status_against_the_printed_digits(printed, ours, expected):
    assert paper.status("fig10", "H", printed, ours) == expected


def test_calibrated_value_and_tables(tmp_path, monkeypatch):
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    assert paper.status("fig07", "H, F* = 1 [m/s]", 346.1, 346.1000001) == "calibrated"
    # 15 % off the value it was fitted to: no longer "calibrated"
    assert paper.status("fig07", "H, F* = 1 [m/s]", 346.1, 346.1 * 1.15) == "off its calibration"
    assert paper.status("fig07", "H, F* = 1 [m/s]", 346.1, 346.16) == "off its calibration"
    assert paper.status("fig07", "H, F* = 1 [m/s]", 346.1, 346.14) == "calibrated"
    text = paper.report("fig10", {"H1 [m/s]": 1.45816, "extra": 2.0}, {"H1 [m/s]": 0.77})
    assert text.splitlines()[1].split() == ["quantity", "paper", "ours", "ours,", "printed",
                                            "c_psi", "rel.", "error", "status"]
    rows = json.loads((tmp_path / "tables" / "fig10.json").read_text())["rows"]
    assert [r["quantity"] for r in rows][:4] == list(paper.PAPER["fig10"])
    assert rows[0]["status"] == "agrees" and rows[1]["status"] == "missing"
    # a figure the paper prints nothing for: ours alone, no empty paper column
    text = paper.report("fig12", {"a_12": 0.4, "b_12": 1.5})
    assert "paper" not in text.splitlines()[1]
    assert "held out by the paper" in text
    assert paper.in_degrees({"slope [rad/mm]": 1.0})["slope [deg/mm]"] == pytest.approx(57.29578)
