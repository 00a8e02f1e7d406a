"""The diagram comparator (tests/regression/compare_diagrams.py) on copies of
the stored fig07 reference, edited one field at a time: identical diagrams
agree; a value moved beyond the tolerance, or a changed special-point type, is
reported naming the run, label and column; a run we no longer write is a
difference naming it; missing and corrupt reference files give an error
naming the file, and the command line exits 0, 1 or 2 accordingly."""
import math
import os
import shutil
import subprocess
import sys

import pytest

import compare_diagrams as cd

REFERENCE = os.path.join(cd.REFERENCE_ROOT, "fig07")
RUN = "po_F1"
SCRIPT = os.path.join(cd.ROOT, "tests", "regression", "compare_diagrams.py")


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    """The scratch directory of the edited copies."""
    return str(tmp_path_factory.mktemp("compare-diagrams"))


def copy_reference(work, name):
    """A fresh copy of REFERENCE's b.<RUN> in work/<name>/; its path."""
    path = os.path.join(work, name)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    shutil.copy(os.path.join(REFERENCE, f"b.{RUN}"), path)
    return path


def edit_labelled_row(directory, label, field, value):
    """Set field `field` (0 BR, 1 PT, 2 TY, 3 LAB, 4.. columns) of the row
    labelled `label` in directory/b.<RUN> to the string `value`."""
    path = os.path.join(directory, f"b.{RUN}")
    with open(path) as f:
        lines = f.readlines()
    for n, line in enumerate(lines):
        fields = line.split()
        if fields[0] != "0" and int(fields[3]) == label:
            fields[field] = value
            lines[n] = " ".join(fields) + "\n"
            break
    else:
        raise AssertionError(f"no label {label} in {path}")
    with open(path, "w") as f:
        f.writelines(lines)


def reference_branch():
    return cd.read_branches(os.path.join(REFERENCE, f"b.{RUN}"))[0]


def last_point():
    """(label, type, {column: value}) of the last labelled point of RUN, and
    its branch number BR."""
    branch = reference_branch()
    index, label, ty = cd.labelled_points(branch)[-1]
    return label, ty, dict(zip(branch.coordnames, branch.coordarray[:, index])), branch.BR


def scaled(directory, label, column, factor):
    """Multiply one column of one labelled row by factor; the new value."""
    coordnames = reference_branch().coordnames
    value = last_point()[2][column] * factor
    edit_labelled_row(directory, label, 4 + coordnames.index(column), f"{value:.16e}")
    return value


def compare(reference, ours):
    """compare_dirs on RUN alone."""
    return cd.compare_dirs(reference, ours, runs=[RUN])


def far_copy(work):
    """A copy with freq * (1 + 1e-4) at the last labelled point."""
    far = copy_reference(work, "far")
    scaled(far, last_point()[0], "freq", 1 + 1e-4)
    return far


def test_identical_diagrams_agree():
    result = cd.compare_dirs(REFERENCE, REFERENCE)
    assert result.ok() and result.points > 0, \
        result.report() or f"{result.points} labelled points compared"


def test_value_moved_beyond_rtol_is_one_difference_naming_it(work):
    """freq * (1 + 1e-4) at one point: exactly one difference, naming run,
    label, type and column, with its relative error 1e-4 (to 1e-9); the
    table shows both values."""
    label, ty, values, br = last_point()
    result = compare(REFERENCE, far_copy(work))
    rows = result.rows
    assert [r[:5] for r in rows] == [(RUN, br, label, ty, "freq")] and not result.problems, \
        result.report()
    assert len(rows) == 1 and math.isclose(rows[0][7], 1e-4, abs_tol=1e-9), result.report()
    table = result.report()
    assert len(rows) == 1 and f"{values['freq']:.10e}" in table \
        and f"{rows[0][6]:.10e}" in table, table


def test_value_moved_within_the_default_rtol_agrees(work):
    """freq * (1 + 1e-7) is within the default rtol 1e-5."""
    near = copy_reference(work, "near")
    scaled(near, last_point()[0], "freq", 1 + 1e-7)
    result = compare(REFERENCE, near)
    assert result.ok(), result.report()


