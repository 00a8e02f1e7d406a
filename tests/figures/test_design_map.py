"""The design map over side-stay angles (studies.design_map): its grid and
make target, the mirror gear: (rho, mu) and (-rho, -mu) give the same
numbers, mirrored (y_tlk changes sign; speeds, kappa* equal), to the
continuation's tolerance (docs/model.md 8.5: f(Su; -rho, -mu) = S f(u; rho, mu)),
the freeplay kappa* allows in mm, a kappa* set on the oleo's stage switch
flagged with the value off it, Hopf points named by mode, and the user's
geometry marked.

Run: /usr/bin/python3 -m pytest -q tests/figures/test_design_map.py
"""
import json
import os
import pathlib
import subprocess
import sys

import matplotlib
import numpy
import pytest

import helpers
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared.draw import palette
from mlgshimmy.studies import design_map

ROOT = pathlib.Path(helpers.ROOT)
GEOMETRY = (-10.0, 20.0)      # the second geometry, against (10, -20)


def tool(*args, **env):
    return subprocess.run([sys.executable, "-m", "mlgshimmy.studies.design_map", *args],
                          cwd=ROOT, capture_output=True, text=True, env={**os.environ, **env})


def test_the_default_grid_is_5_by_5_and_named_by_its_variables(tmp_path):
    proc = tool("targets", MLG_RUN_ROOT=str(tmp_path))
    assert proc.returncode == 0, proc.stderr
    targets = proc.stdout.split()
    assert len(targets) == 25
    assert f"{tmp_path}/design_map/rho-20_mu10/result.json" in targets
    proc = tool("check", "--rho=ten")
    assert proc.returncode != 0 and "DESIGN_RHO" in proc.stderr
    proc = tool("check", "--rho=89", "--mu=0")      # |sin p| > 0.99
    assert proc.returncode != 0 and "rejected" in proc.stderr and "cos p" in proc.stderr
    proc = tool("check", "--rho=0,95", "--mu=0")
    assert proc.returncode != 0 and "DESIGN_RHO" in proc.stderr


