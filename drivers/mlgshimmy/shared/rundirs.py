"""Run directories are owned (claim): the first process to use one locks it
for its lifetime and empties it; another process that wants the same
directory waits for it and says so, so two runs never write one directory."""
from __future__ import annotations

import os
import shutil
import sys
import time
from typing import Callable, Optional

from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs import locks
from mlgshimmy.shared.runerror import RunError

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
            f"{figure_of(path)}: {os.path.relpath(path)}"))
    except locks.LockRefused as exc:
        raise RunError(str(exc)) from None
    if time.monotonic() - waited > 1.0:
        print(f"{figure_of(path)}: {os.path.relpath(path)} free after "
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


def figure_of(rundir: str) -> str:
    """The figure a run directory belongs to: its first component below
    RUN_ROOT (its own name elsewhere)."""
    rel = os.path.relpath(os.path.abspath(rundir), paths.run_root())
    return os.path.basename(rundir) if rel.startswith("..") else rel.split(os.sep)[0]
