"""The console's progress lines: an AUTO run's line gives its number and
the total only where one is known (the count of the same figure, or of the
same part, last time), never "?"; a run that stops is worded as a stop,
since its caller may retry or do without it; a part's line counts the
figure's parts.

Run: /usr/bin/python3 -m pytest -q tests/continuation/test_progress_lines.py
"""
import os
import re

import pytest

from mlgshimmy.shared import autoglue, autosession, progress, runerror
from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs import Parts


@pytest.fixture
def counts(tmp_path, monkeypatch):
    """A fresh build/.runs and run root; no part being computed; the AUTO
    of the real build tree."""
    monkeypatch.setenv("AUTO_DIR", autosession.auto_dir())
    monkeypatch.setattr(paths, "BUILD", str(tmp_path / "build"))
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path / "runs"))
    monkeypatch.setenv(paths.PART_ENV, "")   # restored after the test, whatever it sets
    monkeypatch.delenv(paths.PART_ENV)
    return tmp_path


def lines(capsys):
    return capsys.readouterr().out.splitlines()


def test_no_total_the_first_time_then_last_time_s(counts, capsys):
    rundir = os.path.join(paths.run_root(), "fig98")
    first = progress._Progress()
    for name in ("eq", "po", "hb"):
        first.step(rundir, name, 1.0)
    first.save()
    assert [re.sub(r", \d+ s elapsed$", "", line) for line in lines(capsys)] == [
        "fig98: eq done (run 1) in 1.0 s", "fig98: po done (run 2) in 1.0 s",
        "fig98: hb done (run 3) in 1.0 s"]
    second = progress._Progress()
    second.step(rundir, "eq", 0.5)
    assert lines(capsys)[0].startswith("fig98: eq done (1/3) in 0.5 s")


def test_a_part_counts_its_own_runs(counts, monkeypatch, capsys):
    rundir = os.path.join(paths.run_root(), "fig98")
    whole = progress._Progress()
    for name in ("a", "b", "c", "d"):
        whole.step(rundir, name, 1.0)
    whole.save()
    monkeypatch.setenv(paths.PART_ENV, "curves")
    part = progress._Progress()
    part.step(rundir, "a", 1.0)
    assert "(run 1)" in lines(capsys)[-1]   # not 1/4: the whole figure's count
    assert os.path.basename(part.count_file("fig98")) == "fig98.curves.count"


def test_a_stop_is_worded_as_a_stop(counts, capsys):
    rundir = paths.rundir("fig98")
    with pytest.raises(runerror.RunError):
        autoglue.run(rundir, "eq", "no_such_model", e="no_such_model", c="no_such_model")
    out = "\n".join(lines(capsys))
    assert "FAILED" not in out and "fig98: eq stopped by AUTO (see eq.log)" in out, out


def test_a_part_says_how_many_of_the_figure_s_parts_are_cached(counts, capsys):
    parts = Parts("fig98", {"one": lambda: {"x": 1}, "two": lambda: {"x": 2},
                            "three": lambda: {"x": 3}}, "figures")
    parts.compute("two", alone=True)
    parts.compute("one", alone=True)
    out = [line for line in lines(capsys) if "computed in" in line]
    assert re.match(r"fig98: part two computed in \d+ s \(1 of 3 parts cached\)$", out[0]), out
    assert re.match(r"fig98: part one computed in \d+ s \(2 of 3 parts cached\)$", out[1]), out
    assert os.environ[paths.PART_ENV] == "one"