def make_n(*args):
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES", "MLG_RUN_ROOT")}
    return subprocess.run(["make", "--no-print-directory", "-n", "design-map",
                           "DESIGN_RHO=0,10", "DESIGN_MU=-5", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True)


def test_make_design_map_is_the_grid():
    proc = make_n()
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    points = [line for line in lines if "design_map point" in line]
    assert [p.split()[-1] for p in points] == ["rho0_mu-5", "rho10_mu-5"]
    summary = [line for line in lines if "design_map summary" in line]
    assert len(summary) == 1 and "--mu='-5'" in summary[0] and "--mark" not in summary[0]


def test_make_design_map_with_rho_mu_marks_the_user_s_gear_on_the_same_grid():
    """RHO, MU do not move the grid or its tree (no geometry/ subtree): they
    reach the summary alone, as --mark; the map takes no SET."""
    proc = make_n("RHO=12", "MU=7")
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    points = [line for line in lines if "design_map point" in line]
    assert [p.split()[-1] for p in points] == ["rho0_mu-5", "rho10_mu-5"]
    stamps = [line for line in lines if line.startswith("touch ")]
    assert stamps and all(f"{ROOT}/build/design_map/grid-" in line for line in stamps), stamps
    assert [line for line in lines if "design_map summary" in line][0].endswith(
        "--mark='12,7'")
    proc = make_n("SET=k_tlk=3.51e7")
    assert proc.returncode != 0 and "design-map takes no SET" in proc.stderr


@pytest.fixture(scope="module")
def pair(tmp_path_factory):
    """The scans, one AUTO location of H3, kappa* on three loads and the
    link position, at GEOMETRY and its mirror image."""
    out = {}
    for sign in (1, -1):
        rho, mu = sign * GEOMETRY[0], sign * GEOMETRY[1]
        _, values = design_map.at(rho, mu)
        scans = design_map.speeds(values)
        rundir = str(tmp_path_factory.mktemp(f"mirror{sign:+d}"))
        high = [v for v, hz in scans["hopf"] if hz >= design_map.HIGH_HZ]
        hb = ct.hopf_point(rundir, "hb3", "figures", "V", high[0],
                           Fstar=design_map.FSTAR, **design_map.FREEPLAY, **values)
        out[sign] = {"scans": scans, "hb3": (hb["V"], hb["T"]),
                     "kappa": design_map.kappa(values, loads=(0.3, 0.5, 1.0), finer=()),
                     "links": design_map.link_position(
                         values, 1.0, 1.0, {"eps_abs": 0.0, "eps_rel": 0.1})}
    return out


def test_the_mirror_gear_has_the_same_speeds(pair):
    a, b = pair[1]["scans"], pair[-1]["scans"]
    assert a["critical_V"] == pytest.approx(b["critical_V"], rel=1e-12)
    assert len(a["hopf"]) == len(b["hopf"]) >= 1 and a["bp"] == b["bp"] == []
    for (va, fa), (vb, fb) in zip(a["hopf"], b["hopf"]):
        assert va == pytest.approx(vb, rel=1e-12) and fa == pytest.approx(fb, rel=1e-9)
    # AUTO's location of H3: the same to its tolerance
    (Va, Ta), (Vb, Tb) = pair[1]["hb3"], pair[-1]["hb3"]
    assert Va == pytest.approx(Vb, rel=1e-7) and Ta == pytest.approx(Tb, rel=1e-7)
    assert Va == pytest.approx(a["hopf"][-1][0], rel=1e-4)


def test_the_mirror_gear_has_the_same_kappa_and_mirrored_links(pair):
    a, b = pair[1]["kappa"], pair[-1]["kappa"]
    assert a["kappa"] == pytest.approx(b["kappa"], rel=1e-9)
    assert (a["kappa_Fstar"], a["kappa_V"], a["kappa_mode"]) == \
        (b["kappa_Fstar"], b["kappa_V"], b["kappa_mode"])
    ya, yb = pair[1]["links"], pair[-1]["links"]
    assert abs(ya) > 0.05 and ya == pytest.approx(-yb, rel=1e-9)


def test_hopf_points_are_named_by_their_mode(pair):
    """At (-10, 20) deg the low-frequency pair never loses stability: the
    one Hopf point is H3 (13 Hz), H1 and H2 have vanished."""
    scans = pair[1]["scans"]
    assert scans["hopf_names"] == ["H3"] and scans["hopf"][0][1] > design_map.HIGH_HZ
    # straight rolling is stable up to H3 and unstable beyond, to the scan's end
    assert scans["stable"] == [(ct.V_MIN, scans["hopf"][0][0])]


def test_a_kappa_set_on_the_stage_switch_is_flagged_with_the_value_off_it(pair):
    """(-10, 20) deg on the loads 0.3, 0.5, 1.0 and the five across the
    stage switch: straight rolling is unstable without freeplay on the
    switch (kappa* = 0); off it, the least of the three loads, at F* = 0.3."""
    k = pair[1]["kappa"]
    low, high = k["switch_window"]
    assert (low, high) == pytest.approx((0.633, 0.695), abs=2e-3)
    assert k["on_switch"] and low <= k["kappa_Fstar"] <= high
    assert k["kappa"] == 0.0 and k["kappa_yfp"] == 0.0
    assert k["off_switch_Fstar"] == 0.3
    # docs/design-map.md: 0.4001 at (10, -20) off the switch, at F* = 0.290-0.300
    assert k["kappa_off_switch"] > k["kappa"]
    assert k["kappa_off_switch"] == pytest.approx(0.400, abs=2e-3)
    assert k["off_switch_yfp"] == pytest.approx(k["kappa_off_switch"] * 0.1, rel=1e-12)


def test_the_paper_s_gear_allows_0_037_mm_of_freeplay():
    """kappa* = 0.3651 at F* = 0.295 (Fig. 18) with eps = 0.1 mm: 0.0365 mm,
    the loads 0.25-0.35 refined to 0.01 (the value at 0.29 or 0.30 lies
    within 2e-4 mm of it); no stage switch in these loads, so the value off
    it is the same."""
    _, values = design_map.at(0.0, 0.0)
    k = design_map.kappa(values, loads=(0.25, 0.3, 0.35), finer=(5,))
    assert k["kappa_yfp"] == pytest.approx(0.0365, abs=2e-4)
    assert round(k["kappa_yfp"], 3) == 0.037
    assert k["switch_window"] is None and not k["on_switch"]
    assert k["kappa_off_switch"] == k["kappa"]


def record(rho, mu, **more):
    """A grid point's result as compute() writes it (made-up numbers)."""
    out = {key: 1.0 for key, _, _, _ in design_map.QUANTITIES}
    out.update(rho_deg=rho, mu_deg=mu, kappa_V=120.0, kappa_mode="high",
               cpu_seconds={"scans": 1.0}, hopf=[[1.0, 2.0], [3.0, 2.0], [140.0, 13.0]],
               hopf_names=["H1", "H2", "H3"], stable=[[0.5, 1.0], [3.0, 140.0]],
               S_stop="UZ", switch_window=[0.633, 0.695], on_switch=False,
               kappa_off_switch=1.0, off_switch_Fstar=0.295)
    out.update(more)
    return out


def test_summary_writes_the_table_from_the_grids_records(tmp_path, monkeypatch):
    """summary as shared.jobs.grid calls it (points, their records, their
    provenance): one row per geometry, "-" where kappa* = 0 leaves no
    freeplay for y_tlk/y_fp at kappa* (None), "vanished" for a Hopf point
    that does not exist, a kappa* on the stage switch flagged with the
    value off it, the criticality by the normal form where stored, and the user's geometry (10, 3) marked at the nearest
    grid point (10, 0), in the table and on the map."""
    from mlgshimmy.shared import draw
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    saved, save = {}, draw.save
    monkeypatch.setattr(draw, "save", lambda fig, name: (saved.update(fig=fig), save(fig, name)))
    records = [record(0.0, 0.0, kappa=0.3651, kappa_yfp=0.03651, kappa_Fstar=0.295,
                      hopf_l1=[-413.7, -4.09, 0.0338],
                      hopf_criticality=["supercritical", "supercritical", "subcritical"]),
               record(10.0, 0.0, H1=None, H2=None, hopf=[[140.0, 13.0]], hopf_names=["H3"],
                      stable=[[0.5, 140.0]], kappa=0.0, kappa_yfp=0.0, kappa_Fstar=0.649,
                      kappa_V=10.5, on_switch=True, ytlk_ratio_kappa=None,
                      kappa_off_switch=0.3714, off_switch_yfp=0.03714)]
    design_map.summary([(0.0, 0.0), (10.0, 0.0)], records, None, mark=(10.0, 3.0))
    text = (tmp_path / "tables" / "design_map.txt").read_text()
    rows = {tuple(line.split()[:2]): line.split() for line in text.splitlines()
            if line.split()[:2] in (["0", "0"], ["10", "0"])}
    keys = [key for key, _, _, _ in design_map.QUANTITIES]
    column = {key: 2 + k for k, key in enumerate(keys)}
    assert rows[("0", "0")][column["kappa_yfp"]] == "0.0365"
    assert rows[("10", "0")][column["H1"]] == rows[("10", "0")][column["H2"]] == "vanished"
    assert rows[("10", "0")][column["ytlk_ratio_kappa"]] == "-"
    assert [rows[k][2 + len(keys) + 2] for k in (("0", "0"), ("10", "0"))] == ["no", "yes"]
    assert "Your gear: rho = 10, mu = 3 deg; nearest grid point (10, 0) (marked *)" in text
    headlines = [line for line in text.splitlines() if line.startswith(("* (", "  ("))]
    assert headlines[0].startswith("  (0, 0): straight rolling stable at V = 0.500-1.000, "
                                   "3.000-140.000 m/s")
    assert "allowed freeplay 0.0365 mm (kappa* 0.3651 at F* = 0.295)" in headlines[0]
    assert ("by the normal form: H1 supercritical, H2 supercritical, H3 subcritical"
            in headlines[0] and "by the normal form" not in headlines[1])
    assert headlines[1].startswith("* (10, 0):")
    assert ("no freeplay allowed (unstable without freeplay at F* = 0.649, on the oleo's "
            "stage switch, V = 10.5 m/s); away from the switch 0.0371 mm (kappa* 0.3714 at "
            "F* = 0.295)") in headlines[1]
    assert (tmp_path / "figures" / "design_map.png").exists()
    # on every panel a dashed box (palette.LIFTOFF) at (10, 0): column 1, row 0; and its
    # legend entry
    fig = saved["fig"]
    panels = [ax for ax in fig.axes if ax.get_visible() and ax.get_title()]
    assert len(panels) == len(design_map.QUANTITIES)
    for ax in panels:
        boxes = [p for p in ax.patches if p.get_edgecolor()[:3]
                 == pytest.approx(matplotlib.colors.to_rgb(palette.LIFTOFF))]
        assert len(boxes) == 1 and boxes[0].get_xy() == pytest.approx((1 - 0.44, -0.44))
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "your gear rho = 10, mu = 3 deg (nearest grid point 10, 0)" in labels


@pytest.mark.parametrize("largest, limit", [(0.0, 5.0), (5.0, 5.0), (5.01, 10.0), (15.0, 20.0),
                                            (49.0, 50.0), (446.0, 50.0)])
def test_a_shared_scale_of_changes_takes_the_least_step_that_holds_the_largest(largest, limit):
    """angle_map.change_limit: the least of 5, 10, 20, 50 % holding the
    largest |change| over all maps, 50 % beyond (the colours saturate);
    non-finite changes (a value that vanished) do not count."""
    from mlgshimmy.shared.draw import angle_map
    maps = [numpy.array([[1.0, -largest], [numpy.nan, 0.0]]), numpy.full((2, 2), numpy.nan),
            numpy.array([[0.5 * largest]])]
    assert angle_map.CHANGE_STEPS == (5.0, 10.0, 20.0, 50.0)
    assert angle_map.change_limit(maps) == limit


def test_the_changes_are_from_the_paper_s_geometry_else_from_the_grid_s_median():
    """Each quantity but the links' positions as its change in % from
    rho = mu = 0; without that point in the grid, from its median; NaN where
    the value vanished."""
    cells = [record(0.0, 0.0, H1=2.0, S=40.0), record(10.0, 0.0, H1=2.3, S=40.0),
             record(20.0, 0.0, H1=None, S=36.0)]
    change, against = design_map.changes(cells, [0.0, 10.0, 20.0], [0.0])
    assert against == "the paper's geometry"
    assert set(change) == {k for k, _, _, _ in design_map.QUANTITIES} - set(design_map.POSITION)
    assert change["H1"][0, :2] == pytest.approx([0.0, 15.0]) and numpy.isnan(change["H1"][0, 2])
    assert change["S"][0] == pytest.approx([0.0, 0.0, -10.0])
    change, against = design_map.changes(cells[1:], [10.0, 20.0], [0.0])
    assert against == "the grid's median"
    assert change["S"][0] == pytest.approx([100 * 2 / 38, -100 * 2 / 38])


def test_every_panel_shares_one_of_two_colour_scales(tmp_path, monkeypatch):
    """The map's twelve panels: the ten changes on one scale -L..L (L = 20 %
    here: H1 changes by 15 %), the two link positions on -1..1; one colour
    bar each; the cells hold the values (not the changes), in one font size."""
    from mlgshimmy.shared import draw
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    saved = {}
    monkeypatch.setattr(draw, "save", lambda fig, name: saved.update(fig=fig))
    cells = [record(0.0, 0.0, H1=2.0, ytlk_ratio=0.0), record(10.0, 0.0, H1=2.3, ytlk_ratio=-0.7),
             record(0.0, 10.0, H1=None, ytlk_ratio=0.3), record(10.0, 10.0, H1=2.1, S=0.95)]
    design_map.plot(cells)
    fig = saved["fig"]
    titles = {title: key for key, (title, _) in design_map.PANELS.items()}
    panels = {titles[ax.get_title()]: ax for ax in fig.axes if ax.get_title() in titles}
    assert set(panels) == {key for key, _, _, _ in design_map.QUANTITIES}
    norms = {key: ax.images[0].norm for key, ax in panels.items()}
    change = [norms[k] for k in norms if k not in design_map.POSITION]
    position = [norms[k] for k in design_map.POSITION]
    assert all(n is change[0] for n in change) and all(n is position[0] for n in position)
    assert (change[0].vmin, change[0].vmax) == (-20.0, 20.0)
    assert (position[0].vmin, position[0].vmax) == (-1.0, 1.0)
    bars = [ax for ax in fig.axes if ax not in panels.values() and ax.get_visible()]
    assert sorted(ax.get_ylabel() or ax.get_xlabel() for ax in bars) == [
        "change from the paper's geometry [%]",
        r"links' position $y_{tlk}/y_{fp}$: $\pm$1 against a side of the freeplay gap"]
    h1 = sorted(t.get_text() for t in panels["H1"].texts)
    assert h1 == ["2.00", "2.10", "2.30", "none"]
    assert len({t.get_fontsize() for ax in panels.values() for t in ax.texts}) == 1


def test_a_finished_grid_is_done_for_status_missing_and_submit(tmp_path, monkeypatch):
    """Points written by the point job (its numbers faked, the writing its own)
    carry the provenance shared.jobs.grid reads: `status` exits 0, `jobs
    --missing` lists none, and the submit pipeline of `make submit-design-map`
    submits nothing."""
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    monkeypatch.setattr(design_map, "compute", lambda rho, mu, rundir: {
        "rho_deg": rho, "mu_deg": mu, "critical_V": 346.0, "cpu_seconds": {"scans": 1.0}})
    grid = ["--rho=0,10", "--mu=0"]
    for name in ("rho0_mu0", "rho10_mu0"):
        design_map.run_point(name)
    with open(tmp_path / "design_map" / "rho10_mu0" / "result.json") as source:
        record = json.load(source)
    assert record["critical_V"] == 346.0
    assert record["provenance"]["parameter_set"] == "figures"
    assert record["provenance"]["settings"]["eom_terms"] == 2
    status = tool("status", *grid, MLG_RUN_ROOT=str(tmp_path))
    assert status.returncode == 0, status.stdout + status.stderr
    assert "design_map: all 2 points have a valid result" in status.stdout, status.stdout
    missing = tool("jobs", "--missing", *grid, MLG_RUN_ROOT=str(tmp_path))
    assert missing.returncode == 0 and missing.stdout == "", missing.stdout
    assert "design_map: 0 of 2 points without a valid result" in missing.stderr
    submitted = subprocess.run(
        [sys.executable, "-m", "mlgshimmy.shared.cluster", "submit", "--scheduler", "slurm",
         "--allow-empty", "--dry-run", "--name", "design_map", "--stage", "-",
         "--out", str(tmp_path / "out")], cwd=ROOT, input=missing.stdout,
        capture_output=True, text=True, env={**os.environ, "MLG_RUN_ROOT": str(tmp_path)})
    assert submitted.returncode == 0 and "nothing to submit" in submitted.stderr, \
        submitted.stdout + submitted.stderr


def test_s_is_found_where_the_fast_steps_stop_before_it(tmp_path, capsys):
    """At (10, 10) deg the orbits from H3 stop (MX) just short of their fold
    with DSMAX 3; fold_S runs them again with Fig. 10's DSMAX 1 and finds S
    at 42.262 m/s, as the 5 x 5 map's table gives it (docs/design-map.md)."""
    _, values = design_map.at(10.0, 10.0)
    h3 = [v for v, hz in design_map.speeds(values)["hopf"] if hz >= design_map.HIGH_HZ][0]
    found = design_map.fold_S(str(tmp_path), h3, values)
    assert "again at DSMAX 1" in capsys.readouterr().out
    assert found["S"] == pytest.approx(42.262, abs=2e-3) and found["stop"] != "MX (no convergence)"


@pytest.mark.parametrize("n, cell_texts, named", [(5, 25, 5), (11, 121, 11), (21, 0, 11)])
def test_a_fine_grid_names_every_other_angle_and_leaves_its_numbers_to_the_table(n, cell_texts,
                                                                                 named):
    """draw.angle_map on an n x n grid of 2-degree steps: each cell numbered
    up to 11 per axis, none beyond; at most 11 angles named per axis; no
    text over text either way (draw.overlap)."""
    import matplotlib.pyplot as plt
    from mlgshimmy.shared.draw import angle_map, overlap
    angles = [2.0 * k - (n - 1) for k in range(n)]
    fig, ax = plt.subplots(figsize=(3.5, 3.0))
    angle_map.angle_map(ax, angles, angles, numpy.arange(n * n, dtype=float).reshape(n, n) / 7,
                        lambda v: f"{v:.2f}", fontsize=4)
    fig.canvas.draw()
    assert len(ax.texts) == cell_texts
    assert len([t for t in ax.get_xticklabels() if t.get_text()]) == named
    assert len([t for t in ax.get_yticklabels() if t.get_text()]) == named
    if n > 11:
        assert overlap.overlaps(fig) == []
    plt.close(fig)
