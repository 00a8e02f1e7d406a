"""The fast regression subset of `make test`: `make regress-<fig>` for each
figure of $REGRESS_QUICK (set by the Makefile, tests/regression/regression.mk),
the first of them twice, started 3 s apart as two users would.  Each must
agree with tests/reference/<fig>/ (no false regression from the other run),
the published build/regress/<fig>/ must agree run by run, and
tests/reference/ must stay untouched."""
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "regression"))
import compare_diagrams as cd  # noqa: E402
from check import check  # noqa: E402


def make_regress(figure):
    return subprocess.Popen(["make", "--no-print-directory", f"regress-{figure}"], cwd=cd.ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def finished(figure, proc, what):
    out, _ = proc.communicate()
    check(f"make regress-{figure}{what}: agrees with its reference",
          proc.returncode == 0 and f"tests/reference/{figure}: agree (" in out
          and "DIFFERENT" not in out,
          out.strip()[-1500:])


def published(figure):
    """Every run of the published build/regress/<figure>/, one check each."""
    reference = os.path.join(cd.REFERENCE_ROOT, figure)
    try:
        runs = cd.run_names(reference)
    except cd.DiagramFileError as exc:
        check(f"{figure}: reference set complete", False, str(exc))
        return
    for run in runs:
        try:
            result = cd.compare_dirs(reference, os.path.join(cd.REGRESS_ROOT, figure), runs=[run])
        except cd.DiagramFileError as exc:
            check(f"{figure}: {run} readable", False, str(exc))
            continue
        check(f"{figure}: {run} agrees with its reference at {result.points} labelled points "
              f"(rtol {result.rtol:g}, atol {result.atol:g})", result.ok() and result.points > 0,
              result.report())


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
    first = make_regress(figures[0])
    time.sleep(3.0)
    second = make_regress(figures[0])
    finished(figures[0], first, " (first of two, 3 s apart)")
    finished(figures[0], second, " (second of two)")
    published(figures[0])
    for figure in figures[1:]:
        finished(figure, make_regress(figure), "")
        published(figure)
    after = snapshot(cd.REFERENCE_ROOT)
    check("the regression runs left tests/reference/ untouched", before == after,
          f"changed: {sorted(set(before.items()) ^ set(after.items()))}")


if __name__ == "__main__":
    main()
