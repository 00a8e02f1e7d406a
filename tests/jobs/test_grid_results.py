"""Resume and status for the job grids (shared.jobs.grid) and the staged figures
(shared.jobs.cli), on the sweep's and the atlas's command lines: `status` and `summary`
list every point without a valid result with its index (missing, started without a
result, unreadable, another provenance), `jobs --missing` prints only their lines, a
summary refuses to mix provenances, naming the points, unless --mixed-provenance; a
sweep point's result records its provenance.  Staged figures: `jobs --stage K
--missing` and `status`.  Records are written here with the provenance a job records now (Plane.provenance()), so no
AUTO run is needed but the one sweep point."""
import importlib
import json
import os
import subprocess
import sys

import pytest

import helpers
from mlgshimmy.shared.jobs import grid

ROOT = helpers.ROOT
SWEEP = ["--rho=0,10,20", "--mu=0"]
ATLAS = ["--V=100,300", "--Fstar=0.5,1"]


def study(name, *args, root):
    return subprocess.run([sys.executable, "-m", f"mlgshimmy.studies.{name}", *args],
                          cwd=ROOT, capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, MLG_RUN_ROOT=str(root)))


def plane(name):
    module = importlib.import_module("mlgshimmy.studies.sweep" if name == "sweep"
                                     else "mlgshimmy.studies.atlas.__main__")
    return module.POINTS if name == "sweep" else module.CELLS


def fake(name, root, monkeypatch, a, b, record):
    """A point's result.json as its job writes it (Plane.write), under root."""
    monkeypatch.setenv("MLG_RUN_ROOT", str(root))
    return plane(name).write(a, b, record)


def edit(path, **changes):
    with open(path) as f:
        record = json.load(f)
    record["provenance"].update(changes)
    with open(path, "w") as f:
        json.dump(record, f)


def sweep_record(rho, speed):
    return {"rho_deg": rho, "mu_deg": 0.0, "critical_V": speed, "seconds": 1.0}


def test_sweep_status_and_summary_list_every_point_without_a_result(tmp_path, monkeypatch):
    fake("sweep", tmp_path, monkeypatch, 0.0, 0.0, sweep_record(0.0, 346.1))
    os.makedirs(tmp_path / "sweep" / "rho20_mu0")          # started, no result
    status = study("sweep", "status", *SWEEP, root=tmp_path)
    assert status.returncode == 1, status.stdout + status.stderr
    assert "sweep: 3 points: 1 done, 1 missing, 1 no result" in status.stdout, status.stdout
    assert "missing          index 2    rho10_mu0: no " in status.stdout, status.stdout
    assert "no result        index 3    rho20_mu0: " in status.stdout, status.stdout
    assert "jobs --missing --rho=0,10,20 --mu=0" in status.stderr, status.stderr
    summary = study("sweep", "summary", *SWEEP, root=tmp_path)
    assert summary.returncode == 1 and "Traceback" not in summary.stderr, summary.stderr
    assert "index 2" in summary.stdout and "index 3" in summary.stdout, summary.stdout
    assert "summary refused: 2 of 3 points have no result" in summary.stderr, summary.stderr
    missing = study("sweep", "jobs", "--missing", *SWEEP, root=tmp_path)
    assert missing.returncode == 0, missing.stderr
    lines = missing.stdout.splitlines()
    assert [line.split()[-1] for line in lines] == ["rho10_mu0", "rho20_mu0"], lines
    assert all(line.startswith(f"cd {ROOT} && PYTHONPATH=") for line in lines), lines
    every = study("sweep", "jobs", *SWEEP, root=tmp_path).stdout.splitlines()
    assert len(every) == 3 and every[1:] == lines


