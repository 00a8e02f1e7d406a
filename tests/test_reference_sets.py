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

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "regression"))
import compare_diagrams as cd  # noqa: E402
import reference_set as rs  # noqa: E402
from check import check  # noqa: E402

WORK = os.path.join(cd.ROOT, "build", "tests", "reference-sets")
FIGURE = "fig07"
STEPS = ("copying", "manifest", "verified", "exchanged")


def stored_sets():
    for directory in sorted(glob.glob(os.path.join(cd.REFERENCE_ROOT, "*"))):
        try:
            runs = rs.verify(directory)
            check(f"{os.path.basename(directory)}: {len(runs)} runs match its MANIFEST", runs)
        except rs.SetError as exc:
            check(f"{os.path.basename(directory)}: matches its MANIFEST", False, str(exc))


def coverage():
    """REGRESS_FIGURES (exported by tests/regression/regression.mk) and the
    sets in tests/reference/ name the same figures: a set nobody runs, or a
    registered figure without one, is named."""
    registered = set(os.environ.get("REGRESS_FIGURES", "").split())
    if not check("REGRESS_FIGURES names the figures `make regress` runs (set by the Makefile)",
                 registered, "REGRESS_FIGURES is empty or unset: run through `make test`"):
        return
    stored = {os.path.basename(d) for d in glob.glob(os.path.join(cd.REFERENCE_ROOT, "*"))}
    check(f"make regress runs every figure with a reference set ({len(stored)})",
          not stored - registered, f"sets not in REGRESS_FIGURES: {sorted(stored - registered)}")
    check("every figure of REGRESS_FIGURES has a reference set",
          not registered - stored, f"no tests/reference/<fig>/ for {sorted(registered - stored)}")


def copy_set(name):
    path = os.path.join(WORK, name)
    shutil.rmtree(path, ignore_errors=True)
    shutil.copytree(os.path.join(cd.REFERENCE_ROOT, FIGURE), path)
    return path


def error_of(directory):
    try:
        cd.compare_dirs(directory, os.path.join(cd.REFERENCE_ROOT, FIGURE))
    except cd.DiagramFileError as exc:
        return str(exc)
    return "no error"


def manifest_errors():
    runs = rs.verify(os.path.join(cd.REFERENCE_ROOT, FIGURE))
    deleted = copy_set("deleted")
    gone = os.path.join(deleted, f"b.{runs[0]}")
    os.remove(gone)
    message = error_of(deleted)
    check("a deleted reference b-file is an error naming it",
          gone in message and "missing" in message, message)
    extra = copy_set("extra")
    added = os.path.join(extra, "b.stray")
    shutil.copy(os.path.join(extra, f"b.{runs[0]}"), added)
    message = error_of(extra)
    check("an extra file in a set is an error naming it",
          added in message and "extra" in message, message)
    edited = copy_set("edited")
    path = os.path.join(edited, f"b.{runs[-1]}")
    with open(path, "a") as f:
        f.write(" ")
    message = error_of(edited)
    check("an edited reference file is an error naming it",
          path in message and "changed" in message, message)

    ours = copy_set("ours")
    os.makedirs(os.path.join(ours, "sub"))
    shutil.copy(os.path.join(ours, f"b.{runs[0]}"), os.path.join(ours, "sub", "b.new"))
    result = cd.compare_dirs(os.path.join(cd.REFERENCE_ROOT, FIGURE), ours)
    check("a run the figure writes (sub/b.new) without a reference is reported",
          any(p.startswith("sub/new:") for p in result.problems), result.report())


def new_run():
    """A run directory that differs from the fig07 set in one b-file."""
    run = os.path.join(WORK, "run")
    shutil.rmtree(run, ignore_errors=True)
    os.makedirs(run)
    for path in glob.glob(os.path.join(cd.REFERENCE_ROOT, FIGURE, "b.*")):
        shutil.copy(path, run)
    os.makedirs(os.path.join(run, "zero"))
    shutil.copy(os.path.join(run, "b.eq_F1"), os.path.join(run, "zero", "b.eq"))
    return run


def state(root):
    """"old", "new" or what is wrong with root/FIGURE."""
    directory = os.path.join(root, FIGURE)
    try:
        runs = rs.verify(directory)
    except rs.SetError as exc:
        return f"broken: {exc}"
    return {tuple(sorted(OLD_RUNS)): "old", tuple(sorted(OLD_RUNS + ["zero/eq"])): "new"}.get(
        tuple(runs), f"neither: {runs}")


def replace(root, run, kill_at=None):
    env = dict(os.environ)
    if kill_at:
        env["MLG_REFS_KILL_AT"] = kill_at
    return subprocess.Popen([sys.executable, os.path.join(HERE, "regression",
                                                          "reference_set.py"),
                             "replace", FIGURE, run, "--root", root], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def fresh_root(name):
    root = os.path.join(WORK, name)
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    shutil.copytree(os.path.join(cd.REFERENCE_ROOT, FIGURE), os.path.join(root, FIGURE))
    return root


def interrupts():
    run = new_run()
    for step in STEPS:
        root = fresh_root(f"kill-{step}")
        proc = replace(root, run, step)
        out, _ = proc.communicate(timeout=120)
        expected = "new" if step == "exchanged" else "old"
        check(f"replace killed at '{step}': the {expected} set, complete",
              proc.returncode == -signal.SIGKILL and state(root) == expected,
              f"status {proc.returncode}, {state(root)}; {out[-300:]}")
    leftovers = glob.glob(os.path.join(WORK, "kill-*", ".*"))
    root = os.path.join(WORK, "kill-copying")
    proc = replace(root, run)
    out, _ = proc.communicate(timeout=120)
    check("a later replace succeeds and removes what a killed one left",
          leftovers and proc.returncode == 0 and state(root) == "new"
          and not glob.glob(os.path.join(root, ".*")), f"{leftovers}; {out[-300:]}")
    for delay in (0.3, 0.6, 0.9, 1.2):
        root = fresh_root(f"delay-{delay}")
        proc = replace(root, run)
        time.sleep(delay)
        proc.kill()
        proc.communicate()
        check(f"replace killed after {delay} s: the old or the new set, complete",
              state(root) in ("old", "new"), state(root))


def selection():
    root = fresh_root("selection")
    with open(os.path.join(root, FIGURE, rs.SELECTION), "w") as f:
        f.write('{"store": ["eq_*"], "reason": "test: the equilibria only"}\n')
    run = new_run()
    proc = replace(root, run)
    out, _ = proc.communicate(timeout=120)
    runs = rs.verify(os.path.join(root, FIGURE)) if proc.returncode == 0 else []
    check("runs.json: replace stores only the runs it selects (eq_*)",
          runs == ["eq_F0.2", "eq_F1"], f"{runs}; {out[-300:]}")
    result = cd.compare_dirs(os.path.join(root, FIGURE), run)
    check("... and the comparator asks no reference of the others",
          result.ok() and result.points > 0, result.report())


def main():
    global OLD_RUNS
    os.makedirs(WORK, exist_ok=True)
    stored_sets()
    coverage()
    OLD_RUNS = rs.verify(os.path.join(cd.REFERENCE_ROOT, FIGURE))
    manifest_errors()
    interrupts()
    selection()


OLD_RUNS = []

if __name__ == "__main__":
    main()
