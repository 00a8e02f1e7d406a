"""Paths with spaces are refused up front by the top-level Makefile, with one
clear error line naming the path (make splits targets and prerequisites on
spaces; before, such a path gave ~15 "overriding recipe" warnings and "No
rule to make target ..."):

- `MLG_RUN_ROOT="build/x y" make -n fig07` (and the other path settings:
  AUTO_DIR, AUTO_SRC, REGRESS_ROOT, REFS_ROOT);
- `make -n fig07` in a clone whose path has a space.

Run with: python3 -m pytest -q tests/jobs/test_make_paths.py
"""
import os
import shutil
import subprocess

import pytest

import helpers

ROOT = helpers.ROOT


def make(*args, cwd=ROOT, env=None):
    environment = {k: v for k, v in os.environ.items()
                   if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MLG_RUN_ROOT")}
    environment.update(env or {})
    proc = subprocess.run(["make", "--no-print-directory", *args], cwd=cwd, capture_output=True,
                          text=True, env=environment, timeout=120)
    return proc.returncode, proc.stdout, proc.stderr


def assert_refused(status, out, err, path):
    assert status != 0, err
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err               # one line, no warnings before it
    assert "space" in lines[0] and f"'{path}'" in lines[0], err
    assert "overriding recipe" not in err and "No rule" not in err
    assert out == "", out                     # nothing run, not even echoed (-n)


def test_run_root_with_a_space_is_refused():
    status, out, err = make("-n", "fig07", env={"MLG_RUN_ROOT": "build/x y"})
    assert_refused(status, out, err, "build/x y")
    assert "MLG_RUN_ROOT" in err


@pytest.mark.parametrize("variable", ["AUTO_DIR", "AUTO_SRC", "REGRESS_ROOT", "REFS_ROOT"])
def test_other_path_settings_with_a_space_are_refused(variable):
    status, out, err = make("-n", "fig07", f"{variable}=/tmp/a b")
    assert_refused(status, out, err, "/tmp/a b")
    assert variable in err


def test_clone_under_a_directory_with_a_space_is_refused(tmp_path):
    parent = tmp_path / "with space"
    parent.mkdir()
    clone = parent / "mlg-shimmy"
    # a copy of this working tree (its makefiles as they are now), without build/
    shutil.copytree(ROOT, clone, ignore=shutil.ignore_patterns("build", ".git"))
    status, out, err = make("-n", "fig07", cwd=clone)
    assert_refused(status, out, err, str(clone))
    shutil.rmtree(clone)


def test_paths_without_spaces_still_work():
    status, out, err = make("-n", "fig07", env={"MLG_RUN_ROOT": "build/x_y"})
    assert status == 0, err
    assert "mlgshimmy.figures.fig07" in out, out
