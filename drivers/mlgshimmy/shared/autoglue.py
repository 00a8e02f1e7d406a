"""The interface to AUTO-07p's Python package (python/auto of AUTO_DIR).

    from mlgshimmy.shared import autoglue
    bd = autoglue.run(rundir, "eq", constants=path_to_c_file, e=model,
                      expect=["HB"], ICP=["p"])
    auto = autoglue.init()          # AUTO's CLUI module, for interactive use

Importing this module does nothing to the process: init() (called by every
function here that needs AUTO) finds AUTO through AUTO_DIR (default: the
tree the Makefile builds, build/auto/07p), puts its python/ on sys.path,
gives numpy >= 1.24 the `numpy.bool` AUTO 0.9.2 still uses, and sets the
OpenMP thread count of the AUTO runs this process starts to
MLG_AUTO_THREADS (1 unless set: more threads change AUTO's rounding, and a
fold curve of Fig. 11 then stops at a run-dependent point; an inherited
OMP_NUM_THREADS is not used), and has SIGTERM and SIGHUP stop the AUTO
executable with the process (shared.children).  A missing AUTO raises
AutoMissing.

The CPU guards of the runs known to stall (run(time_limit=...): Fig. 11's
FOLD_TIME_LIMIT, shared.torus's CURVE_TIME_LIMIT, 120 s each) are scaled
by MLG_CPU_GUARD_SCALE (cpu_guard(); default 1, so the guards and the
figures stay as they are; 2 or 3 on nodes that are slower per core,
docs/cluster.md), read and checked here only, at init() and at each
guarded run.

Run directories are owned (claim): the first process to use one locks it
for its lifetime and empties it; another process that wants the same
directory waits for it and says so, so two runs never write one directory.
AUTO's own output goes to <rundir>/<name>.log; the console gets one line per
run, and a failed run's RunError carries the tail of its log.
"""
import atexit
import importlib.util
import math
import os
import re
import shutil
import signal
import sys
import time
from typing import Any, Callable, List, Optional, Sequence, Union

import numpy

from mlgshimmy.shared import branches, children, paths
from mlgshimmy.shared.jobs import locks


class AutoMissing(RuntimeError):
    """No usable AUTO-07p tree at AUTO_DIR, or a bad thread count."""


_auto = None


def auto_dir() -> str:
    """AUTO_DIR if set, else the AUTO make was told to use (build/auto-dir,
    mk/auto.mk), else the tree make builds (build/auto/07p)."""
    if os.environ.get("AUTO_DIR"):
        return os.environ["AUTO_DIR"]
    try:
        with open(os.path.join(paths.BUILD, "auto-dir")) as chosen:
            return chosen.read().strip()
    except OSError:
        return os.path.join(paths.BUILD, "auto", "07p")


def threads() -> str:
    """MLG_AUTO_THREADS, checked: the OpenMP threads of each AUTO run."""
    value = os.environ.get("MLG_AUTO_THREADS", "1")
    if not (value.isdigit() and int(value) >= 1):
        raise AutoMissing(f"MLG_AUTO_THREADS={value!r} must be a whole number >= 1")
    return value


CPU_GUARD_SCALE_ENV = "MLG_CPU_GUARD_SCALE"


class BadSetting(ValueError):
    """An environment setting of the runs that is not valid (named)."""


def cpu_guard_scale() -> float:
    """MLG_CPU_GUARD_SCALE, checked: the factor on every CPU guard (1 unless
    set)."""
    text = os.environ.get(CPU_GUARD_SCALE_ENV, "").strip()
    if not text:
        return 1.0
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and 0.1 <= value <= 1000):
        raise BadSetting(f"{CPU_GUARD_SCALE_ENV}={text!r} must be a number from 0.1 to 1000 "
                         "(the factor on the 120 s CPU guards of the AUTO runs that may "
                         "stall; 2 or 3 for slow nodes, docs/cluster.md)")
    return value


def cpu_guard(seconds: Optional[float]) -> Optional[float]:
    """A CPU guard of `seconds` (None: none) times MLG_CPU_GUARD_SCALE."""
    return None if seconds is None else seconds * cpu_guard_scale()