def test_an_unreadable_result_or_another_provenance_is_missing(tmp_path, monkeypatch):
    for rho in (0.0, 10.0, 20.0):
        path = fake("sweep", tmp_path, monkeypatch, rho, 0.0, sweep_record(rho, 346.1 + rho))
    with open(path, "w") as f:
        f.write('{"rho_deg": 20.0, "critic')                  # cut short
    edit(tmp_path / "sweep" / "rho10_mu0" / "result.json", auto_version="0.9.1")
    status = study("sweep", "status", *SWEEP, root=tmp_path)
    assert status.returncode == 1, status.stdout
    assert "1 done, 1 other provenance, 1 unreadable" in status.stdout, status.stdout
    assert "other provenance index 2    rho10_mu0: recorded with auto_version 0.9.1 (not " \
        in status.stdout, status.stdout
    assert "unreadable       index 3    rho20_mu0: " in status.stdout, status.stdout
    missing = study("sweep", "jobs", "--missing", *SWEEP, root=tmp_path).stdout.split("\n")
    assert [line.split()[-1] for line in missing if line] == ["rho10_mu0", "rho20_mu0"]


def test_a_summary_refuses_mixed_provenance_naming_the_points(tmp_path, monkeypatch):
    for rho in (0.0, 10.0, 20.0):
        fake("sweep", tmp_path, monkeypatch, rho, 0.0, sweep_record(rho, 346.1 + rho))
    other = "0123456789abcdef0123456789abcdef01234567"
    edit(tmp_path / "sweep" / "rho10_mu0" / "result.json", git_commit=other)
    edit(tmp_path / "sweep" / "rho20_mu0" / "result.json", auto_version="0.9.1")
    summary = study("sweep", "summary", *SWEEP, root=tmp_path)
    assert summary.returncode == 1, summary.stdout + summary.stderr
    text = summary.stderr
    assert "the results have 3 different provenances" in text, text
    assert "1 with git_commit 0123456789ab (not " in text and "rho10_mu0 (index 2)" in text
    assert "1 with auto_version 0.9.1 (not " in text and "rho20_mu0 (index 3)" in text
    assert "summary refused: it would mix them" in text and "--mixed-provenance" in text
    assert not (tmp_path / "figures").exists()
    mixed = study("sweep", "summary", "--mixed-provenance", *SWEEP, root=tmp_path)
    assert mixed.returncode == 0, mixed.stderr
    assert "mixing them, as --mixed-provenance asks" in mixed.stderr
    assert mixed.stdout.count("critical speed") == 3, mixed.stdout
    assert (tmp_path / "figures" / "sweep_critical_speed.png").exists()


def test_the_atlas_names_every_missing_cell(tmp_path, monkeypatch):
    fake("atlas", tmp_path, monkeypatch, 100.0, 0.5,
         {"V": 100.0, "Fstar": 0.5, "starts": {}, "label": "straight", "cpu_seconds": 1.0})
    status = study("atlas", "status", *ATLAS, root=tmp_path)
    assert status.returncode == 1, status.stdout
    assert "atlas: 4 cells: 1 done, 3 missing" in status.stdout, status.stdout
    for index, name in ((2, "V300_F0.5"), (3, "V100_F1"), (4, "V300_F1")):
        assert f"index {index:<4} {name}: no " in status.stdout, status.stdout
    summary = study("atlas", "summary", *ATLAS, root=tmp_path)
    assert summary.returncode == 1 and "Traceback" not in summary.stderr, summary.stderr
    assert "summary refused: 3 of 4 cells have no result" in summary.stderr
    assert summary.stdout.count(": no ") == 3, summary.stdout
    missing = study("atlas", "jobs", "--missing", *ATLAS, root=tmp_path)
    assert [line.split()[-1] for line in missing.stdout.splitlines()] == \
        ["V300_F0.5", "V100_F1", "V300_F1"], missing.stdout
    assert "atlas: 3 of 4 cells without a valid result" in missing.stderr


def test_a_sweep_point_records_its_provenance_atomically(tmp_path, monkeypatch):
    point = study("sweep", "point", "rho0_mu0", root=tmp_path)
    assert point.returncode == 0, point.stderr[-2000:]
    folder = tmp_path / "sweep" / "rho0_mu0"
    record = json.loads((folder / "result.json").read_text())
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    now = plane("sweep").provenance()
    assert grid.comparable(record["provenance"]) == grid.comparable(now), record
    assert set(record["provenance"]) >= {"git_commit", "auto_version", "parameter_set",
                                         "settings", "written"}
    assert record["provenance"]["settings"]["parameters"]["eom_terms"] == 2
    assert not [name for name in os.listdir(folder) if name.endswith(".part")]
    status = study("sweep", "status", "--rho=0", "--mu=0", root=tmp_path)
    assert status.returncode == 0 and "all 1 points have a valid result" in status.stdout
    nothing = study("sweep", "jobs", "--missing", "--rho=0", "--mu=0", root=tmp_path)
    assert nothing.returncode == 0 and nothing.stdout == "", nothing.stdout


