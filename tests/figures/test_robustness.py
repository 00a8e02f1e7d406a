"""The robustness suite's job list and its sensitivity table
(studies.robustness), without running it: `make robustness` itself is
exercised by tests/figures/test_changed_gear.py's smaller run of fig10.

Run: /usr/bin/python3 -m pytest -q tests/figures/test_robustness.py
"""
import argparse

import pytest

from mlgshimmy.shared import mlgmodel, paths
from mlgshimmy.shared.jobs import grid as jobgrid
from mlgshimmy.studies import robustness


def points(parameters=",".join(robustness.PARAMETERS), factors=robustness.FACTORS):
    return robustness.grid(argparse.Namespace(parameters=parameters, factors=factors))


def test_the_suite_is_every_parameter_at_every_factor_and_the_gear_itself():
    found = points()
    assert found[0] == (robustness.BASELINE, 1.0)
    assert len(found) == 1 + 13 * 4
    names = [robustness.JOBS.name(*p) for p in found]
    assert names[:3] == ["baseline_x1", "k_tlk_x0.8", "k_tlk_x0.9"]
    assert all(robustness.JOBS.parse(n) == p for n, p in zip(names, found))


@pytest.mark.parametrize("parameters, says", [("k_tk", "did you mean k_tlk"),
                                              ("eta_stage", "is not varied by the suite")])
def test_a_parameter_outside_the_suite_is_refused(parameters, says):
    with pytest.raises(ValueError, match=says):
        points(parameters)


def test_a_variation_scales_the_parameter_of_the_figures_set():
    k = robustness.varied("k_tlk", 0.9)
    assert dict(k.overlay) == {"k_tlk": pytest.approx(3.51e7, rel=1e-12)}
    c = robustness.varied("c_psi", 1.2)       # the calibrated 724.0034, not the printed 410
    assert dict(c.overlay)["c_psi"] == pytest.approx(1.2 * mlgmodel.C_PSI_FIGURES, rel=1e-12)
    assert robustness.varied(robustness.BASELINE, 1.0).baseline


def record(parameter, factor, vcrit, kappa, complete=True):
    fig10 = {"V_crit (zero freeplay) [m/s]": vcrit, "H1 [m/s]": 1.458, "H2 [m/s]": 28.31,
             "H3 [m/s]": 144.27, "S1 [m/s]": 41.49}
    return {"parameter": parameter, "factor": factor, "complete": complete,
            "targets": {"fig10": {"status": 0, "complete": True, "numbers": fig10},
                        "fig07": {"status": 0 if complete else 2, "complete": complete,
                                  "numbers": None},
                        "criterion": {"status": 0, "complete": True,
                                      "numbers": {"kappa*": kappa}}}}


def test_the_sensitivity_table(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    results = [record("baseline", 1.0, 346.1, 0.3651),
               record("k_tlk", 0.9, 304.6, 0.3034, complete=False)]
    robustness.summary([("baseline", 1.0), ("k_tlk", 0.9)], results, None)
    text = (tmp_path / "tables" / "robustness.txt").read_text()
    assert text.startswith("robustness: 1 of 2 variations complete with every named point "
                           "(5 of 6 target runs)")
    row = next(line for line in text.splitlines() if line.startswith("k_tlk x0.9"))
    assert "304.6 (-12.0%)" in row and "0.3034 (-16.9%)" in row and "1.458 (+0.0%)" in row
    assert "incomplete: k_tlk x0.9, fig07 (exit 2)" in text
    assert paths.run_root() == str(tmp_path)
