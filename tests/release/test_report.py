"""make report (mlgshimmy.report) from a small fake run root in
tmp_path: the page names every figure, every <img> it shows exists beside
it, the scorecard has one row per number the paper prints (shared.paper
PAPER) and per held-out value (HELD_OUT) with the status the tables give,
a figure not made shows as missing, and headless Chromium renders the page
to a screenshot, its sidebar beside the text (`make test` installs Chromium
and sets MLG_REQUIRE_CHROMIUM: there a missing Chromium fails; by hand it
skips, with the reason).

Run: /usr/bin/python3 -m pytest -q tests/release/test_report.py
"""
import html.parser
import json
import os
import shutil
import subprocess

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from mlgshimmy.shared import paper  # noqa: E402
from mlgshimmy import report  # noqa: E402

OURS = {"fig07": {"H, F* = 1 [m/s]": 346.1000001},
        "fig10": {"H1 [m/s]": 1.45816, "H2 [m/s]": 28.3067, "H3 [m/s]": 144.27,
                  "S1 [m/s]": 41.4912},
        "fig13": {"y_fp = 1: H1 [m/s]": 1.45817, "y_fp = 1: H2 [m/s]": 28.3067},
        "fig12": {"a_12": 0.408, "b_12": 1.527, "pitchfork 1 F*": 0.037}}


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.images, self.ids, self.rows, self._in_score = [], [], [], False
        self._cells, self.sidebar, self._in_nav, self.links = None, [], False, []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "img":
            self.images.append(attrs["src"])
        if tag == "nav" and attrs.get("class") == "side":
            self._in_nav = True
        if tag == "a":
            (self.sidebar if self._in_nav else self.links).append(attrs["href"])
        if "id" in attrs:
            self.ids.append(attrs["id"])
        if tag == "table" and "score" in attrs.get("class", ""):
            self._in_score = True
        if self._in_score and tag == "tr":
            self._cells = []
        if self._cells is not None and tag == "td":
            self._cells.append("")

    def handle_data(self, data):
        if self._cells:
            self._cells[-1] += data

    def handle_endtag(self, tag):
        if tag == "tr" and self._cells:
            self.rows.append([c.strip() for c in self._cells])
            self._cells = None
        if tag == "table":
            self._in_score = False
        if tag == "nav":
            self._in_nav = False


# a figure's named points, under its table (e.g. fig10.plot's)
NOTES = {"fig10": ["H3: high-frequency lateral, loses stability, subcritical (l1 = +0.03378; "
                   "the orbit branch agrees)", "criticality: 3 of 3 Hopf points agree"]}


@pytest.fixture
def run_root(tmp_path, monkeypatch):
    """fig07, fig10, fig12 and fig13 made (result, table, PNG); the rest not."""
    root = tmp_path / "build"
    monkeypatch.setenv("MLG_RUN_ROOT", str(root))
    (root / "figures").mkdir(parents=True)
    for figure, ours in OURS.items():
        (root / figure).mkdir()
        (root / figure / "result.json").write_text(json.dumps({
            "figure": figure, "part": None, "data": {"numbers": ours},
            "provenance": {"parameter_set": "figures", "git_commit": "abc123",
                           "auto_version": "0.9.2", "written": "2026-01-01T00:00:00+00:00"}}))
        paper.report(figure, ours, notes=NOTES.get(figure, ()))
        fig, ax = plt.subplots(figsize=(3, 2))
        ax.plot([0, 1], [0, 1])
        fig.savefig(root / "figures" / f"{figure}.png")
        plt.close(fig)
    (root / "tables" / "criterion.txt").write_text("criterion: kappa* table\n")
    fig, ax = plt.subplots(figsize=(3, 2))
    fig.savefig(root / "figures" / "criterion.png")
    plt.close(fig)
    return root


