"""The fast regression subset of `make test`: `make regress-<fig>` for each
figure of $REGRESS_QUICK (set by the Makefile, tests/regression/regression.mk),
the first of them twice, started 3 s apart as two users would.  Each must
agree with tests/reference/<fig>/ (no false regression from the other run),
the published build/regress/<fig>/ must agree run by run, and
tests/reference/ must stay untouched."""
import os
import subprocess
import time

import pytest

import compare_diagrams as cd
import helpers


def make_regress(figure):
    return subprocess.Popen(["make", "--no-print-directory", f"regress-{figure}"], cwd=cd.ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def snapshot(directory):
    """{path: (size, mtime)} of every file under directory."""
    return {os.path.join(d, f): (os.stat(os.path.join(d, f)).st_size,
                                 os.stat(os.path.join(d, f)).st_mtime_ns)
            for d, _, files in os.walk(directory) for f in files}


@pytest.fixture(scope="module")
def quick():
    figures = helpers.make_variable("REGRESS_QUICK").split()
    assert figures, "REGRESS_QUICK is empty: it names the figures `make test` compares"
    return figures


def test_regress_quick_names_the_figures_to_compare(quick):
    """REGRESS_QUICK (set by the Makefile) is not empty (the fixture asserts it)."""
    assert quick


@pytest.fixture(scope="module")
def regressed(quick):
    """Every figure of REGRESS_QUICK through make regress-<fig>, the first
    twice, 3 s apart: ([(figure, what, exit status, output)], snapshot of
    tests/reference/ before, after)."""
    before = snapshot(cd.REFERENCE_ROOT)
    first = make_regress(quick[0])
    time.sleep(3.0)
    second = make_regress(quick[0])
    runs = []
    for proc, what in ((first, " (first of two, 3 s apart)"), (second, " (second of two)")):
        out, _ = proc.communicate()
        runs.append((quick[0], what, proc.returncode, out))
    for figure in quick[1:]:
        proc = make_regress(figure)
        out, _ = proc.communicate()
        runs.append((figure, "", proc.returncode, out))
    return runs, before, snapshot(cd.REFERENCE_ROOT)


def test_make_regress_of_each_quick_figure_agrees_with_its_reference(regressed):
    failed = [f"make regress-{figure}{what}: exit status {status}\n{out.strip()[-1500:]}"
              for figure, what, status, out in regressed[0]
              if not (status == 0 and f"tests/reference/{figure}: agree (" in out
                      and "DIFFERENT" not in out)]
    assert not failed, "\n\n".join(failed)


def test_published_regress_runs_agree_with_their_reference_run_by_run(quick, regressed):
    """Every run of the published build/regress/<figure>/, each compared on
    its own."""
    failed, compared = [], 0
    for figure in quick:
        reference = os.path.join(cd.REFERENCE_ROOT, figure)
        try:
            runs = cd.run_names(reference)
        except cd.DiagramFileError as exc:
            failed.append(f"{figure}: reference set incomplete: {exc}")
            continue
        for run in runs:
            try:
                result = cd.compare_dirs(reference, os.path.join(cd.REGRESS_ROOT, figure),
                                         runs=[run])
            except cd.DiagramFileError as exc:
                failed.append(f"{figure}: {run} unreadable: {exc}")
                continue
            compared += 1
            if not (result.ok() and result.points > 0):
                failed.append(f"{figure}: {run} disagrees with its reference at "
                              f"{result.points} labelled points (rtol {result.rtol:g}, "
                              f"atol {result.atol:g}):\n{result.report()}")
    assert not failed, "\n\n".join(failed)
    assert compared > 0


def test_the_regression_runs_leave_tests_reference_untouched(regressed):
    _, before, after = regressed
    assert before == after, f"changed: {sorted(set(before.items()) ^ set(after.items()))}"
