"""The fast regression subset of `make test`: each figure of $REGRESS_QUICK
(set by the Makefile, tests/regression/regression.mk) is rerun by its driver
drivers/<fig>.py into build/tests/regress/<fig>/ and every run is compared
with tests/reference/<fig>/ (default tolerances, compare_diagrams.py)."""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "regression"))
import compare_diagrams as cd  # noqa: E402
from check import check  # noqa: E402

RUN_ROOT = os.path.join(cd.ROOT, "build", "tests", "regress")


def regress(figure):
    """Run one figure's driver into RUN_ROOT; one check per reference run."""
    shutil.rmtree(os.path.join(RUN_ROOT, figure), ignore_errors=True)
    proc = subprocess.run([sys.executable, os.path.join(cd.ROOT, "drivers", f"{figure}.py")],
                          env=dict(os.environ, MLG_RUN_ROOT=RUN_ROOT),
                          capture_output=True, text=True)
    if not check(f"{figure}: driver runs", proc.returncode == 0,
                 (proc.stdout + proc.stderr).strip().splitlines()[-1:]):
        return
    reference = os.path.join(cd.REFERENCE_ROOT, figure)
    try:
        runs = cd.run_names(reference)
    except cd.DiagramFileError as exc:
        check(f"{figure}: reference present", False, str(exc))
        return
    for run in runs:
        try:
            result = cd.compare_dirs(reference, os.path.join(RUN_ROOT, figure), runs=[run])
        except cd.DiagramFileError as exc:
            check(f"{figure}: {run} readable", False, str(exc))
            continue
        if not result.ok():
            print(result.report())
        check(f"{figure}: {run} agrees with its reference at {result.points} labelled points "
              f"(rtol {result.rtol:g}, atol {result.atol:g})", result.ok() and result.points > 0,
              f"{len(result.problems)} structural, {len(result.rows)} values differ (table above)")


def snapshot(directory):
    """{path: (size, mtime)} of every file under directory."""
    return {os.path.join(d, f): (os.stat(os.path.join(d, f)).st_size,
                                 os.stat(os.path.join(d, f)).st_mtime_ns)
            for d, _, files in os.walk(directory) for f in files}


def main():
    figures = os.environ.get("REGRESS_QUICK", "").split()
    if not check("REGRESS_QUICK names the figures to compare (set by the Makefile)",
                 figures, "REGRESS_QUICK is empty or unset: run through `make test`"):
        return
    before = snapshot(cd.REFERENCE_ROOT)
    for figure in figures:
        regress(figure)
    after = snapshot(cd.REFERENCE_ROOT)
    check("the regression runs left tests/reference/ untouched", before == after,
          f"changed: {sorted(set(before.items()) ^ set(after.items()))}")


if __name__ == "__main__":
    main()
