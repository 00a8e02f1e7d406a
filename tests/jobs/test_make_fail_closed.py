"""Shell recipes of the top-level makefiles fail closed:

- `make regress-<fig>` and `make refs-<fig>` stop with mkdir's or mktemp's own
  message when their scratch directory cannot be made (REGRESS_ROOT/REFS_ROOT
  under a regular file; an existing but read-only directory: `chattr +i` as
  root, `chmod a-w` otherwise), instead of going on with an empty $scratch:
  no comparison of `/<fig>`, no publish or move of `/figures/*`, no
  `reference_set.py replace` of `/<fig>`; tests/reference/ untouched;
- every recipe line of Makefile, tests/regression/regression.mk, c/c.mk,
  c/simulate/simulate.mk, models/models.mk and mk/**/*.mk that runs more than
  one shell command starts with `set -e` (a static check of the files).

Run with: python3 -m pytest -q tests/jobs/test_make_fail_closed.py
(after `make setup`: the regress/refs targets need its stamps)
"""
import contextlib
import glob
import os
import re
import shutil
import subprocess

import pytest

import helpers

ROOT = helpers.ROOT
REFERENCE = os.path.join(ROOT, "tests", "reference", "fig07")
MAKEFILES = ["Makefile", "tests/regression/regression.mk", "c/c.mk", "c/simulate/simulate.mk",
             "models/models.mk"] + sorted(
    os.path.relpath(p, ROOT) for p in glob.glob(os.path.join(ROOT, "mk", "**", "*.mk"),
                                                recursive=True))


def make(*args):
    proc = subprocess.run(["make", "--no-print-directory", "-C", ROOT, *args],
                          capture_output=True, text=True, timeout=120,
                          env={k: v for k, v in os.environ.items()
                               if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")})
    return proc.returncode, proc.stdout + proc.stderr


def snapshot(directory):
    out = {}
    for parent, _, files in os.walk(directory):
        for name in files:
            path = os.path.join(parent, name)
            with open(path, "rb") as f:
                out[path] = f.read()
    return out


@contextlib.contextmanager
def read_only_directory(path):
    """An existing directory nobody (root included) can create entries in."""
    os.makedirs(path, exist_ok=True)
    if os.geteuid() == 0:
        if subprocess.run(["chattr", "+i", path], capture_output=True).returncode != 0:
            pytest.skip(f"chattr +i not supported on {path}")
        try:
            yield path
        finally:
            subprocess.run(["chattr", "-i", path], check=True)
    else:
        os.chmod(path, 0o555)
        try:
            yield path
        finally:
            os.chmod(path, 0o755)


def assert_stopped(status, out, message):
    assert status != 0, out
    assert message in out, out
    assert "compare:" not in out, out           # nothing compared
    assert "refs:" not in out, out              # nothing published or replaced
    assert "runs in \n" not in out and not out.rstrip().endswith("runs in"), out
    assert "'/fig07'" not in out and " /fig07" not in out, out  # no empty $scratch used


@pytest.fixture
def work():
    # under build/ (same file system as the tree: chattr works there)
    path = os.path.join(ROOT, "build", "tests", "make-fail-closed")
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    yield path
    shutil.rmtree(path, ignore_errors=True)


@pytest.mark.parametrize("target,variable", [("regress-fig07", "REGRESS_ROOT"),
                                             ("refs-fig07", "REFS_ROOT")])
def test_mkdir_failure_stops_with_its_message(work, target, variable):
    blocker = os.path.join(work, "a-file")
    open(blocker, "w").close()
    before = snapshot(REFERENCE)
    status, out = make(target, f"{variable}={blocker}/sub")
    assert_stopped(status, out, "mkdir: cannot create directory")
    assert "Not a directory" in out, out
    assert snapshot(REFERENCE) == before


@pytest.mark.parametrize("target,variable", [("regress-fig07", "REGRESS_ROOT"),
                                             ("refs-fig07", "REFS_ROOT")])
def test_mktemp_failure_stops_with_its_message(work, target, variable):
    before = snapshot(REFERENCE)
    with read_only_directory(os.path.join(work, "read-only")) as root:
        status, out = make(target, f"{variable}={root}")
        assert os.listdir(root) == []
    assert_stopped(status, out, "mktemp: failed to create directory")
    assert snapshot(REFERENCE) == before


def recipe_commands(path):
    """(line number, text) of each recipe command of a makefile, continuation
    lines joined; the recipes of define blocks included."""
    with open(os.path.join(ROOT, path)) as f:
        lines = f.read().split("\n")
    out, n = [], 0
    while n < len(lines):
        line = lines[n]
        start = n
        if line.startswith("\t"):
            text = line
            while text.endswith("\\") and n + 1 < len(lines):
                n += 1
                text = text[:-1] + " " + lines[n].strip()
            out.append((start + 1, text.strip()))
        n += 1
    return out


def several_commands(text):
    """True if a recipe command runs more than one shell command (outside
    quotes: ;, &&, ||, a pipe or a for/while/if block)."""
    bare = re.sub(r"'[^']*'|\"(\\.|[^\"\\])*\"", "''", text)
    bare = re.sub(r"\$\([a-z-]+\b", "$(", bare)  # make functions: $(if ...), $(call ...)
    return bool(re.search(r";|&&|\|\||(^|[^|])\|([^|]|$)|\b(for|while|if)\b", bare))


@pytest.mark.parametrize("path", MAKEFILES)
def test_multi_command_recipes_set_e(path):
    missing = [(number, text) for number, text in recipe_commands(path)
               if several_commands(text) and not re.match(r"^[@+-]*set -e", text)]
    assert not missing, "\n".join(f"{path}:{number}: {text[:100]}" for number, text in missing)
