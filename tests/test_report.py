"""make report (mlgshimmy.studies.report) from a small fake run root in
tmp_path: the page names every figure, every <img> it shows exists beside
it, the scorecard has one row per number the paper prints (shared.paper
PAPER) and per held-out value (HELD_OUT) with the status the tables give,
a figure not made shows as missing, and headless Chromium renders the page
to a screenshot (skipped, with the reason, where Chromium is absent).

Run: /usr/bin/python3 -m pytest -q tests/test_report.py
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
from mlgshimmy.studies import report  # noqa: E402

OURS = {"fig07": {"H, F* = 1 [m/s]": 346.1000001},
        "fig10": {"H1 [m/s]": 1.45816, "H2 [m/s]": 28.3067, "H3 [m/s]": 144.27,
                  "S1 [m/s]": 41.4912},
        "fig12": {"a_12": 0.408, "b_12": 1.527, "pitchfork 1 F*": 0.037}}


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.images, self.ids, self.rows, self._in_score = [], [], [], False
        self._cells = None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "img":
            self.images.append(attrs["src"])
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


# a figure's named points, under its table (e.g. fig10.plot's)
NOTES = {"fig10": ["H3: high-frequency lateral, loses stability, subcritical (l1 = +0.03378; "
                   "the orbit branch agrees)", "criticality: 3 of 3 Hopf points agree"]}


@pytest.fixture
def run_root(tmp_path, monkeypatch):
    """fig07, fig10 and fig12 made (result, table, PNG); the rest not."""
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
    # the scorecard: every printed number, then every held-out value
    printed = [(f, q) for f, values in paper.PAPER.items() for q in values]
    held = [(f, q) for f, values in paper.HELD_OUT.items() for q in values]
    assert [(r[0], r[1]) for r in page.rows] == printed + held
    status = {(r[0], r[1]): r[5] for r in page.rows}
    assert status[("fig07", "H, F* = 1 [m/s]")] == "calibrated"
    assert status[("fig10", "H1 [m/s]")] == "agrees"
    assert status[("fig10", "H3 [m/s]")] == "close"
    assert status[("fig13", "y_fp = 1: H1 [m/s]")] == "missing"      # not made
    assert status[("fig12", "a_12")] == "held out"
    assert status[("fig16", "r1 = a [mm]")] == "missing"
    text = (out / "index.html").read_text()
    assert "No figure yet: run <code>make fig11</code>" in text
    assert "numpy" in text and "matplotlib" in text and "abc123" in text
    assert "missing: fig06" in capsys.readouterr().out
    # the studies: one run (its table and figure shown), the others named as not run
    assert "study-criterion" in page.ids and "criterion: kappa* table" in text
    assert "Not run: <code>make -j2 atlas</code>" in text
    # the lines under a table: the named points with their criticality
    assert "<li>H3: high-frequency lateral, loses stability, subcritical (l1 = +0.03378; " \
           "the orbit branch agrees)</li>" in text


def test_chromium_renders_the_page(run_root, tmp_path):
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
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
