"""Each cached part records what computing it cost, its children's CPU
included (AUTO and the simulator run as child processes), and `make
profile-<fig>` lists the parts most CPU first."""
import os
import subprocess
import sys

import pytest

from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs import cache, costs

SPIN = "import time\nt = time.process_time()\nwhile time.process_time() - t < {}: pass\n"


def spend(seconds):
    """Burn `seconds` of CPU in a child process, as an AUTO run does."""
    subprocess.run([sys.executable, "-c", SPIN.format(seconds)], check=True)
    return {"x": seconds}


def test_a_part_records_its_childrens_cpu(tmp_path, monkeypatch):
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    assert cache.compute_once("figZ", lambda: spend(0.6), part="slow")
    assert cache.compute_once("figZ", lambda: spend(0.1), part="quick")
    found = {c["part"]: c for c in costs.costs("figZ")}
    assert set(found) == {"slow", "quick"}
    # the child's 0.6 s, plus the interpreter's start (< 0.5 s on a loaded machine)
    assert 0.6 <= found["slow"]["cpu_seconds"] < 1.1, found
    assert 0.1 <= found["quick"]["cpu_seconds"] < 0.6, found
    assert found["slow"]["wall_seconds"] >= found["slow"]["cpu_seconds"] - 0.05, found
    assert [c["part"] for c in costs.costs("figZ")] == ["slow", "quick"]
    assert cache.read("figZ", "slow") == {"x": 0.6}    # the cost is no part of the checked data


def test_the_table_says_what_it_does_not_know(tmp_path, monkeypatch):
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    cache.write("figZ", {"x": 1}, part="old")           # written before costs were kept
    cache.write("figZ", {"x": 2}, part="new", cost={"wall_seconds": 9.0, "cpu_seconds": 7.5})
    text = costs.table(costs.costs("figZ"))
    assert text.splitlines()[1].split() == ["new", "8", "9"], text
    assert "all 2 parts        " in text and "(1 computed before costs were kept)" in text, text


def run_profile(figure, root):
    env = dict(os.environ, MLG_RUN_ROOT=str(root), PYTHONPATH=os.path.join(paths.ROOT, "drivers"))
    return subprocess.run([sys.executable, "-m", "mlgshimmy.shared.jobs.costs", figure],
                          capture_output=True, text=True, env=env)


def test_a_misspelt_figure_is_named(tmp_path):
    proc = run_profile("fig11x", tmp_path)
    assert proc.returncode == 2 and "no figure 'fig11x'; did you mean fig11?" in proc.stderr, proc


def test_a_figure_not_computed_says_what_to_run(tmp_path):
    proc = run_profile("fig13", tmp_path)
    assert proc.returncode == 1 and "(run `make fig13`" in proc.stderr, proc
