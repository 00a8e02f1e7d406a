"""No make variable reaches a shell unquoted: an injection in a grid or a
geometry value runs nothing, even in a dry run, and no $(shell ...) of the
makefiles holds a variable outside shell_quote."""
import glob
import os
import re
import subprocess

import pytest

import helpers

ROOT = helpers.ROOT
MAKEFILES = [os.path.join(ROOT, "Makefile")] + sorted(
    glob.glob(os.path.join(ROOT, "mk", "**", "*.mk"), recursive=True)
    + glob.glob(os.path.join(ROOT, "c", "**", "*.mk"), recursive=True)
    + glob.glob(os.path.join(ROOT, "models", "*.mk"))
    + glob.glob(os.path.join(ROOT, "tests", "regression", "*.mk")))


def balanced(text, start):
    """The end of the parenthesised group opening at text[start] == '('."""
    depth = 0
    for k in range(start, len(text)):
        depth += {"(": 1, ")": -1}.get(text[k], 0)
        if depth == 0:
            return k + 1
    return len(text)


def unquoted_in_shell(text):
    """Names of make variables inside $(shell ...) that no shell_quote wraps
    ($(1), $(2): a macro's own arguments, quoted where it is called)."""
    found = []
    for match in re.finditer(r"\$\$?\(shell[ \t\\]", text):
        opening = match.start() + text[match.start():].index("(")
        body = text[opening + len("(shell"):balanced(text, opening) - 1]
        while "call shell_quote," in body:
            k = body.index("$(call shell_quote,")
            body = body[:k] + body[balanced(body, k + 1):]
        found += [name for name in re.findall(r"\$\$?\(([A-Za-z_][A-Za-z0-9_]*)\)", body)]
    return found


@pytest.mark.parametrize("path", MAKEFILES, ids=lambda p: os.path.relpath(p, ROOT))
def test_no_variable_reaches_shell_unquoted(path):
    with open(path) as f:
        assert unquoted_in_shell(f.read()) == []


def test_the_checker_finds_an_unquoted_variable():
    assert unquoted_in_shell("X := $(shell echo $(SWEEP_RHO))") == ["SWEEP_RHO"]
    assert unquoted_in_shell("X := $(shell echo $(call shell_quote,$(SWEEP_RHO)))") == []


@pytest.mark.parametrize("goal, variables", [
    ("sweep", ["SWEEP_RHO=1;touch {mark};", "SWEEP_MU=0"]),
    ("sweep", ["SWEEP_RHO=0", "SWEEP_MU=$(touch {mark})"]),
    ("atlas", ["ATLAS_V=1';touch {mark};'", "ATLAS_FSTAR=1"]),
])
@pytest.mark.parametrize("dry", [True, False])
def test_an_injection_runs_nothing(tmp_path, goal, variables, dry):
    mark = tmp_path / "pwned"
    args = [v.format(mark=mark) for v in variables]
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    proc = subprocess.run(["make", "--no-print-directory", *(["-n"] if dry else []), goal, *args],
                          cwd=ROOT, capture_output=True, text=True,
                          env=dict(env, MLG_RUN_ROOT=str(tmp_path / "root")), timeout=300)
    assert not mark.exists(), proc.stdout + proc.stderr
    assert proc.returncode != 0 and "is not a number" in proc.stderr


def test_a_geometry_injection_runs_nothing(tmp_path):
    mark = tmp_path / "pwned"
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    proc = subprocess.run(["make", "--no-print-directory", "sidestay", f"RHO=1;touch {mark};",
                           "MU=0"], cwd=ROOT, capture_output=True, text=True, timeout=300,
                          env=dict(env, MLG_RUN_ROOT=str(tmp_path / "root")))
    assert not mark.exists() and proc.returncode != 0, proc.stdout + proc.stderr