def test_reference_tolerances_json_overrides_the_default_rtol(work):
    """A reference's tolerances.json (rtol 1e-3) overrides the default."""
    loose = copy_reference(work, "loose")
    scaled(loose, last_point()[0], "freq", 1 + 1e-4)
    with open(os.path.join(loose, cd.TOLERANCE_FILE), "w") as f:
        f.write('{"rtol": 1e-3}\n')
    result = compare(loose, far_copy(work))
    assert result.ok(), result.report()


def test_near_zero_mean_column_compared_on_the_amplitudes_scale(work):
    """psi_mean of the symmetric orbit is rounding noise (|x| < 1e-14);
    moved by 0.3e-5 of the largest psi_amp it is within rtol of that
    scale, moved by 1e-3 of it it is reported."""
    label, _, values, _ = last_point()
    assert abs(values["psi_mean"]) < 1e-14, f"psi_mean = {values['psi_mean']}"
    branch = reference_branch()
    scale = max(abs(v) for v in branch["psi_amp"])
    noise = copy_reference(work, "noise")
    column = 4 + branch.coordnames.index("psi_mean")
    edit_labelled_row(noise, label, column, f"{0.3e-5 * scale:.6e}")
    result = compare(REFERENCE, noise)
    assert result.ok(), result.report()
    edit_labelled_row(noise, label, column, f"{1e-3 * scale:.6e}")
    rows = compare(REFERENCE, noise).rows
    assert [r[4] for r in rows] == ["psi_mean"], f"rows {rows}"


def test_report_opens_with_the_special_points_moved(work):
    """The Hopf point of eq_F1 moved by 1 % in V is shown reference -> ours
    with its relative change, first in the report."""
    run = "eq_F1"
    path = os.path.join(work, "summary")
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    shutil.copy(os.path.join(REFERENCE, f"b.{run}"), path)
    branch = cd.read_branches(os.path.join(REFERENCE, f"b.{run}"))[0]
    index, label, ty = [p for p in cd.labelled_points(branch) if p[2] == "HB"][0]
    V = branch.coordarray[branch.coordnames.index("V"), index]
    lines = open(os.path.join(path, f"b.{run}")).readlines()
    for n, line in enumerate(lines):
        fields = line.split()
        if fields[0] != "0" and int(fields[3]) == label:
            fields[4] = f"{V * 1.01:.16e}"
            lines[n] = " ".join(fields) + "\n"
    with open(os.path.join(path, f"b.{run}"), "w") as f:
        f.writelines(lines)
    text = cd.compare_dirs(REFERENCE, path, runs=[run]).report()
    first = text.splitlines()[0] if text else ""
    assert first.strip().startswith("special points") and f"{ty}{label}" in text \
        and f"{V:.6g}" in text and f"{V * 1.01:.6g}" in text and "+1.00e-02" in text, text


def test_labels_json_leaves_out_ignored_points_unless_raw(work):
    """labels.json leaves the points of po_* of the last point's type out
    (moved 5 % unseen); raw=True compares them as stored."""
    label, ty, _, _ = last_point()
    moved = copy_reference(work, "ignored")
    scaled(moved, label, "V", 1.05)
    with open(os.path.join(moved, cd.LABEL_FILE), "w") as f:
        f.write('{"ignore": [{"run": "po_*", "type": "%s", "reason": "test"}]}\n' % ty)
    result = cd.compare_dirs(moved, REFERENCE, runs=[RUN])
    assert result.ok(), f"{ty}{label} moved 5 % was seen: {result.report()}"
    result = cd.compare_dirs(moved, REFERENCE, runs=[RUN], raw=True)
    assert len(result.rows) == 1, result.report()


def test_changed_special_point_type_is_a_sequence_mismatch(work):
    """A special point turned into a UZ point: the sequence mismatch is
    reported, and the points before it are still compared (and agree)."""
    label, ty, _, _ = last_point()
    changed = copy_reference(work, "sequence")
    edit_labelled_row(changed, label, 2, "-4")  # TY -4: a UZ point
    result = cd.compare_dirs(REFERENCE, changed, runs=[RUN], raw=True)  # every label
    problem = " ".join(result.problems)
    assert len(result.problems) == 1 and f"UZ{label}]" in problem and f"{ty}{label}]" in problem, \
        problem or "no problem reported"
    assert result.points == len(cd.labelled_points(reference_branch())) - 1 \
        and not result.rows, f"{result.points} points compared, rows {result.rows}"


