"""AUTO_THREADS is checked by make itself (Makefile), never by a shell: a
value that would have run a command inside the old `$(shell [[ "..." =~ ]])`
check is refused naming it, and runs nothing, even with `make -n`; whole
numbers >= 1 pass, anything else is refused in one line.

Run with: python3 -m pytest -q tests/jobs/test_make_auto_threads.py
"""
import os
import subprocess

import pytest

import helpers

ROOT = helpers.ROOT


def make_n(value):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    proc = subprocess.run(["make", "--no-print-directory", "-n", "fig07", f"AUTO_THREADS={value}"],
                          cwd=ROOT, capture_output=True, text=True, env=env, timeout=120)
    return proc.returncode, proc.stderr


def test_a_value_with_shell_code_runs_nothing(tmp_path):
    planted = tmp_path / "pwned"
    value = f'1" ]] ; touch {planted}; [[ "1'
    status, err = make_n(value)
    assert not planted.exists()
    assert status != 0 and f"AUTO_THREADS='{value}'" in err, err


@pytest.mark.parametrize("value", ["1", "2", "16"])
def test_whole_numbers_pass(value):
    status, err = make_n(value)
    assert status == 0, err


@pytest.mark.parametrize("value", ["0", "01", "-1", "two", "1 2", "", "1.5", "1;2"])
def test_other_values_are_refused(value):
    status, err = make_n(value)
    assert status != 0
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and f"AUTO_THREADS='{value}' must be a whole number" in lines[0], err
