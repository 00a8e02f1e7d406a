"""Reference sets (tests/regression/reference_set.py) on copies of the fig07
set in a scratch root: every stored set matches its MANIFEST; a deleted,
extra or edited file is an error naming it; a run writing a b-file the set
lacks is reported, unless the set's runs.json leaves it out; `replace`
killed at each of its steps, or after a few delays, leaves either the
complete old set or the complete new one; and the figures `make regress`
runs ($REGRESS_FIGURES) are exactly those with a set."""
import glob
import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

import compare_diagrams as cd
import reference_set as rs
import helpers

HERE = os.path.join(helpers.ROOT, "tests")
FIGURE = "fig07"
STEPS = ("copying", "manifest", "verified", "exchanged")
SETS = sorted(glob.glob(os.path.join(cd.REFERENCE_ROOT, "*")))


@pytest.mark.parametrize("directory", SETS, ids=os.path.basename)
def test_stored_set_matches_its_manifest(directory):
    try:
        runs = rs.verify(directory)
    except rs.SetError as exc:
        pytest.fail(f"{os.path.basename(directory)}: {exc}")
    assert runs, f"{os.path.basename(directory)}: no runs"


@pytest.fixture(scope="module")
def registered():
    """REGRESS_FIGURES: the figures `make regress` runs."""
    figures = set(helpers.make_variable("REGRESS_FIGURES").split())
    assert figures, "REGRESS_FIGURES is empty: it names the figures `make regress` runs"
    return figures


def test_make_regress_runs_every_figure_with_a_reference_set(registered):
    stored = {os.path.basename(d) for d in SETS}
    assert not stored - registered, f"sets not in REGRESS_FIGURES: {sorted(stored - registered)}"


def test_every_figure_of_regress_figures_has_a_reference_set(registered):
    stored = {os.path.basename(d) for d in SETS}
    assert not registered - stored, \
        f"no tests/reference/<fig>/ for {sorted(registered - stored)}"


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    return str(tmp_path_factory.mktemp("reference-sets"))


@pytest.fixture(scope="module")
def old_runs():
    """The runs of the stored fig07 set."""
    return rs.verify(os.path.join(cd.REFERENCE_ROOT, FIGURE))


def copy_set(work, name):
    path = os.path.join(work, name)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(os.path.join(cd.REFERENCE_ROOT, FIGURE), path)
    return path


def error_of(directory):
    try:
        cd.compare_dirs(directory, os.path.join(cd.REFERENCE_ROOT, FIGURE))
    except cd.DiagramFileError as exc:
        return str(exc)
    return "no error"


def test_manifest_a_deleted_reference_b_file_is_an_error_naming_it(work, old_runs):
    deleted = copy_set(work, "deleted")
    gone = os.path.join(deleted, f"b.{old_runs[0]}")
    os.remove(gone)
    message = error_of(deleted)
    assert gone in message and "missing" in message, message


def test_manifest_an_extra_file_in_a_set_is_an_error_naming_it(work, old_runs):
    extra = copy_set(work, "extra")
    added = os.path.join(extra, "b.stray")
    shutil.copy(os.path.join(extra, f"b.{old_runs[0]}"), added)
    message = error_of(extra)
    assert added in message and "extra" in message, message


def test_manifest_an_edited_reference_file_is_an_error_naming_it(work, old_runs):
    edited = copy_set(work, "edited")
    path = os.path.join(edited, f"b.{old_runs[-1]}")
    with open(path, "a") as f:
        f.write(" ")
    message = error_of(edited)
    assert path in message and "changed" in message, message


def test_a_run_the_figure_writes_without_a_reference_is_reported(work, old_runs):
    ours = copy_set(work, "ours")
    os.makedirs(os.path.join(ours, "sub"))
    shutil.copy(os.path.join(ours, f"b.{old_runs[0]}"), os.path.join(ours, "sub", "b.new"))
    result = cd.compare_dirs(os.path.join(cd.REFERENCE_ROOT, FIGURE), ours)
    assert any(p.startswith("sub/new:") for p in result.problems), result.report()


