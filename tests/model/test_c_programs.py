"""The C test programs (tests/c/test_*.c, built by `make test` into
build/tests/) as pytest cases, one per program, named after it, so that
`pytest -k jacobian` selects test_jacobian.c with the Python tests.  A
program prints `ok <check>` / `not ok <check> - <detail>` per check; it
passes when it exits 0, reports at least one check and no `not ok`.
Each runs twice: as built (build/tests/) and built under UBSan
(build/ubsan/tests/, c/c.mk), where undefined behaviour stops it."""
import glob
import os
import subprocess

import pytest

import helpers

ROOT = helpers.ROOT
SOURCES = sorted(glob.glob(os.path.join(ROOT, "tests", "c", "test_*.c")))


@pytest.mark.parametrize("build", ["tests", "ubsan/tests"], ids=["plain", "ubsan"])
@pytest.mark.parametrize("program", [os.path.basename(s)[:-2] for s in SOURCES])
def test_c_program(program, build):
    path = os.path.join(ROOT, "build", build, program)
    if not os.access(path, os.X_OK):
        pytest.fail(f"{path} is not built (make {os.path.relpath(path, ROOT)}, or make test)")
    proc = subprocess.run([path], capture_output=True, text=True, timeout=600,
                          env=dict(os.environ, UBSAN_OPTIONS="print_stacktrace=1"))
    lines = proc.stdout.splitlines()
    failed = [line for line in lines if line.startswith("not ok ")]
    passed = [line for line in lines if line.startswith("ok ")]
    assert not failed, "\n".join(failed)
    assert proc.returncode == 0, f"exit status {proc.returncode}: {proc.stderr[-2000:]}"
    assert passed, f"{program} reported no check"