def test_the_page_from_cached_results(run_root, capsys):
    target = report.build()
    out = run_root / "report"
    assert target == str(out / "index.html")
    page = Page()
    page.feed((out / "index.html").read_text())
    # every figure has its section; every image shown exists beside the page
    assert {f for f, _, _ in report.FIGURES} <= set(page.ids)
    assert sorted(page.images) == sorted([f"figures/{f}.png" for f in OURS]
                                         + ["figures/criterion.png"])
    for src in page.images:
        assert (out / src).is_file(), src
    # the scorecard: every printed number once (Fig. 13's y_fp = 1 slice is Fig. 10's
    # four numbers, shown beside them), then every held-out value
    assert [(r[0].split("also")[0], r[1]) for r in page.rows] == [
        ("fig07", "H, F* = 1 [m/s]"), ("fig10", "H1 [m/s]"), ("fig10", "H2 [m/s]"),
        ("fig10", "H3 [m/s]"), ("fig10", "S1 [m/s]"), ("fig12", "a_12"), ("fig12", "b_12"),
        ("fig16", "r1 = a [mm]"), ("fig16", "r2 = b [mm]"), ("fig16", "r3 = c [mm]"),
        ("fig18", "kappa*")]
    status = {(r[0].split("also")[0], r[1]): r[5] for r in page.rows}
    assert status[("fig07", "H, F* = 1 [m/s]")] == "calibrated"
    assert status[("fig10", "H1 [m/s]")] == "agrees"
    assert status[("fig10", "H3 [m/s]")] == "close"
    assert status[("fig12", "a_12")] == "held out"
    assert status[("fig16", "r1 = a [mm]")] == "missing"
    assert page.rows[1][0] == "fig10also fig13 (y_fp = 1: H1 [m/s]): 1.45817"
    assert page.rows[4][0] == "fig10also fig13 (y_fp = 1: S1 [m/s]): –"   # not in fig13's table
    text = (out / "index.html").read_text()
    assert "<p>11 numbers, each counted once: 1 calibrated, 2 agrees, 2 close, 2 held out, " \
        "4 missing.</p>" in text
    # a sidebar to every part; provenance folded; each figure's checks and docs section
    assert page.sidebar[:3] == ["#top", "#scorecard", "#provenance"]
    assert [h for h in page.sidebar if h.startswith("#fig")] == \
        [f"#{f}" for f, _, _ in report.FIGURES]
    assert "<details><summary>the tools that made" in text
    assert text.count('<details class="prov"><summary>provenance of the cached result') == 4
    docs = os.path.relpath(os.path.join(report.paths.ROOT, "docs", "reproduction.md"), out)
    assert f"{docs}#fig-10--f--1-with-1-mm-of-freeplay-diagram-in-v" in page.links
    assert os.path.isfile(os.path.join(out, docs))
    assert "tests/continuation/test_naming.py::test_the_paper_s_gear_has_its_three_named_points" in text
    assert "No figure yet: run <code>make fig11</code>" in text
    assert "numpy" in text and "matplotlib" in text and "abc123" in text
    assert "missing: fig06" in capsys.readouterr().out
    # the studies: one run (its table and figure shown), the others named as not run
    assert "study-criterion" in page.ids and "criterion: kappa* table" in text
    assert "Not run: <code>make -j2 atlas</code>" in text
    # the lines under a table: the named points with their criticality
    assert "<li>H3: high-frequency lateral, loses stability, subcritical (l1 = +0.03378; " \
           "the orbit branch agrees)</li>" in text