def init():
    """AUTO's Python package, imported once (see the module's text)."""
    global _auto
    cpu_guard_scale()   # a bad value stops the job before its first run, not at a guard
    children.stop_with_this_process()   # a make interrupted leaves no mlg.exe running
    if _auto is None:
        where = auto_dir()
        if not os.path.isdir(os.path.join(where, "python", "auto")):
            raise AutoMissing(f"no AUTO-07p at AUTO_DIR={where} (run `make setup`, or set "
                              "AUTO_DIR to a built AUTO-07p tree)")
        os.environ["AUTO_DIR"] = where    # AUTO's own modules read it
        os.environ["OMP_NUM_THREADS"] = threads()
        if "bool" not in vars(numpy):  # hasattr() would warn on numpy 1.24
            numpy.bool = numpy.bool_  # AUTO 0.9.2's Points.py still uses numpy.bool
        _auto = sys.modules.get("auto") or _import_package("auto", os.path.join(where, "python"))
    return _auto


def _import_package(name: str, parent: str):
    """Import the package <parent>/<name> as `name` (its modules import each
    other as `from auto import ...`), leaving sys.path as it is."""
    directory = os.path.join(parent, name)
    spec = importlib.util.spec_from_file_location(
        name, os.path.join(directory, "__init__.py"), submodule_search_locations=[directory])
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[name]
        raise
    return module


MX, NON_FINITE = "MX", "non-finite"   # RunError.kind of a run that did not converge


class RunError(RuntimeError):
    """An AUTO run that failed, did not converge or missed a special point.
    str() ends with the tail of the run's log; .brief is the first line;
    .kind is MX (a branch ends with no convergence), NON_FINITE (the model
    stopped the run at a non-finite solution, models/mlg.c) or None."""

    def __init__(self, message, log=None, kind=None):
        self.brief = message
        self.kind = kind
        if log:
            message += f"\n  log {log}, last lines:\n" + "".join(
                f"    | {line}" for line in tail(log))
        super().__init__(message)

    @property
    def unconverged(self) -> bool:
        """Whether AUTO's iteration failed (a smaller step or a finer mesh
        may succeed: continuation.with_ladder)."""
        return self.kind in (MX, NON_FINITE)


# the line models/mlg.c writes before it stops a run at a non-finite solution
NON_FINITE_LINE = "mlg: non-finite solution"


def non_finite_stop(log):
    """The model's line saying it stopped the run at a non-finite solution
    (stripped), or None."""
    return next((line.strip() for line in tail(log, 40) if NON_FINITE_LINE in line), None)


def tail(path, lines=15):
    """The last `lines` lines of a text file ([] if it cannot be read)."""
    try:
        with open(path, errors="replace") as f:
            return f.readlines()[-lines:]
    except OSError:
        return []


# Directories this process owns (path -> open lock file, held until exit).
# Child processes inherit the list through the environment: a job started by
# a driver may use a directory under one its parent claimed without waiting
# for its own parent.
_claimed = {}
CLAIMED_ENV = "MLG_RUN_CLAIMED"


def _owned(path):
    inherited = [p for p in os.environ.get(CLAIMED_ENV, "").split(os.pathsep) if p]
    return any(path == p or path.startswith(p + os.sep) for p in list(_claimed) + inherited)


# What a claim keeps when it empties a run directory: the figure's cached
# result and parts (shared.jobs.cache), which readers may be using; each is
# replaced atomically by whoever recomputes it.
CACHE_NAMES = ("result.json", "parts", "parts.mk")


def claim(path: str, keep: Optional[Callable[[str], bool]] = None) -> str:
    """Make the run directory `path` this process's own and return it.

    The first claim takes an exclusive lock (jobs.locks on .<dir>.lock
    beside it, released when the process ends) and empties the directory,
    so that every run in it comes from this process (unless keep(path),
    called under the lock, says its contents are a valid cached result);
    the figure's cache (CACHE_NAMES) is kept.  If another live process
    holds the lock, this waits until it ends, saying so on stderr.  A run
    directory, or its lock, that is a symbolic link is refused (RunError).
    Claims of the same directory, or of one below an owned one, return at
    once."""
    path = os.path.abspath(path)
    if _owned(path):
        os.makedirs(path, exist_ok=True)
        return path
    parent, base = os.path.split(path)
    os.makedirs(parent, exist_ok=True)
    if os.path.islink(path):
        raise RunError(f"{path} is a symbolic link: a run directory must be a directory of "
                       "its own (remove the link, or point MLG_RUN_ROOT elsewhere)")
    waited = time.monotonic()
    try:
        lock = locks.acquire(os.path.join(parent, f".{base}.lock"), locks.say_waiting(
            f"{_label(path)}: {os.path.relpath(path)}"))
    except locks.LockRefused as exc:
        raise RunError(str(exc)) from None
    if time.monotonic() - waited > 1.0:
        print(f"{_label(path)}: {os.path.relpath(path)} free after "
              f"{time.monotonic() - waited:.0f} s; computing its runs afresh",
              file=sys.stderr, flush=True)
    if not (keep and os.path.isdir(path) and keep(path)):
        _empty(path)
    os.makedirs(path, exist_ok=True)
    _claimed[path] = lock
    os.environ[CLAIMED_ENV] = os.pathsep.join(
        [p for p in os.environ.get(CLAIMED_ENV, "").split(os.pathsep) if p] + [path])
    return path