def figure(*args, root):
    return subprocess.run([sys.executable, "-m", "mlgshimmy.figures.fig11", *args], cwd=ROOT,
                          capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, MLG_RUN_ROOT=str(root)))


def test_a_staged_figure_prints_its_missing_parts_and_its_stages(tmp_path):
    """Fig. 11's parts come in three stages: the Hopf curves from the slices
    (slice_hopf) read the fold curves of stage 2 (upper_folds), and the
    lift-off edge's ends the lift-off speeds, which wait for the long
    chains' inputs (stage 1) to leave the cores to those chains."""
    assert figure("stages", root=tmp_path).stdout.strip() == "3"
    beyond = figure("jobs", "--stage", "4", root=tmp_path)
    assert beyond.returncode != 0 and "--stage 4: its parts have stages 1 to 3" \
        in beyond.stderr, beyond.stderr
    third = [line.split()[-1] for line in
             figure("jobs", "--stage", "3", root=tmp_path).stdout.splitlines()]
    assert third == ["slice_hopf", "liftoff_end_light", "liftoff_end_heavy"], third
    second = [line.split()[-1] for line in
              figure("jobs", "--stage", "2", root=tmp_path).stdout.splitlines()]
    assert len(second) == 15 and {"upper_folds", "grid", "liftoff_0.10"} <= set(second), second
    parts = tmp_path / "fig11" / "parts"
    parts.mkdir(parents=True)
    for name in second[:5]:
        (parts / f"{name}.json").write_text("{}")
    missing = figure("jobs", "--stage", "2", "--missing", root=tmp_path)
    assert [line.split()[-1] for line in missing.stdout.splitlines()] == second[5:]
    assert "fig11: stage 2: 10 of 15 parts not cached" in missing.stderr, missing.stderr
    status = figure("status", root=tmp_path)
    assert status.returncode == 1, status.stdout
    assert "fig11: stage 1: 0 of 24 parts cached" in status.stdout
    assert "fig11: stage 2: 5 of 15 parts cached" in status.stdout
    assert "fig11: stage 3: 0 of 3 parts cached" in status.stdout
    assert f"missing  stage 2, index 6   {second[5]}: no " in status.stdout, status.stdout
    assert status.stdout.count("  missing  ") == 37


def test_a_job_stopped_by_an_out_of_date_model_says_one_line(tmp_path, monkeypatch):
    """mlg.exe older than its mlg.c (autoglue.check_prebuilt) ended a study's
    job in a 30-line traceback; now one line naming the job, the file and
    the make command that rebuilds it."""
    from mlgshimmy.shared import autoglue, paths
    from mlgshimmy.studies import sweep
    (tmp_path / "auto" / "lib").mkdir(parents=True)
    (tmp_path / "auto" / "lib" / "main.o").write_text("")
    model = tmp_path / "models" / "mlg"
    model.parent.mkdir()
    for suffix, age in ((".o", 20), (".exe", 10), (".c", 0)):      # mlg.c edited last
        path = model.parent / f"mlg{suffix}"
        path.write_text("")
        os.utime(path, (1e9 - age, 1e9 - age))
    os.utime(tmp_path / "auto" / "lib" / "main.o", (1e9 - 30, 1e9 - 30))
    monkeypatch.setenv("AUTO_DIR", str(tmp_path / "auto"))
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    monkeypatch.setattr(sweep, "run_point", lambda name: autoglue.check_prebuilt(str(model)))
    monkeypatch.setattr(sys, "argv", ["sweep", "point", "rho0_mu0", "--rho=0", "--mu=0"])
    with pytest.raises(SystemExit) as stop:
        sweep.main()
    rel = os.path.relpath(f"{model}.exe", paths.ROOT)
    assert stop.value.code == (
        f"sweep: rho0_mu0: {model}.exe is out of date (older than mlg.c or AUTO's objects): "
        f"run `make -C {paths.ROOT} {rel}` (the make target of a figure or study rebuilds it "
        "too)")
