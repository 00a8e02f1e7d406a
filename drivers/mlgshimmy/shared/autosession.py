"""The AUTO-07p session of this process: which AUTO (AUTO_DIR), how many
threads, and AUTO's Python package imported once.

    auto = autosession.init()       # AUTO's CLUI module

Importing this module does nothing to the process: init() finds AUTO through
AUTO_DIR (default: the tree the Makefile builds, build/auto/07p), puts its
python/ on sys.path, gives numpy >= 1.24 the `numpy.bool` AUTO 0.9.2 still
uses, sets the OpenMP thread count of the AUTO runs this process starts to
MLG_AUTO_THREADS (1 unless set: more threads change AUTO's rounding, and a
fold curve of Fig. 11 then stops at a run-dependent point; an inherited
OMP_NUM_THREADS is not used), and has SIGTERM and SIGHUP stop the AUTO
executable with the process (shared.children).  A missing AUTO raises
AutoMissing.  The lowest floor of the AUTO side: it imports only paths,
children and guards, so the cache can ask auto_dir() without AUTO.
"""
from __future__ import annotations

import importlib.util
import os
import sys
from typing import Any

import numpy

from mlgshimmy.shared import children, guards, paths


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


def init() -> Any:
    """AUTO's Python package, imported once (see the module's text)."""
    global _auto
    guards.cpu_guard_scale()   # a bad value stops the job before its first run, not at a guard
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
