"""tests/regression/reference_set.py on a full disk (a small tmpfs; needs root
to mount it, skipped otherwise): a new set that does not fit is reported in
one line (exit 2) naming the set and what was full, its partial copy
(.<fig>.new-<pid>/) is removed, no *.part file is left, and an old set is
left byte for byte as it was.

Run with: python3 -m pytest -q tests/regression/test_reference_set_full_disk.py
"""
import os
import shutil
import subprocess
import sys

import pytest

import helpers

ROOT = helpers.ROOT
REFERENCE_SET = os.path.join(ROOT, "tests", "regression", "reference_set.py")
FIG07 = os.path.join(ROOT, "tests", "reference", "fig07")   # 184 kB of files


@pytest.fixture
def small_disk(tmp_path, request):
    """A tmpfs of request.param bytes mounted at tmp_path/disk."""
    if os.geteuid() != 0:
        pytest.skip("mounting a tmpfs needs root")
    mount = tmp_path / "disk"
    mount.mkdir()
    proc = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={request.param}", "tmpfs",
                           str(mount)], capture_output=True, text=True)
    if proc.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs: {proc.stderr.strip()}")
    try:
        yield mount
    finally:
        subprocess.run(["umount", str(mount)], check=True)


def files(directory):
    out = {}
    for parent, _, names in os.walk(directory):
        for name in names:
            path = os.path.join(parent, name)
            with open(path, "rb") as f:
                out[os.path.relpath(path, directory)] = f.read()
    return out


def replace(root):
    proc = subprocess.run([sys.executable, REFERENCE_SET, "replace", "fig07", FIG07,
                           "--root", str(root)], capture_output=True, text=True, timeout=120)
    return proc.returncode, proc.stdout, proc.stderr


def assert_reported_and_clean(status, out, err, root):
    assert status == 2, out + err
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    assert "did not fit" in lines[0] and "No space left on device" in lines[0], err
    assert "partial copy" in lines[0] and "removed" in lines[0], err
    assert "Traceback" not in err
    assert [e for e in os.listdir(root) if e.startswith(".")] == [], os.listdir(root)
    assert [f for f in files(root) if f.endswith(".part") or ".part." in f] == []


@pytest.mark.parametrize("small_disk", ["300k"], indirect=True)
def test_new_set_that_does_not_fit_leaves_the_old_set(small_disk):
    shutil.copytree(FIG07, small_disk / "fig07")
    before = files(small_disk / "fig07")
    status, out, err = replace(small_disk)
    assert_reported_and_clean(status, out, err, small_disk)
    assert "left as it was" in err, err
    assert files(small_disk / "fig07") == before
    assert sorted(os.listdir(small_disk)) == ["fig07"]


@pytest.mark.parametrize("small_disk", ["64k"], indirect=True)
def test_first_set_that_does_not_fit_is_not_created(small_disk):
    status, out, err = replace(small_disk)
    assert_reported_and_clean(status, out, err, small_disk)
    assert "not created" in err, err
    assert os.listdir(small_disk) == []


@pytest.mark.parametrize("small_disk", ["1m"], indirect=True)
def test_a_set_that_fits_is_replaced(small_disk):
    shutil.copytree(FIG07, small_disk / "fig07")
    status, out, err = replace(small_disk)
    assert status == 0, err
    assert "refs: replaced" in out, out
    assert files(small_disk / "fig07") == files(FIG07)
    assert sorted(os.listdir(small_disk)) == ["fig07"]
