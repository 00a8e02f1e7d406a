"""Runs that meet keep each other's results: two identical figure requests
make one computation and both succeed; a lock or run directory planted as
a symbolic link is refused, and what it points to is left alone."""
import os
import subprocess
import sys
import time

import pytest

from mlgshimmy.shared import jobs, paths, rundirs, runerror


def make(root, *goals):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    return subprocess.Popen(["make", "--no-print-directory", *goals], cwd=paths.ROOT,
                            env=dict(env, MLG_RUN_ROOT=str(root)), stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)


def test_two_make_fig07_one_computation(tmp_path):
    first = make(tmp_path, "fig07")
    lock = tmp_path / ".locks" / "fig07.lock"
    deadline = time.monotonic() + 60
    while not (lock.exists() and "process" in lock.read_text()) and time.monotonic() < deadline:
        time.sleep(0.05)
    second = make(tmp_path, "fig07")
    out = [p.communicate(timeout=600)[0] for p in (first, second)]
    assert [first.returncode, second.returncode] == [0, 0], out
    both = "".join(out)
    assert both.count("fig07: computed in") == 1, both
    assert both.count("computed meanwhile by another process; using it") == 1, both
    assert all("Hopf at V = 346.100 m/s" in o for o in out)
    assert (tmp_path / "fig07" / "result.json").exists()


def test_a_claim_keeps_the_cached_result(tmp_path, monkeypatch):
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    jobs.write("figY", {"n": 1})
    (tmp_path / "figY" / "b.old").write_text("a run")
    code = (f"from mlgshimmy.shared import rundirs; rundirs.claim({str(tmp_path / 'figY')!r})")
    subprocess.run([sys.executable, "-c", code], check=True, env=dict(os.environ))
    assert sorted(os.listdir(tmp_path / "figY")) == ["result.json"]
    assert jobs.read("figY") == {"n": 1}


def test_a_lock_planted_as_a_symlink_is_refused(tmp_path, monkeypatch):
    victim = tmp_path / "victim"
    victim.write_text("precious\n")
    root = tmp_path / "s"
    root.mkdir()
    os.symlink(victim, root / ".fig07.lock")
    monkeypatch.setenv("MLG_RUN_ROOT", str(root))
    code = f"from mlgshimmy.shared import rundirs; rundirs.claim({str(root / 'fig07')!r})"
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.returncode != 0 and "is a symbolic link" in proc.stderr, proc.stderr
    assert victim.read_text() == "precious\n"


def test_a_run_directory_that_is_a_symlink_is_refused(tmp_path):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "keep.txt").write_text("mine")
    os.symlink(elsewhere, tmp_path / "fig07")
    with pytest.raises(runerror.RunError, match="symbolic link"):
        rundirs.claim(str(tmp_path / "fig07"))
    assert (elsewhere / "keep.txt").read_text() == "mine"
