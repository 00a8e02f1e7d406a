"""A run's output is checked complete by its content: a b-file cut at a
line end (which the old last-byte check passed), an s-file missing its last
solution, and a run on a full file system are all errors, the last naming
the full disk."""
import os
import shutil
import subprocess
import sys

import pytest

import helpers
from mlgshimmy.shared import autosession, diagrams, runerror
from mlgshimmy.shared import continuation as ct

REFERENCE = os.path.join(helpers.ROOT, "tests", "reference", "fig07")


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """Fig. 7's straight rolling at F* = 1, run once: (directory, name)."""
    rundir = str(tmp_path_factory.mktemp("complete") / "eq")
    ct.equilibria(rundir, "eq", ct.Start("figures", Fstar=1.0), stop={"V": 400.0})
    return rundir, "eq"


def outputs(rundir, name):
    return [os.path.join(rundir, f"{kind}.{name}") for kind in "bsd"]


def copy(run, tmp_path):
    rundir, name = run
    for path in outputs(rundir, name):
        shutil.copy(path, tmp_path)
    return outputs(str(tmp_path), name)


def test_a_whole_run_reads(run):
    bd = diagrams.read_diagram(outputs(*run), "eq")
    assert bd[0]("HB1")["V"] == pytest.approx(346.1, rel=1e-4)


def test_a_b_file_cut_at_a_line_end_is_an_error(run, tmp_path):
    files = copy(run, tmp_path)
    with open(files[0]) as f:
        lines = f.readlines()
    with open(files[0], "w") as f:
        f.writelines(lines[:-3])                 # whole lines, no end point
    with pytest.raises(runerror.RunError, match="cut short.*has no end point"):
        diagrams.read_diagram(files, "eq")


def test_an_s_file_without_its_last_solution_is_an_error(run, tmp_path):
    files = copy(run, tmp_path)
    auto = autosession.init()
    solutions = auto.parseS.parseS(files[1])
    del solutions[-1]
    solutions.writeFilename(files[1])
    with pytest.raises(runerror.RunError, match="holds solutions.*cut short"):
        diagrams.read_diagram(files, "eq")


@pytest.mark.skipif(os.geteuid() != 0, reason="mounting a small tmpfs needs root")
def test_a_run_on_a_full_disk_says_so(tmp_path):
    disk = tmp_path / "disk"
    disk.mkdir()
    subprocess.run(["mount", "-t", "tmpfs", "-o", "size=48k", "tmpfs", str(disk)], check=True)
    code = ("from mlgshimmy.shared import continuation as ct\n"
            f"ct.equilibria({str(disk / 'eq')!r}, 'eq', ct.Start('figures', Fstar=1.0),"
            " stop={'V': 600.0})\n")
    try:
        proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    finally:
        subprocess.run(["umount", str(disk)], check=True)
    assert proc.returncode != 0
    assert "RunError" in proc.stderr and "is full" in proc.stderr, proc.stderr[-2000:]


def test_an_s_file_cut_at_a_line_end_inside_its_last_solution_is_an_error(run, tmp_path):
    files = copy(run, tmp_path)
    with open(files[1]) as f:
        lines = f.readlines()
    with open(files[1], "w") as f:
        f.writelines(lines[:-1])             # whole lines, the last label's header kept
    with pytest.raises(runerror.RunError, match=f"{files[1]}: solution .* has .* values in "
                       ".* lines, its header says .*: cut short"):
        diagrams.read_diagram(files, "eq")
