"""An AUTO-07p run, checked (AUTO's session: autosession; run directories:
rundirs; the console and logs: progress; reading a diagram: diagrams).

    from mlgshimmy.shared import autoglue
    bd = autoglue.run(rundir, "eq", constants=path_to_c_file, e=model,
                      expect=["HB"], ICP=["p"])

A run claims its run directory, sends AUTO's output to <rundir>/<name>.log,
prints one console line, and raises RunError (shared.runerror) with the tail
of the log when it fails.
"""
from __future__ import annotations

import os
import re
import time
from typing import Any, Dict, List, Optional, Sequence, Union

from mlgshimmy.shared import autosession, guards, paths
from mlgshimmy.shared.diagrams import BRANCH_ENDS, check_diagram, read_diagram
from mlgshimmy.shared.progress import PROGRESS, LogTo
from mlgshimmy.shared.rundirs import claim
from mlgshimmy.shared.runerror import MX, NON_FINITE, RunError, non_finite_stop


def check_prebuilt(model: str) -> None:
    """Fail unless AUTO's run() would use <model>.exe as it is.

    run() recompiles <model>.o if <model>.c is newer and relinks <model>.exe
    if <model>.o or $AUTO_DIR/lib/*.o is newer; its link line has no room for
    our libraries, so executables built by the Makefile must be up to date.
    """
    # the next step names the make target (build/models/mlg.exe), run from the checkout
    rebuild = f"run `make -C {paths.ROOT} {os.path.relpath(model + '.exe', paths.ROOT)}` " \
        "(the make target of a figure or study rebuilds it too)"

    def mtime(path):
        if not os.path.exists(path):
            raise RunError(f"{path} is missing: {rebuild}")
        return os.stat(path).st_mtime

    libdir = os.path.join(autosession.auto_dir(), "lib")
    auto_objects = [os.path.join(libdir, f) for f in os.listdir(libdir)
                    if f.endswith(".o")]
    exe = mtime(model + ".exe")
    obj = mtime(model + ".o")
    if mtime(model + ".c") > obj or max(map(mtime, auto_objects + [model + ".o"])) > exe:
        raise RunError(f"{model}.exe is out of date (older than {os.path.basename(model)}.c or "
                       f"AUTO's objects): {rebuild}")


def read_constants(paths: Union[str, List[str]]) -> Dict[str, Any]:
    """A constants file, or a list of them: each later file overrides the
    constants it sets (read with AUTO's parseC; unset ones stay as they are)."""
    if isinstance(paths, str):
        paths = [paths]
    auto = autosession.init()
    merged = auto.parseC.parseC(os.path.abspath(paths[0]))
    for path in paths[1:]:
        override = auto.parseC.parseC(os.path.abspath(path))
        for key in override:
            if key != "new" and override[key] is not None:
                merged[key] = override[key]
    return merged


def run(rundir: str, name: str, data: Any = None, constants: Union[None, str, List[str]] = None,
        expect: Sequence[str] = (), allow_mx: bool = False, time_limit: Optional[float] = None,
        **kw: Any) -> Any:
    """Run AUTO in rundir, save to b./s./d.<name> there, and check the result.

    constants: path of a constants file, or a list of files merged in order
    (read_constants), read afresh for this run (every constant they do not
    set takes AUTO's default); kw overrides single
    constants and may give e= (equations name; with a directory part it must
    name an executable prebuilt by the Makefile, see check_prebuilt).
    Raises RunError naming the run if any branch ends in MX or a special point
    type listed in expect (e.g. "HB", "LP", "BP") does not occur.  With
    allow_mx, an MX is no error: the diagram is returned
    (for curves known to end at a hard spot; the caller marks the end);
    its progress line says so.
    time_limit: CPU seconds of the AUTO executable after which it is killed
    and RunError raised (for runs known to stall in AUTO's iterations),
    times MLG_CPU_GUARD_SCALE (guards.cpu_guard).
    rundir is claimed (claim); AUTO's messages go to <rundir>/<name>.log.
    """
    auto = autosession.init()
    rundir = claim(rundir)
    if constants is not None:
        kw["c"] = read_constants(constants)
    if os.sep in kw.get("e", ""):
        kw["e"] = os.path.abspath(kw["e"])
        check_prebuilt(kw["e"])

    outputs = [os.path.join(rundir, f"{kind}.{name}") for kind in "bsd"]
    log = os.path.join(rundir, f"{name}.log")
    started = time.monotonic()
    guard = guards.cpu_guard(time_limit)
    limit = guards.CPULimit(guard)
    cwd = os.getcwd()
    os.chdir(rundir)
    try:
        for stale in ["fort.7", "fort.8", "fort.9"] + outputs:
            if os.path.exists(stale):
                os.remove(stale)
        with limit, LogTo(log):
            auto.run(data, sv=name, **kw)
    except auto.AUTOExceptions.AUTORuntimeError as exc:
        scale = guards.CPU_GUARD_SCALE_ENV
        why = (f"killed by its CPU guard after {guard:g} s of CPU time ({time_limit:g} s x "
               f"{scale}={guards.cpu_guard_scale():g}; raise {scale} on a slow node)"
               if limit.fired else exc)
        stop = None if limit.fired else non_finite_stop(log)
        # a stop, not yet a failure: the caller may retry or do without it,
        # and says so; a failure it cannot take stops the figure, naming it
        word = ("stopped at a non-finite solution" if stop else "stopped by its CPU guard"
                if limit.fired else f"stopped by AUTO (see {name}.log)")
        PROGRESS.step(rundir, name, time.monotonic() - started, word)
        if stop:
            raise RunError(f"run {name} in {rundir}: {stop.removeprefix('mlg: ')}", log,
                           NON_FINITE) from exc
        raise RunError(f"run {name} in {rundir}: AUTO stopped ({why})", log) from exc
    finally:
        os.chdir(cwd)
    missing = [path for path in outputs if not os.path.exists(path)]
    if missing:
        raise RunError(f"run {name} in {rundir}: AUTO wrote no {', '.join(missing)}", log)
    # a run told to STOP at a special point (e.g. "BP1") ends there, unlabelled EP
    stops = tuple(re.sub(r"\d+$", "", str(kind)) for kind in kw.get("STOP", ()))
    bd = read_diagram(outputs, f"run {name} in {rundir}", log, ends=BRANCH_ENDS + stops)

    status = "done"
    try:
        check_diagram(bd, f"run {name} in {rundir}", expect)
    except RunError as exc:
        if not (allow_mx and exc.kind == MX):
            # an MX is the caller's to judge (continuation.with_ladder retries it)
            word = "stops with no convergence (MX)" if exc.kind == MX else \
                "stops: " + exc.brief.split(f"in {rundir}: ", 1)[-1]
            PROGRESS.step(rundir, name, time.monotonic() - started, word)
            raise RunError(exc.brief, log, exc.kind) from None
        status = "done, ends in MX (kept up to there, as allowed)"
    PROGRESS.step(rundir, name, time.monotonic() - started, status)
    return bd