def _empty(path: str) -> None:
    """Remove what is in the run directory but the cache (CACHE_NAMES);
    links inside are removed, never followed."""
    if not os.path.isdir(path):
        return
    for entry in os.scandir(path):
        if entry.name in CACHE_NAMES:
            continue
        if entry.is_dir(follow_symlinks=False):
            shutil.rmtree(entry.path)
        else:
            os.remove(entry.path)


def _label(rundir):
    """The figure a run directory belongs to: its first component below
    RUN_ROOT (its own name elsewhere)."""
    rel = os.path.relpath(os.path.abspath(rundir), paths.run_root())
    return os.path.basename(rundir) if rel.startswith("..") else rel.split(os.sep)[0]


class _Progress:
    """One console line per AUTO run: figure, run, its number and, where
    known, the total: the number of runs the same figure, or the same part
    of it (paths.PART_ENV), made last time under any run root
    (build/.runs/<figure>[.<part>].count); the first time, no total."""

    def __init__(self):
        self.started = time.monotonic()
        self.done = {}

    def count_file(self, figure):
        part = os.environ.get(paths.PART_ENV)
        return os.path.join(paths.BUILD, ".runs", f"{figure}.{part}.count" if part else
                            f"{figure}.count")

    def previous(self, figure):
        try:
            with open(self.count_file(figure)) as f:
                return int(f.read())
        except (OSError, ValueError):
            return None

    def step(self, rundir, name, seconds, status="done"):
        figure = _label(rundir)
        if figure not in self.done:
            self.done[figure] = [0, self.previous(figure)]
        self.done[figure][0] += 1
        done, total = self.done[figure]
        count = f"run {done}" if total is None or total < done else f"{done}/{total}"
        where = os.path.relpath(os.path.join(os.path.abspath(rundir), name),
                                os.path.join(paths.run_root(), figure))
        print(f"{figure}: {where} {status} ({count}) in {seconds:.1f} s, "
              f"{time.monotonic() - self.started:.0f} s elapsed", flush=True)

    def save(self):
        """At exit: remember each figure's run count as next time's total."""
        for figure, (done, _) in self.done.items():
            try:
                os.makedirs(os.path.dirname(self.count_file(figure)), exist_ok=True)
                with open(self.count_file(figure), "w") as f:
                    f.write(f"{done}\n")
            except OSError:
                pass


PROGRESS = _Progress()
atexit.register(PROGRESS.save)


class _LogTo:
    """Send this process's stdout and stderr (its own and AUTO's child
    processes') to a file, at the descriptor level.  A sys.stdout or
    sys.stderr that something replaced (pytest's capture, IPython) writes
    elsewhere than descriptor 1 or 2: it is replaced by one on the
    descriptor meanwhile, so that AUTO's own messages reach the log too."""

    def __init__(self, path):
        self.path = path

    def __enter__(self):
        sys.stdout.flush()
        sys.stderr.flush()
        self.saved = [os.dup(1), os.dup(2)]
        log = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        os.dup2(log, 1)
        os.dup2(log, 2)
        os.close(log)
        self.streams = [sys.stdout, sys.stderr]
        if sys.stdout is not sys.__stdout__:
            sys.stdout = open(1, "w", closefd=False)
        if sys.stderr is not sys.__stderr__:
            sys.stderr = open(2, "w", closefd=False)

    def __exit__(self, *exc):
        sys.stdout.flush()
        sys.stderr.flush()
        for stream, saved in zip((sys.stdout, sys.stderr), self.streams):
            if stream is not saved:
                stream.close()   # the descriptor stays open (closefd=False)
        sys.stdout, sys.stderr = self.streams
        for fd, saved in zip((1, 2), self.saved):
            os.dup2(saved, fd)
            os.close(saved)


def check_prebuilt(model):
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

    libdir = os.path.join(auto_dir(), "lib")
    auto_objects = [os.path.join(libdir, f) for f in os.listdir(libdir)
                    if f.endswith(".o")]
    exe = mtime(model + ".exe")
    obj = mtime(model + ".o")
    if mtime(model + ".c") > obj or max(map(mtime, auto_objects + [model + ".o"])) > exe:
        raise RunError(f"{model}.exe is out of date (older than {os.path.basename(model)}.c or "
                       f"AUTO's objects): {rebuild}")


