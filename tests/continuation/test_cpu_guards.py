"""The CPU guards of the AUTO runs that may stall (Fig. 11's FOLD_TIME_LIMIT,
shared.torus's CURVE_TIME_LIMIT, 120 s each) and their one setting,
MLG_CPU_GUARD_SCALE (shared.guards.cpu_guard): the default leaves them as they are,
a factor scales them in every run, a bad value is refused naming the variable."""
import types

import pytest

from mlgshimmy.shared import autoglue, autosession, guards


@pytest.mark.parametrize("text, scale", [(None, 1.0), ("", 1.0), ("2", 2.0), ("2.5", 2.5)])
def test_the_cpu_guard_scale(monkeypatch, text, scale):
    if text is None:
        monkeypatch.delenv("MLG_CPU_GUARD_SCALE", raising=False)
    else:
        monkeypatch.setenv("MLG_CPU_GUARD_SCALE", text)
    assert guards.cpu_guard_scale() == scale
    assert guards.cpu_guard(120) == 120 * scale and guards.cpu_guard(None) is None


@pytest.mark.parametrize("text", ["x", "0", "-1", "inf", "nan", "1e9"])
def test_a_bad_cpu_guard_scale_is_refused_naming_it(monkeypatch, text):
    monkeypatch.setenv("MLG_CPU_GUARD_SCALE", text)
    with pytest.raises(guards.BadSetting, match="MLG_CPU_GUARD_SCALE="):
        guards.cpu_guard_scale()
    with pytest.raises(guards.BadSetting, match="MLG_CPU_GUARD_SCALE="):
        autosession.init()


def test_the_guards_keep_their_values_and_a_run_gets_them_scaled(tmp_path, monkeypatch):
    from mlgshimmy.figures.fig11 import curves
    from mlgshimmy.shared import torus
    assert curves.FOLD_TIME_LIMIT == 120 and torus.CURVE_TIME_LIMIT == 120

    class Stop(Exception):
        pass

    seen = []

    class Recorded:
        def __init__(self, seconds):
            seen.append(seconds)

        def __enter__(self):
            raise Stop

        def __exit__(self, *exc):
            return False

    class Failed(Exception):
        pass

    # AUTO itself is not needed: the guard is set up before AUTO runs
    auto = types.SimpleNamespace(AUTOExceptions=types.SimpleNamespace(AUTORuntimeError=Failed))
    monkeypatch.setattr(autosession, "init", lambda: auto)
    monkeypatch.setattr(guards, "CPULimit", Recorded)
    monkeypatch.setenv("MLG_CPU_GUARD_SCALE", "2.5")
    for limit in (curves.FOLD_TIME_LIMIT, None):
        with pytest.raises(Stop):
            autoglue.run(str(tmp_path / "run"), "x", time_limit=limit)
    assert seen == [300.0, None]
