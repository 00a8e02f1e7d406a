"""Shared glue between the figure drivers and AUTO-07p's Python interface.

    import autoglue
    bd = autoglue.run(rundir, "eq", constants=path_to_c_file, e=model,
                      expect=["HB"], ICP=["p"])

AUTO_DIR comes from the environment (the Makefile exports it), else the tree
the Makefile builds, build/auto/07p. Importing this module makes the `auto`
package importable and usable with numpy >= 1.24.
"""
import os
import signal
import sys

import numpy

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build")
# Run directories and figures go under MLG_RUN_ROOT (default build/); `make
# regress` points it at build/regress/ so that build/<fig>/ stays as it was.
RUN_ROOT = os.path.abspath(os.environ.get("MLG_RUN_ROOT", BUILD))
FIGURES_DIR = os.path.join(RUN_ROOT, "figures")
AUTO_DIR = os.environ.get("AUTO_DIR", os.path.join(BUILD, "auto", "07p"))

if not os.path.isdir(os.path.join(AUTO_DIR, "python", "auto")):
    sys.exit(f"autoglue: no AUTO-07p at AUTO_DIR={AUTO_DIR} (run `make setup`)")
os.environ["AUTO_DIR"] = AUTO_DIR
sys.path.insert(0, os.path.join(AUTO_DIR, "python"))
if "bool" not in vars(numpy):  # hasattr() would warn on numpy 1.24
    numpy.bool = numpy.bool_  # AUTO 0.9.2's Points.py still uses numpy.bool

import auto  # noqa: E402


class RunError(RuntimeError):
    """An AUTO run that failed, did not converge or missed a special point."""


def check_prebuilt(model):
    """Fail unless AUTO's run() would use <model>.exe as it is.

    run() recompiles <model>.o if <model>.c is newer and relinks <model>.exe
    if <model>.o or $AUTO_DIR/lib/*.o is newer; its link line has no room for
    our libraries, so executables built by the Makefile must be up to date.
    """
    def mtime(path):
        if not os.path.exists(path):
            raise RunError(f"{path} is missing: build it with make")
        return os.stat(path).st_mtime

    libdir = os.path.join(AUTO_DIR, "lib")
    auto_objects = [os.path.join(libdir, f) for f in os.listdir(libdir)
                    if f.endswith(".o")]
    exe = mtime(model + ".exe")
    obj = mtime(model + ".o")
    if mtime(model + ".c") > obj or max(map(mtime, auto_objects + [model + ".o"])) > exe:
        raise RunError(f"{model}.exe is out of date: rebuild it with make")


def special_points(bd):
    """List (branch number, label, type) of every labelled point."""
    points = []
    for branch in bd:
        for index in branch.labels.getIndices():
            for ty, info in list(branch.labels[index].items()):
                if "LAB" in info:  # skip {"No Label": {"stab": ...}} entries
                    points.append((branch.BR, info["LAB"], ty))
    return points


def read_constants(paths):
    """A constants file, or a list of them: each later file overrides the
    constants it sets (read with AUTO's parseC; unset ones stay as they are)."""
    if isinstance(paths, str):
        paths = [paths]
    merged = auto.parseC.parseC(os.path.abspath(paths[0]))
    for path in paths[1:]:
        override = auto.parseC.parseC(os.path.abspath(path))
        for key in override:
            if key != "new" and override[key] is not None:
                merged[key] = override[key]
    return merged


def _kill_children(signum, frame):
    """SIGALRM handler of run(time_limit=...): kill this process's children
    (the AUTO executable); AUTO's run() then raises."""
    for entry in os.listdir("/proc"):
        try:
            with open(f"/proc/{entry}/stat") as stat:
                parent = int(stat.read().rsplit(")", 1)[1].split()[1])
        except (OSError, ValueError, IndexError):
            continue
        if parent == os.getpid():
            os.kill(int(entry), signal.SIGKILL)


def run(rundir, name, data=None, constants=None, expect=(), allow_mx=False, time_limit=None,
        **kw):
    """Run AUTO in rundir, save to b./s./d.<name> there, and check the result.

    constants: path of a constants file, or a list of files merged in order
    (read_constants), read afresh for this run (every constant they do not
    set takes AUTO's default); kw overrides single
    constants and may give e= (equations name; with a directory part it must
    name an executable prebuilt by the Makefile, see check_prebuilt).
    Raises RunError naming the run if any branch ends in MX or a special point
    type listed in expect (e.g. "HB", "LP", "BP") does not occur.  With
    allow_mx, an MX is reported on stdout instead and the diagram returned
    (for curves known to end at a hard spot; the caller marks the end).
    time_limit: seconds after which the AUTO executable is killed and
    RunError raised (for runs known to stall in AUTO's iterations).
    """
    os.makedirs(rundir, exist_ok=True)
    if constants is not None:
        kw["c"] = read_constants(constants)
    if os.sep in kw.get("e", ""):
        kw["e"] = os.path.abspath(kw["e"])
        check_prebuilt(kw["e"])

    outputs = [os.path.join(rundir, f"{kind}.{name}") for kind in "bsd"]
    cwd = os.getcwd()
    os.chdir(rundir)
    try:
        for stale in ["fort.7", "fort.8", "fort.9"] + outputs:
            if os.path.exists(stale):
                os.remove(stale)
        if time_limit:
            signal.signal(signal.SIGALRM, _kill_children)
            signal.alarm(int(time_limit))
        auto.run(data, sv=name, **kw)
    except auto.AUTOExceptions.AUTORuntimeError as exc:
        timed_out = time_limit and signal.alarm(0) == 0
        why = f"killed after the time limit of {time_limit} s" if timed_out else exc
        raise RunError(f"run {name} in {rundir}: AUTO stopped ({why}); "
                       "see the messages above") from exc
    finally:
        if time_limit:
            signal.alarm(0)
        os.chdir(cwd)
    if not all(map(os.path.exists, outputs)):
        raise RunError(f"run {name} in {rundir}: AUTO wrote no output")
    # The diagram run() returns reads its files lazily, by relative path.
    bd = auto.bifDiag.bifDiag(*outputs)

    try:
        check_diagram(bd, f"run {name} in {rundir}", expect)
    except RunError as exc:
        if not (allow_mx and "(MX)" in str(exc)):
            raise
        print(f"REPORTED: {exc}; the branch ends there")
    return bd


def check_diagram(bd, what, expect=()):
    """Raise RunError about `what` if a branch of bd holds non-finite values,
    ends in MX, or a special point type listed in expect does not occur."""
    for branch in bd:
        if not numpy.all(numpy.isfinite(branch.coordarray)):
            raise RunError(f"{what}: non-finite values on branch {branch.BR} "
                           "(AUTO continued past a rejected step)")
    points = special_points(bd)
    mx = [(br, lab) for br, lab, ty in points if ty == "MX"]
    if mx:
        raise RunError(f"{what}: no convergence (MX) at "
                       + ", ".join(f"branch {br} label {lab}" for br, lab in mx))
    found = {ty for _, _, ty in points}
    missing = [ty for ty in expect if ty not in found]
    if missing:
        raise RunError(f"{what}: expected special points {missing} missing"
                       f" (found {sorted(found)})")