def special_points(bd):
    """List (branch number, label, type) of every labelled point."""
    return [(branch.BR, label, ty) for branch in bd
            for _, label, ty in branches.labelled_points(branch)]


def read_constants(paths: Union[str, List[str]]):
    """A constants file, or a list of them: each later file overrides the
    constants it sets (read with AUTO's parseC; unset ones stay as they are)."""
    if isinstance(paths, str):
        paths = [paths]
    auto = init()
    merged = auto.parseC.parseC(os.path.abspath(paths[0]))
    for path in paths[1:]:
        override = auto.parseC.parseC(os.path.abspath(path))
        for key in override:
            if key != "new" and override[key] is not None:
                merged[key] = override[key]
    return merged


def _cpu_seconds(pid):
    """CPU time (user + system) a process has used, from /proc/<pid>/stat."""
    with open(f"/proc/{pid}/stat") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


class _CPULimit:
    """While active, kills this process's children (the AUTO executable) once
    one has used `seconds` of CPU time (None: no limit).  A stall guard on
    CPU, not wall, time: a loaded machine must not cut short a run that an
    idle one finishes, or the figure would depend on the load."""

    def __init__(self, seconds):
        self.seconds, self.fired = seconds, False

    def __enter__(self):
        if self.seconds:
            signal.signal(signal.SIGALRM, self._check)
            signal.setitimer(signal.ITIMER_REAL, 1.0, 1.0)
        return self

    def __exit__(self, *exc):
        if self.seconds:
            signal.setitimer(signal.ITIMER_REAL, 0)

    def _check(self, signum, frame):
        for pid in children.of_this_process():
            try:
                if _cpu_seconds(pid) > self.seconds:
                    os.kill(pid, signal.SIGKILL)
                    self.fired = True
            except (OSError, ValueError, IndexError):
                continue