def test_fig11_shows_its_caption_and_links_each_region_to_its_motion(run_root):
    """The caption beside Fig. 11's PNG is shown under it; each kind of
    region is linked to its animation (studies.animate --fig11), with what
    the simulation settled on, and one that settled elsewhere is flagged."""
    root = run_root
    root.joinpath("figures", "fig11_caption.txt").write_text(
        "Fig. 11: the plane.\n\nWhere a curve ends:\n- V = 10 m/s, F* = 0.66: two Hopf "
        "curves meet\n")
    cases = [{"kind": "straight", "V": 175.0, "Fstar": 1.5, "start": "rolling", "alone": True,
              "name": "animate_V175_F1.5_yfp1_rolling"},
             {"kind": "high", "V": 400.0, "Fstar": 1.5, "start": "shimmy", "alone": False,
              "name": "animate_V400_F1.5_yfp1_shimmy"},
             {"kind": "quasi", "V": 550.0, "Fstar": 1.0, "start": "shimmy", "alone": True,
              "name": "animate_V550_F1_yfp1_shimmy"}]
    root.joinpath("figures", "fig11_motion.json").write_text(json.dumps(cases))
    for case, kind in zip(cases[:2], ("straight", "low")):     # the second went elsewhere
        root.joinpath("figures", f"{case['name']}.gif").write_bytes(b"GIF89a")
        (root / case["name"]).mkdir()
        (root / case["name"] / "result.json").write_text(json.dumps(
            {"figure": case["name"], "data": {"kind": kind}, "provenance": {}}))
    report.build()
    text = (root / "report" / "index.html").read_text()
    page = Page()
    page.feed(text)
    assert "<p>Fig. 11: the plane.</p>" in text
    assert "<ul><li>V = 10 m/s, F* = 0.66: two Hopf curves meet</li></ul>" in text
    assert [h for h in page.links if "-motion-" in h] == \
        ["#fig11-motion-straight", "#fig11-motion-high", "#fig11-motion-quasi"]
    assert {"fig11-motion-straight", "fig11-motion-high", "fig11-motion-quasi"} <= set(page.ids)
    for case in cases[:2]:
        assert f"figures/{case['name']}.gif" in page.images
        assert (root / "report" / "figures" / f"{case['name']}.gif").is_file()
    assert "settled on straight rolling</li>" in text
    assert "settled on low-frequency shimmy <span class=\"st bad\">another state</span>" in text
    assert "not simulated yet" in text and "make fig11-motion" in text


def test_chromium_renders_the_page(run_root, tmp_path):
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        assert not os.environ.get("MLG_REQUIRE_CHROMIUM"), "chromium is not installed, and " \
            "make test installs it (mk/install-packages.sh chromium)"
        pytest.skip("chromium is not installed (apt-get install -y chromium): the page "
                    "is checked as HTML only")
    target = report.build()
    shot = tmp_path / "page.png"
    proc = subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu",
                           "--hide-scrollbars", f"--screenshot={shot}",
                           "--window-size=1280,2000", f"file://{target}"],
                          capture_output=True, text=True, timeout=180)
    assert proc.returncode == 0, proc.stderr[-2000:]
    image = plt.imread(shot)
    assert image.shape[:2] == (2000, 1280)
    # something is drawn: the page is not blank
    assert (image[..., :3] < 0.5).any()
    assert os.path.getsize(shot) > 10_000
    # the sidebar's background (#f5f6f8) down the left edge, the page's white right of it
    assert image[1900, 20, :3] == pytest.approx([0xf5 / 255, 0xf6 / 255, 0xf8 / 255], abs=0.01)
    assert image[1900, 1270, :3] == pytest.approx([1.0, 1.0, 1.0], abs=0.01)


def test_a_changed_gears_page_shows_what_was_made_and_no_scorecard(run_root):
    """At a changed gear (a lead: the design answers) the page has no
    scorecard (the paper's numbers are its own gear's) and lists only the
    figures and studies made there."""
    info = report.collect(str(run_root))
    images = {f["figure"]: f"figures/{f['figure']}.png" for f in info["figures"] if f["png"]}
    text = report.page(info, images, lead='<h2 id="gear">Your gear: ...</h2>')
    page = Page()
    page.feed(text)
    assert "Scorecard" not in text and "#scorecard" not in page.sidebar
    assert page.sidebar[:3] == ["#top", "#gear", "#provenance"]
    assert [h for h in page.sidebar if h.startswith("#fig")] == [f"#{f}" for f in sorted(OURS)]
    assert "No figure yet" not in text and "Not run:" not in text
    assert "mlg-shimmy: your gear" in text
