"""The design map over side-stay angles (studies.design_map): its grid and
make target, and the mirror gear: (rho, mu) and (-rho, -mu) give the same
numbers, mirrored (y_tlk changes sign; speeds, kappa* equal), to the
continuation's tolerance (docs/model.md 8.5: f(Su; -rho, -mu) = S f(u; rho, mu)).

Run: /usr/bin/python3 -m pytest -q tests/test_design_map.py
"""
import json
import os
import pathlib
import subprocess
import sys

import pytest

from mlgshimmy.shared import continuation as ct
from mlgshimmy.studies import design_map

ROOT = pathlib.Path(__file__).resolve().parent.parent
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


def test_make_design_map_is_the_grid():
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES")}
    proc = subprocess.run(["make", "--no-print-directory", "-n", "design-map",
                           "DESIGN_RHO=0,10", "DESIGN_MU=-5"], cwd=ROOT, env=env,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    points = [line for line in proc.stdout.splitlines() if "design_map point" in line]
    assert [p.split()[-1] for p in points] == ["rho0_mu-5", "rho10_mu-5"]
    assert "design_map summary" in proc.stdout


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


def test_summary_writes_the_table_from_the_grids_records(tmp_path, monkeypatch):
    """summary as shared.jobs.grid calls it (points, their records, their
    provenance): one row per geometry, and "-" where kappa* = 0 leaves no
    freeplay for y_tlk/y_fp at kappa* (None)."""
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    record = {key: 1.0 for key, _, _, _ in design_map.QUANTITIES}
    records = [dict(record, rho_deg=rho, mu_deg=0.0, kappa=0.0, ytlk_ratio_kappa=None,
                    kappa_V=10.5, kappa_mode="strut", cpu_seconds={"scans": 1.0})
               for rho in (0.0, 10.0)]
    design_map.summary([(0.0, 0.0), (10.0, 0.0)], records, None)
    rows = [line.split() for line in (tmp_path / "tables" / "design_map.txt").read_text()
            .splitlines() if line.split()[:2] in (["0", "0"], ["10", "0"])]
    assert len(rows) == 2 and all(row[11] == "-" for row in rows), rows
    assert (tmp_path / "figures" / "design_map.png").exists()


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
        [sys.executable, "-m", "mlgshimmy.shared.jobs.submit", "submit", "--scheduler", "slurm",
         "--allow-empty", "--dry-run", "--name", "design_map", "--stage", "-",
         "--out", str(tmp_path / "out")], cwd=ROOT, input=missing.stdout,
        capture_output=True, text=True, env={**os.environ, "MLG_RUN_ROOT": str(tmp_path)})
    assert submitted.returncode == 0 and "nothing to submit" in submitted.stderr, \
        submitted.stdout + submitted.stderr
