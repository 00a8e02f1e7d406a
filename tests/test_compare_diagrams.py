"""The diagram comparator (tests/regression/compare_diagrams.py) on copies of
the stored fig07 reference, edited one field at a time: identical diagrams
agree; a value moved beyond the tolerance, or a changed special-point type, is
reported naming the run, label and column; a run we no longer write is a
difference naming it; missing and corrupt reference files give an error
naming the file, and the command line exits 0, 1 or 2 accordingly."""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "regression"))
import compare_diagrams as cd  # noqa: E402
from check import approx, check  # noqa: E402

REFERENCE = os.path.join(cd.REFERENCE_ROOT, "fig07")
RUN = "po_F1"
WORK = os.path.join(cd.ROOT, "build", "tests", "compare-diagrams")


def copy_reference(name):
    """A fresh copy of REFERENCE's b.<RUN> in WORK/<name>/; its path."""
    path = os.path.join(WORK, name)
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


def last_point():
    """(label, type, {column: value}) of the last labelled point of RUN, and
    its branch number BR."""
    branch = cd.read_branches(os.path.join(REFERENCE, f"b.{RUN}"))[0]
    index, label, ty = cd.labelled_points(branch)[-1]
    return label, ty, dict(zip(branch.coordnames, branch.coordarray[:, index])), branch.BR


def scaled(directory, label, column, factor):
    """Multiply one column of one labelled row by factor; the new value."""
    coordnames = cd.read_branches(os.path.join(REFERENCE, f"b.{RUN}"))[0].coordnames
    value = last_point()[2][column] * factor
    edit_labelled_row(directory, label, 4 + coordnames.index(column), f"{value:.16e}")
    return value


def compare(reference, ours):
    """compare_dirs on RUN alone."""
    return cd.compare_dirs(reference, ours, runs=[RUN])


def identical():
    result = cd.compare_dirs(REFERENCE, REFERENCE)
    check("identical diagrams agree", result.ok() and result.points > 0,
          result.report() or f"{result.points} labelled points compared")


def perturbed_values():
    label, ty, values, br = last_point()
    far = copy_reference("far")
    scaled(far, label, "freq", 1 + 1e-4)
    result = compare(REFERENCE, far)
    rows = result.rows
    check("freq * (1 + 1e-4) at one point: exactly one difference, naming run, label, "
          "type and column", [r[:5] for r in rows] == [(RUN, br, label, ty, "freq")]
          and not result.problems, result.report())
    check("... with its relative error 1e-4 (to 1e-9)",
          len(rows) == 1 and approx(rows[0][7], 1e-4, abs=1e-9), result.report())
    table = result.report()
    check("... and the table shows both values", len(rows) == 1
          and f"{values['freq']:.10e}" in table and f"{rows[0][6]:.10e}" in table, table)

    near = copy_reference("near")
    scaled(near, label, "freq", 1 + 1e-7)
    result = compare(REFERENCE, near)
    check("freq * (1 + 1e-7) is within the default rtol 1e-5", result.ok(), result.report())

    loose = copy_reference("loose")
    scaled(loose, label, "freq", 1 + 1e-4)
    with open(os.path.join(loose, cd.TOLERANCE_FILE), "w") as f:
        f.write('{"rtol": 1e-3}\n')
    result = compare(loose, far)
    check("a reference's tolerances.json (rtol 1e-3) overrides the default", result.ok(),
          result.report())


def near_zero_column():
    label, _, values, _ = last_point()
    check("psi_mean of the symmetric orbit is rounding noise (|x| < 1e-14)",
          abs(values["psi_mean"]) < 1e-14, f"psi_mean = {values['psi_mean']}")
    scale = max(abs(v) for v in cd.read_branches(os.path.join(REFERENCE, f"b.{RUN}"))[0]
                ["psi_amp"])
    noise = copy_reference("noise")
    coordnames = cd.read_branches(os.path.join(REFERENCE, f"b.{RUN}"))[0].coordnames
    edit_labelled_row(noise, label, 4 + coordnames.index("psi_mean"), f"{0.3e-5 * scale:.6e}")
    result = compare(REFERENCE, noise)
    check("psi_mean moved by 0.3e-5 of the largest psi_amp: within rtol of that scale",
          result.ok(), result.report())
    edit_labelled_row(noise, label, 4 + coordnames.index("psi_mean"), f"{1e-3 * scale:.6e}")
    rows = compare(REFERENCE, noise).rows
    check("psi_mean moved by 1e-3 of the largest psi_amp: reported",
          [r[4] for r in rows] == ["psi_mean"], f"rows {rows}")


