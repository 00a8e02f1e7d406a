"""Fig. 11's drawing (figures/fig11/plot.py) on a small made-up result, no
AUTO: a legend of about ten entries in the reader's words, no text over
other text, and a caption beside the PNG that says where each curve ends
and why.  The made-up result has every kind of curve, end and region that
the plot draws, so that every branch of it is drawn.
Run: /usr/bin/python3 -m pytest -q tests/figures/test_fig11_legend.py
"""
import numpy
import pytest

from mlgshimmy.figures.fig11 import plot as fig11_plot
from mlgshimmy.figures.fig11.plane import F_GRID, V_GRID
from mlgshimmy.figures.fig11.regions import ATTRACTORS
from mlgshimmy.shared import draw

MAX_ENTRIES = 10     # the curves' and the regions' legends together


def curve(V, F):
    return [{"columns": {"V": list(V), "Fstar": list(F)}, "stable": [True] * len(V),
             "labels": []}]


def made_up():
    """Regions in bands of V; one curve of each kind; one end of each kind."""
    code = numpy.full((len(F_GRID), len(V_GRID)), ATTRACTORS["straight"])
    bands = [(0, 30, "low"), (30, 140, "straight", "high"), (140, 300, "high"),
             (300, 450, "quasi"), (450, 601, "liftoff")]
    for lo, hi, *kinds in bands:
        code[:, (V_GRID >= lo) & (V_GRID < hi)] = sum(ATTRACTORS[k] for k in kinds)
    code[(F_GRID > 0.2) & (F_GRID < 0.4), :] |= ATTRACTORS["yaw"]
    line = numpy.linspace(0.05, 3.4, 20)
    ends = {"mx_joins": [{"V": 10.0, "Fstar": 0.66, "kind": "hopf"},
                         {"V": 200.0, "Fstar": 0.9, "kind": "tongue"}],
            "stage_switch_ends": [{"V": 145.0, "Fstar": 0.68, "curve": "hopf3"}],
            "generalised_hopf_ends": [{"V": 40.0, "Fstar": 3.0, "curve": "fold2"}],
            "on_fold_ends": [{"V": 320.0, "Fstar": 2.5, "curve": "torus1"}],
            "liftoff_ends": [{"V": 470.0, "Fstar": 1.5, "curve": "torus1"}],
            "mx_stops": [{"V": 250.0, "Fstar": 3.3, "curve": "fold1"}]}
    return {"region_map": {"code": code.tolist()},
            "curves": {"hopf": [curve(30 + 0 * line, line)], "fold": [curve(40 + 5 * line, line)],
                       "zero": [curve(340 + 10 * line, line)],
                       "torus": [curve(300 + 20 * line, line)],
                       "tongue": [curve(200 + 0 * line, line)]},
            "pitchfork": [[], [0.2, 0.4]], "torus_points": [{"V": 210.0, "Fstar": 1.2}],
            "edge_curves": [{"kind": "liftoff", "V": [450.0, 450.0], "Fstar": [0.02, 3.5]}],
            "liftoff": {"points": [[450.0, 0.5], [450.0, 1.5]], "t_end": 2.0, "psi0": 0.05},
            "stage_switch": [0.63, 0.70], "numbers": {}, "codim2": [], "codim2_notes": [], **ends}


def draw_fig11(tmp_path, monkeypatch, mark=None, result=None):
    """Draw the made-up result (or `result`); (its legends' texts, the
    overlapping texts, the caption, the PNG).  mark(ax): marks more points
    before the plot draws (as a figure marking codimension-two points
    would)."""
    import matplotlib.pyplot as plt
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    monkeypatch.setattr(fig11_plot.paper, "report", lambda *args, **kw: "")
    if mark:
        subplots = plt.subplots

        def marked(*args, **kw):
            fig, ax = subplots(*args, **kw)
            mark(ax)
            return fig, ax
        monkeypatch.setattr(plt, "subplots", marked)
    kept = {}
    save = draw.save

    def keep(fig, name):
        kept["legends"] = [[t.get_text() for t in legend.get_texts()]
                           for legend in fig.legends]
        kept["titles"] = [legend.get_title().get_text() for legend in fig.legends]
        kept["overlaps"] = draw.overlap.overlaps(fig)
        save(fig, name)
    monkeypatch.setattr(draw, "save", keep)
    fig11_plot.plot(made_up() if result is None else result)
    kept["caption"] = (tmp_path / "figures" / fig11_plot.CAPTION).read_text()
    kept["png"] = tmp_path / "figures" / "fig11.png"
    return kept