@pytest.fixture(scope="module")
def new_run(work):
    """A run directory that differs from the fig07 set in one b-file."""
    run = os.path.join(work, "run")
    shutil.rmtree(run, ignore_errors=True)
    os.makedirs(run)
    for path in glob.glob(os.path.join(cd.REFERENCE_ROOT, FIGURE, "b.*")):
        shutil.copy(path, run)
    os.makedirs(os.path.join(run, "zero"))
    shutil.copy(os.path.join(run, "b.eq_F1"), os.path.join(run, "zero", "b.eq"))
    return run


def state(root, old_runs):
    """"old", "new" or what is wrong with root/FIGURE."""
    directory = os.path.join(root, FIGURE)
    try:
        runs = rs.verify(directory)
    except rs.SetError as exc:
        return f"broken: {exc}"
    return {tuple(sorted(old_runs)): "old", tuple(sorted(old_runs + ["zero/eq"])): "new"}.get(
        tuple(runs), f"neither: {runs}")


def replace(root, run, kill_at=None):
    """reference_set.py replace, as make refs-<fig> runs it (PYTHONPATH=drivers:
    tests/conftest.py sets it, as make does)."""
    env = dict(os.environ)
    if kill_at:
        env["MLG_REFS_KILL_AT"] = kill_at
    return subprocess.Popen([sys.executable, os.path.join(HERE, "regression",
                                                          "reference_set.py"),
                             "replace", FIGURE, run, "--root", root], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def fresh_root(work, name):
    root = os.path.join(work, name)
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    shutil.copytree(os.path.join(cd.REFERENCE_ROOT, FIGURE), os.path.join(root, FIGURE))
    return root


@pytest.fixture(scope="module")
def killed(work, new_run, old_runs):
    """{step: (exit status, state of the set, output)} of a replace killed
    at each step, each in its own root kill-<step>."""
    out = {}
    for step in STEPS:
        root = fresh_root(work, f"kill-{step}")
        proc = replace(root, new_run, step)
        text, _ = proc.communicate(timeout=120)
        out[step] = (proc.returncode, state(root, old_runs), text)
    return out


@pytest.mark.parametrize("step", STEPS)
def test_replace_killed_at_a_step_leaves_the_old_or_new_set_complete(killed, step):
    expected = "new" if step == "exchanged" else "old"
    status, got, text = killed[step]
    assert status == -signal.SIGKILL and got == expected, \
        f"killed at '{step}': status {status}, {got} (expected the {expected} set); {text[-300:]}"


def test_replace_after_a_killed_one_succeeds_and_removes_its_leftovers(work, killed, new_run,
                                                                       old_runs):
    leftovers = glob.glob(os.path.join(work, "kill-*", ".*"))
    root = os.path.join(work, "kill-copying")
    proc = replace(root, new_run)
    out, _ = proc.communicate(timeout=120)
    assert leftovers and proc.returncode == 0 and state(root, old_runs) == "new" \
        and not glob.glob(os.path.join(root, ".*")), f"{leftovers}; {out[-300:]}"


@pytest.mark.parametrize("delay", [0.3, 0.6, 0.9, 1.2])
def test_replace_killed_after_a_delay_leaves_the_old_or_new_set_complete(work, new_run,
                                                                         old_runs, delay):
    root = fresh_root(work, f"delay-{delay}")
    proc = replace(root, new_run)
    time.sleep(delay)
    proc.kill()
    proc.communicate()
    assert state(root, old_runs) in ("old", "new"), state(root, old_runs)


@pytest.fixture(scope="module")
def selected(work, new_run):
    """(root, runs stored, replace's output) of a replace into a set whose
    runs.json selects the equilibria only."""
    root = fresh_root(work, "selection")
    with open(os.path.join(root, FIGURE, rs.SELECTION), "w") as f:
        f.write('{"store": ["eq_*"], "reason": "test: the equilibria only"}\n')
    proc = replace(root, new_run)
    out, _ = proc.communicate(timeout=120)
    runs = rs.verify(os.path.join(root, FIGURE)) if proc.returncode == 0 else []
    return root, runs, out


def test_runs_json_replace_stores_only_the_runs_it_selects(selected):
    _, runs, out = selected
    assert runs == ["eq_F0.2", "eq_F1"], f"{runs}; {out[-300:]}"


def test_runs_json_the_comparator_asks_no_reference_of_the_others(selected, new_run):
    result = cd.compare_dirs(os.path.join(selected[0], FIGURE), new_run)
    assert result.ok() and result.points > 0, result.report()