def summary():
    """The Hopf point of eq_F1 moved by 1 % in V."""
    run = "eq_F1"
    path = os.path.join(WORK, "summary")
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
    check(f"the report opens with the special points; {ty}{label} of {run} moved 1 % in V is "
          "shown reference -> ours with its relative change",
          first.strip().startswith("special points") and f"{ty}{label}" in text
          and f"{V:.6g}" in text and f"{V * 1.01:.6g}" in text and "+1.00e-02" in text, text)


def ignored_labels():
    label, ty, _, _ = last_point()
    moved = copy_reference("ignored")
    scaled(moved, label, "V", 1.05)
    with open(os.path.join(moved, cd.LABEL_FILE), "w") as f:
        f.write('{"ignore": [{"run": "po_*", "type": "%s", "reason": "test"}]}\n' % ty)
    result = cd.compare_dirs(moved, REFERENCE, runs=[RUN])
    check(f"labels.json leaves the {ty} points of po_* out: {ty}{label} moved 5 % unseen",
          result.ok(), result.report())
    result = cd.compare_dirs(moved, REFERENCE, runs=[RUN], raw=True)
    check("... and raw=True compares it as stored", len(result.rows) == 1, result.report())


def changed_sequence():
    label, ty, _, _ = last_point()
    changed = copy_reference("sequence")
    edit_labelled_row(changed, label, 2, "-4")  # TY -4: a UZ point
    result = cd.compare_dirs(REFERENCE, changed, runs=[RUN], raw=True)  # every label
    problem = " ".join(result.problems)
    check(f"special point {ty}{label} turned into UZ{label}: sequence mismatch reported",
          len(result.problems) == 1 and f"UZ{label}]" in problem and f"{ty}{label}]" in problem,
          problem or "no problem reported")
    check("... and the points before it still compared (and agree)",
          result.points == len(cd.labelled_points(
              cd.read_branches(os.path.join(REFERENCE, f"b.{RUN}"))[0])) - 1
          and not result.rows, f"{result.points} points compared, rows {result.rows}")


def file_errors():
    def error_of(reference, run):
        try:
            compare(reference, run)
        except cd.DiagramFileError as exc:
            return str(exc)
        return "no error"

    missing_dir = os.path.join(WORK, "no-such-reference")
    check("missing reference directory: error names it",
          missing_dir in error_of(missing_dir, REFERENCE), error_of(missing_dir, REFERENCE))
    empty = os.path.join(WORK, "empty")
    os.makedirs(empty, exist_ok=True)
    ours = os.path.join(empty, f"b.{RUN}")
    result = compare(copy_reference("only"), empty)
    check("missing b-file in the run directory: a difference naming it",
          not result.ok() and ours in " ".join(result.problems), result.report())
    for name, damage in (("garbage", "this is not a b-file\n"),
                         ("truncated", None), ("blank", "")):
        bad = copy_reference(name)
        path = os.path.join(bad, f"b.{RUN}")
        if damage is None:  # cut the file in the middle of a data row
            text = open(path).read()
            damage = text[:len(text) // 2 + 7]
        with open(path, "w") as f:
            f.write(damage)
        message = error_of(bad, REFERENCE)
        check(f"{name} reference b-file: error names the file", path in message
              and "not a readable AUTO b-file" in message, message)


def command_line():
    def cli(*args):
        proc = subprocess.run([sys.executable, os.path.join(HERE, "regression",
                                                            "compare_diagrams.py"), *args],
                              capture_output=True, text=True)
        return proc.returncode, proc.stdout + proc.stderr

    status, out = cli(REFERENCE, REFERENCE)
    check("CLI: identical directories exit 0", status == 0, out)
    status, out = cli("--runs", RUN, "--", REFERENCE, os.path.join(WORK, "far"))
    check("CLI: a difference exits 1 and prints the table", status == 1
          and "rel. error" in out and "freq" in out, out)
    garbage = os.path.join(WORK, "garbage", f"b.{RUN}")
    status, out = cli("--runs", RUN, "--", os.path.join(WORK, "garbage"), REFERENCE)
    check("CLI: a corrupt reference exits 2 naming the file", status == 2 and garbage in out,
          out)


def main():
    os.makedirs(WORK, exist_ok=True)
    identical()
    perturbed_values()
    near_zero_column()
    summary()
    ignored_labels()
    changed_sequence()
    file_errors()
    command_line()


if __name__ == "__main__":
    main()