def error_of(reference, run):
    try:
        compare(reference, run)
    except cd.DiagramFileError as exc:
        return str(exc)
    return "no error"


def test_missing_reference_directory_is_an_error_naming_it(work):
    missing_dir = os.path.join(work, "no-such-reference")
    message = error_of(missing_dir, REFERENCE)
    assert missing_dir in message, message


def test_missing_b_file_in_the_run_directory_is_a_difference_naming_it(work):
    empty = os.path.join(work, "empty")
    os.makedirs(empty, exist_ok=True)
    ours = os.path.join(empty, f"b.{RUN}")
    result = compare(copy_reference(work, "only"), empty)
    assert not result.ok() and ours in " ".join(result.problems), result.report()


def damaged_copy(work, name):
    """A copy of the reference whose b-file is garbage, cut in the middle
    of a data row, or empty."""
    bad = copy_reference(work, name)
    path = os.path.join(bad, f"b.{RUN}")
    if name == "truncated":
        text = open(path).read()
        damage = text[:len(text) // 2 + 7]
    else:
        damage = {"garbage": "this is not a b-file\n", "blank": ""}[name]
    with open(path, "w") as f:
        f.write(damage)
    return bad, path


@pytest.mark.parametrize("name", ("garbage", "truncated", "blank"))
def test_damaged_reference_b_file_is_an_error_naming_it(work, name):
    bad, path = damaged_copy(work, name)
    message = error_of(bad, REFERENCE)
    assert path in message and "not a readable AUTO b-file" in message, message


def cli(*args):
    proc = subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)
    return proc.returncode, proc.stdout + proc.stderr


def test_command_line_identical_directories_exit_0():
    status, out = cli(REFERENCE, REFERENCE)
    assert status == 0, out


def test_command_line_a_difference_exits_1_with_the_table(work):
    status, out = cli("--runs", RUN, "--", REFERENCE, far_copy(work))
    assert status == 1 and "rel. error" in out and "freq" in out, out


def test_command_line_a_corrupt_reference_exits_2_naming_it(work):
    bad, path = damaged_copy(work, "garbage")
    status, out = cli("--runs", RUN, "--", bad, REFERENCE)
    assert status == 2 and path in out, out


def test_command_line_two_runs_of_ones_own_need_no_manifest(work):
    """docs/regression.md: any two directories of b-files; the first is the
    baseline and only its b-files are compared.  It demanded a MANIFEST."""
    mine = copy_reference(work, "mine")
    far = far_copy(work)
    shutil.copy(os.path.join(REFERENCE, "b.eq_F1"), far)      # a run the baseline has not
    status, out = cli(mine, mine)
    assert status == 0 and "agree (5 labelled points, 55 values" in out, out
    status, out = cli(mine, far)
    assert status == 1 and "freq" in out and "eq_F1" not in out, out


def test_a_reference_set_without_its_manifest_is_still_refused(work, monkeypatch):
    monkeypatch.setattr(cd, "REFERENCE_ROOT", work)
    mine = copy_reference(work, "unlisted")
    with pytest.raises(cd.DiagramFileError, match=r"unlisted/MANIFEST: missing"):
        cd.compare_dirs(mine, mine)


def test_a_tolerance_carries_its_reason(tmp_path):
    """tolerances.json may say why a set is looser ("reason", a text), and
    nothing else besides rtol and atol."""
    (tmp_path / "tolerances.json").write_text('{"rtol": 2e-4, "reason": "why"}')
    assert cd.tolerances(str(tmp_path)) == (2e-4, cd.ATOL)
    (tmp_path / "tolerances.json").write_text('{"rtol": 2e-4, "reason": 3}')
    with pytest.raises(cd.SettingsError, match="'reason' must be a text"):
        cd.tolerances(str(tmp_path))