def run(rundir: str, name: str, data=None, constants: Union[None, str, List[str]] = None,
        expect: Sequence[str] = (), allow_mx: bool = False, time_limit: Optional[float] = None,
        **kw: Any):
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
    times MLG_CPU_GUARD_SCALE (cpu_guard).
    rundir is claimed (claim); AUTO's messages go to <rundir>/<name>.log.
    """
    auto = init()
    rundir = claim(rundir)
    if constants is not None:
        kw["c"] = read_constants(constants)
    if os.sep in kw.get("e", ""):
        kw["e"] = os.path.abspath(kw["e"])
        check_prebuilt(kw["e"])

    outputs = [os.path.join(rundir, f"{kind}.{name}") for kind in "bsd"]
    log = os.path.join(rundir, f"{name}.log")
    started = time.monotonic()
    guard = cpu_guard(time_limit)
    limit = _CPULimit(guard)
    cwd = os.getcwd()
    os.chdir(rundir)
    try:
        for stale in ["fort.7", "fort.8", "fort.9"] + outputs:
            if os.path.exists(stale):
                os.remove(stale)
        with limit, _LogTo(log):
            auto.run(data, sv=name, **kw)
    except auto.AUTOExceptions.AUTORuntimeError as exc:
        why = (f"killed by its CPU guard after {guard:g} s of CPU time ({time_limit:g} s x "
               f"{CPU_GUARD_SCALE_ENV}={cpu_guard_scale():g}; raise {CPU_GUARD_SCALE_ENV} "
               "on a slow node)" if limit.fired else exc)
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


# AUTO ends every branch with a labelled point of one of these types (the
# stop it reached, a stop value, or no convergence); a branch whose last
# point is not one was cut short.
BRANCH_ENDS = ("EP", "UZ", "MX")


def read_diagram(outputs, what, log=None, ends=BRANCH_ENDS):
    """The diagram of a run's b-, s- and d-files, its b-file parsed now (AUTO
    reads lazily), checked complete by its content (AUTO ignores write
    errors, so a full disk leaves files cut at any byte): every branch ends
    in a labelled point of a type in `ends` (EP, UZ or MX, and the types the
    run was told to STOP at), the s-file holds a whole solution for every
    label of the b-file, and the b-file's last line is whole.  RunError otherwise
    (saying so when the file system is full)."""
    auto = init()
    try:
        with open(outputs[0], "rb") as f:
            text = f.read()
    except OSError as exc:
        raise RunError(f"{what}: {outputs[0]} unreadable ({exc.strerror})", log) from exc
    if not text.endswith(b"\n"):
        raise RunError(f"{what}: {outputs[0]} is empty or cut short" + _full(outputs[0]), log)
    try:
        bd = auto.bifDiag.bifDiag(*outputs)
        lengths = [len(branch) for branch in bd]
        labels = [lab for branch in bd for _, lab, _ in branches.labelled_points(branch)]
        cut = [branch.BR for branch in bd
               if not any(index == len(branch) - 1 and kind in ends
                          for index, _, kind in branches.labelled_points(branch))]
    except Exception as exc:  # any parser failure means an unreadable file
        raise RunError(f"{what}: {outputs[0]} unreadable ({type(exc).__name__}: {exc})"
                       + _full(outputs[0]), log) from exc
    if not lengths or min(lengths) == 0 or cut:
        raise RunError(f"{what}: {outputs[0]} is empty or cut short"
                       + (f" (branch {cut[0]} has no end point)" if cut else "")
                       + _full(outputs[0]), log)
    saved = solution_labels(outputs[1], what, log)
    if sorted(labels) != sorted(saved):
        raise RunError(f"{what}: {outputs[1]} holds solutions {sorted(saved)}, the b-file "
                       f"labels {sorted(labels)}: cut short" + _full(outputs[1]), log)
    return bd


def solution_labels(path, what, log=None):
    """The labels of an s-file's solutions, each read in full (AUTO's parseS
    reads only the headers, so a solution cut at a line end passed): after
    its header (IBR NTOT ITP LAB NFPR ISW NTPL NAR NROWPR NTST NCOL NPARX)
    NROWPR lines holding NTPL points of NAR values and NPARX parameters,
    and, when NROWPR is more than those take, the direction: NFPR indices,
    NFPR values and NTPL points of NAR - 1 values.  RunError naming the file
    otherwise."""
    try:
        with open(path, "rb") as f:
            lines = f.read().split(b"\n")
    except OSError as exc:
        raise RunError(f"{what}: {path} unreadable ({exc.strerror})", log) from exc
    if lines.pop():
        raise RunError(f"{what}: {path}: its last line is cut short" + _full(path), log)
    labels, at = [], 0
    while at < len(lines):
        try:
            header = [int(word) for word in lines[at].split()]
        except ValueError:
            header = []
        if len(header) not in (12, 16):
            raise RunError(f"{what}: {path}: line {at + 1} is not a solution header: cut "
                           "short or not an s-file" + _full(path), log)
        _, _, _, label, nfpr, _, ntpl, nar, nrowpr, _, _, nparx = header[:12]
        block = lines[at + 1:at + 1 + nrowpr]
        values = len(b" ".join(block).split())
        # the line counts AUTO writes (wrtsp8): 7 values a line, 20 indices
        plain = ((nar - 1) // 7 + 1) * ntpl + (nparx + 6) // 7
        expected = nar * ntpl + nparx + (2 * nfpr + (nar - 1) * ntpl if nrowpr > plain else 0)
        if len(block) != nrowpr or values != expected:
            raise RunError(f"{what}: {path}: solution {label} has {values} values in "
                           f"{len(block)} lines, its header says {expected} in {nrowpr}: "
                           "cut short" + _full(path), log)
        labels.append(label)
        at += 1 + nrowpr
    return labels


def _full(path):
    """' (the file system ... is full)' when it is, else ''."""
    try:
        stat = os.statvfs(os.path.dirname(os.path.abspath(path)))
    except OSError:
        return ""
    return f" (the file system of {os.path.dirname(path)} is full)" if stat.f_bavail == 0 else ""


def check_diagram(bd, what, expect=()):
    """Raise RunError about `what` if a branch of bd holds non-finite values,
    ends in MX, or a special point type listed in expect does not occur."""
    for branch in bd:
        if not numpy.all(numpy.isfinite(branch.coordarray)):
            raise RunError(f"{what}: non-finite values on branch {branch.BR} "
                           "(AUTO continued past a rejected step)", kind=NON_FINITE)
    points = special_points(bd)
    mx = [(br, lab) for br, lab, ty in points if ty == "MX"]
    if mx:
        raise RunError(f"{what}: no convergence (MX) at "
                       + ", ".join(f"branch {br} label {lab}" for br, lab in mx), kind=MX)
    found = {ty for _, _, ty in points}
    missing = [ty for ty in expect if ty not in found]
    if missing:
        raise RunError(f"{what}: expected special points {missing} missing"
                       f" (found {sorted(found)})")
