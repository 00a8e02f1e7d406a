"""The diagram comparator (tests/regression/compare_diagrams.py) compares what
a diagram means, run as a command on edited copies of tests/reference/fig07:

- the stability of every point (AUTO's PT sign, negative = stable): a branch
  whose every sign is flipped is a difference naming run, branch and where;
  a stability change moved by one continuation step agrees, by three steps
  it is a difference giving both positions;
- a non-finite value at an unlabelled point is a difference;
- exit status 2 (a usage error, no traceback) for a missing or mistyped run
  directory, a missing AUTO, a labels.json rule naming a column that does not
  exist, and a tolerances.json with an unknown key;
- every stored reference set agrees with itself (exit 0).

Run with: python3 -m pytest -q tests/regression/test_compare_meaning.py
"""
import glob
import hashlib
import os
import shutil
import subprocess
import sys

import pytest

import helpers

ROOT = helpers.ROOT
COMPARE = os.path.join(ROOT, "tests", "regression", "compare_diagrams.py")
REFERENCE_ROOT = os.path.join(ROOT, "tests", "reference")
FIG07 = os.path.join(REFERENCE_ROOT, "fig07")


def compare(*args, env=None):
    """(exit status, stdout + stderr) of the comparator."""
    proc = subprocess.run([sys.executable, COMPARE, *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, env=env, timeout=600)
    return proc.returncode, proc.stdout + proc.stderr


def rows(path):
    """The lines of a b-file, split into header lines and data rows."""
    with open(path) as f:
        return f.readlines()


def data_rows(lines):
    """Indices of the data rows (BR != 0) of a b-file's lines."""
    return [n for n, line in enumerate(lines) if line.split() and line.split()[0] != "0"]


def set_pt(line, sign):
    """The row with its PT field (I6 after BR's I4) given the sign +1/-1."""
    pt = int(line[4:10])
    return line[:4] + f"{sign * abs(pt):6d}" + line[10:]


def columns(lines):
    """Column names of a b-file (from its header line with PT TY LAB)."""
    header = [line for line in lines if " PT " in line and " TY " in line][0]
    return header.split()[4:]


def write(path, lines):
    with open(path, "w") as f:
        f.writelines(lines)


def copy_set(tmp_path, name="fig07"):
    path = tmp_path / name
    shutil.copytree(FIG07, path)
    return path


def rewrite_manifest(directory):
    """A MANIFEST matching the set's files (as reference_set.py writes it)."""
    lines = []
    for parent, dirs, files in os.walk(directory):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for name in files:
            rel = os.path.relpath(os.path.join(parent, name), directory)
            if rel != "MANIFEST" and not name.startswith("."):
                with open(os.path.join(parent, name), "rb") as f:
                    lines.append(f"{hashlib.sha256(f.read()).hexdigest()}  {rel}\n")
    write(os.path.join(directory, "MANIFEST"), sorted(lines, key=lambda s: s.split("  ", 1)[1]))


def test_flipped_stability_is_a_difference(tmp_path):
    ours = copy_set(tmp_path)
    path = ours / "b.po_F1"
    lines = rows(path)
    first = data_rows(lines)[0]
    V0 = float(lines[first].split()[4])
    for n in data_rows(lines):
        pt = int(lines[n][4:10])
        lines[n] = set_pt(lines[n], -1 if pt > 0 else 1)
    write(path, lines)
    status, out = compare(FIG07, ours)
    assert status == 1, out
    assert "DIFFERENT" in out
    line = [s for s in out.splitlines() if "stability" in s and "po_F1" in s]
    assert line, out
    # names run, branch and where (the first segment, from the branch's first point)
    assert "po_F1 branch 1" in line[0], out
    assert f"V = {V0:.6g}" in line[0], out
    # the other runs of the set agree: only po_F1 is named
    assert not any(r in out for r in ("eq_F1 branch", "eq_F0.2 branch", "po_F0.2 branch")), out


def moved_change(tmp_path, name, points):
    """A copy of fig07 whose eq_F1 is stable `points` points further past its
    Hopf point (the labels and values unchanged); (directory, V at the
    reference's first unstable point, V at ours)."""
    ours = copy_set(tmp_path, name)
    path = ours / "b.eq_F1"
    lines = rows(path)
    data = data_rows(lines)
    signs = [int(lines[n][4:10]) for n in data]
    first_unstable = next(k for k in range(2, len(signs)) if signs[k] > 0 > signs[k - 1])
    for k in range(first_unstable, first_unstable + points):
        lines[data[k]] = set_pt(lines[data[k]], -1)
    write(path, lines)
    V = [float(lines[n].split()[4]) for n in data]
    return ours, V[first_unstable], V[first_unstable + points]


def test_stability_change_within_a_step_agrees(tmp_path):
    ours, V_ref, V_ours = moved_change(tmp_path, "one", 1)
    assert 1.0 < V_ours - V_ref < 3.0  # one step of about 2 m/s
    status, out = compare(FIG07, ours)
    assert status == 0, out
    assert "stability changes" in out, out


def test_stability_change_three_steps_away_is_a_difference(tmp_path):
    ours, V_ref, V_ours = moved_change(tmp_path, "three", 3)
    assert V_ours - V_ref > 5.0
    status, out = compare(FIG07, ours)
    assert status == 1, out
    line = [s for s in out.splitlines() if "eq_F1 branch 1" in s and "stability" in s]
    assert line, out
    assert f"{V_ours:.6g}" in line[0] and f"{V_ref:.6g}" in line[0], out


@pytest.mark.parametrize("value", ["NaN", "Infinity", "-inf"])
def test_non_finite_value_at_an_unlabelled_point(tmp_path, value):
    ours = copy_set(tmp_path)
    path = ours / "b.eq_F1"
    lines = rows(path)
    names = columns(lines)
    unlabelled = [n for n in data_rows(lines) if int(lines[n].split()[3]) == 0]
    n = unlabelled[len(unlabelled) // 2]
    fields = lines[n].split()
    fields[4 + names.index("L2-NORM")] = value
    lines[n] = " ".join(fields) + "\n"
    write(path, lines)
    status, out = compare(FIG07, ours)
    assert status == 1, out
    line = [s for s in out.splitlines() if "non-finite" in s]
    assert line and "eq_F1 branch 1" in line[0] and "L2-NORM" in line[0], out


def test_missing_or_mistyped_run_directory_is_exit_2(tmp_path):
    for run_dir in (tmp_path / "no-such-dir", os.path.join(ROOT, "build", "regress", "fig7x")):
        status, out = compare(FIG07, run_dir)
        assert status == 2, out
        assert str(run_dir) in out or os.path.relpath(run_dir, ROOT) in out, out
        assert "Traceback" not in out, out
    status, out = compare("--figure", "fig07", tmp_path / "no-such-dir")
    assert status == 2 and "Traceback" not in out, out


def test_missing_auto_is_exit_2(tmp_path):
    env = dict(os.environ, AUTO_DIR=str(tmp_path / "no-auto"))
    status, out = compare(FIG07, FIG07, env=env)
    assert status == 2, out
    assert "AUTO_DIR" in out and str(tmp_path / "no-auto") in out, out
    assert "Traceback" not in out, out


def test_labels_rule_naming_a_missing_column_is_a_usage_error(tmp_path):
    ref = copy_set(tmp_path)
    with open(ref / "labels.json", "w") as f:
        f.write('{"ignore": [{"run": "*po*", "type": "TR", "from": {"Vee": 550.0}, '
                '"reason": "a typo in the column name"}]}\n')
    rewrite_manifest(ref)
    status, out = compare(ref, FIG07)
    assert status == 2, out
    assert "labels.json" in out and "'Vee'" in out, out
    assert "Traceback" not in out, out


@pytest.mark.parametrize("text,named", [
    ('{"ignore": [{"run": "*po*", "type": "TR", "from": [550], "reason": "r"}]}', "from"),
    ('{"ignore": [{"run": "*po*", "type": "TR", "form": {"V": 550}, "reason": "r"}]}', "form"),
    ('{"ignore": [{"run": "*po*", "type": "TRX", "reason": "r"}]}', "TRX"),
])
def test_malformed_labels_rule_is_a_usage_error(tmp_path, text, named):
    ref = copy_set(tmp_path)
    with open(ref / "labels.json", "w") as f:
        f.write(text + "\n")
    rewrite_manifest(ref)
    status, out = compare(ref, FIG07)
    assert status == 2, out
    assert "labels.json" in out and named in out and "Traceback" not in out, out


@pytest.mark.parametrize("text,named", [('{"rtoll": 1e-3}', "rtoll"), ('{"rtol": -1}', "rtol")])
def test_bad_tolerances_are_a_usage_error(tmp_path, text, named):
    ref = copy_set(tmp_path)
    with open(ref / "tolerances.json", "w") as f:
        f.write(text + "\n")
    rewrite_manifest(ref)
    status, out = compare(ref, FIG07)
    assert status == 2, out
    assert "tolerances.json" in out and named in out and "Traceback" not in out, out


@pytest.mark.parametrize("figure", sorted(os.path.basename(d) for d in
                                          glob.glob(os.path.join(REFERENCE_ROOT, "*"))))
def test_every_reference_set_agrees_with_itself(figure):
    directory = os.path.join(REFERENCE_ROOT, figure)
    status, out = compare(directory, directory)
    assert status == 0, out
    assert ": agree (" in out, out