@pytest.fixture
def drawn(tmp_path, monkeypatch):
    return draw_fig11(tmp_path, monkeypatch)


def test_the_legend_is_short_and_in_the_reader_s_words(drawn):
    entries = [text for legend in drawn["legends"] for text in legend]
    assert len(entries) <= MAX_ENTRIES, entries
    assert len(drawn["legends"]) == 2
    for words in ("Hopf curve", "fold of shimmy orbits", "torus curve", "tongue edge",
                  "lift-off edge"):
        assert any(entry.startswith(words) for entry in drawn["legends"][0]), words
    # the fills by the shimmy stable there, straight and yawed rolling as
    # patterns over them; the regions beyond the torus curve and the lift-off
    # edge named by those curves' entries
    assert drawn["legends"][1] == ["low-frequency shimmy", "high-frequency shimmy",
                                   "dotted: straight rolling too", "hatched: yawed rolling too"]
    assert "torus curve: quasi-periodic shimmy beyond (shaded)" in drawn["legends"][0]
    assert "lift-off edge: a wheel lifts off beyond (shaded)" in drawn["legends"][0]
    code_words = ("AUTO", "ISW", "MX", "eta", "k_stage", "\n")
    assert [e for e in entries if any(w in e for w in code_words)] == []


def test_no_text_overlaps_other_text(drawn):
    assert drawn["overlaps"] == []
    assert drawn["png"].is_file()


def test_the_caption_says_where_each_curve_ends_and_why(drawn):
    lines = [line for line in drawn["caption"].splitlines() if line.startswith("- V = ")]
    assert len(lines) == 7        # made_up's ends, one line each
    assert lines[0] == ("- V = 10 m/s, F* = 0.66: two Hopf curves meet inside the oleo's "
                        "stage switch (at the paper's gear those from H1 and H2)")
    assert "AUTO stopped the continuation (MX)" in lines[-1] and "V = 250 m/s" in lines[-1]
    for reference in ("without freeplay", "yawed (off-centre) rolling", "torus points",
                      "a wheel lifts off within 2 s", "stage switch"):
        assert reference in drawn["caption"], reference


def test_a_special_point_marked_is_named_in_the_caption(tmp_path, monkeypatch):
    """Points marked through draw.mark (codimension-two points on the
    curves) are named on the plot, and the caption says what each name
    means; the legends stay within MAX_ENTRIES however many kinds there are."""
    def marks(ax):
        for kind in ("GH", "ZH", "HH", "BT"):
            draw.mark(ax, 100.0, 1.0, kind)
    drawn = draw_fig11(tmp_path, monkeypatch, marks)
    assert "- Special points, named on the plot: " in drawn["caption"]
    assert "GH: generalised Hopf point (l1 = 0)" in drawn["caption"]
    assert not [t for legend in drawn["legends"] for t in legend if t.startswith("GH")]
    assert sum(len(legend) for legend in drawn["legends"]) <= MAX_ENTRIES


def test_the_region_with_no_shimmy_gets_its_entry_within_the_limit(tmp_path, monkeypatch):
    """Where no shimmy is stable the map is left white (dotted: straight
    rolling there; hatched: yawed rolling): the regions' title says so, and
    with every other kind present the legends still hold at most
    MAX_ENTRIES, none over other text."""
    result = made_up()
    code = numpy.array(result["region_map"]["code"])
    code[:, V_GRID < 10] = ATTRACTORS["straight"]
    code[(F_GRID > 0.2) & (F_GRID < 0.4), :] |= ATTRACTORS["yaw"]
    result["region_map"]["code"] = code.tolist()
    drawn = draw_fig11(tmp_path, monkeypatch, result=result)
    assert drawn["titles"][1] == "the gear settles on\n(white: no shimmy)"
    assert drawn["legends"][1] == ["low-frequency shimmy", "high-frequency shimmy",
                                   "dotted: straight rolling too", "hatched: yawed rolling too"]
    assert sum(len(legend) for legend in drawn["legends"]) <= MAX_ENTRIES
    assert drawn["overlaps"] == []
