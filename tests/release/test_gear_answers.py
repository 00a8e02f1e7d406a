"""make gear's page (shared.gear_answers through mlgshimmy.report): at a
changed gear the report opens with the design answers read from the
cached Figs. 10 and 18, the paper's gear beside each; a vanished Hopf
point and a figure not made say so."""

import math
import re

import pytest

from mlgshimmy import report
from mlgshimmy.shared import gear, gear_answers, geometry, jobs
from mlgshimmy.shared.stage_switch import stage_switch_window

FIG10 = {"numbers": {"V_crit (zero freeplay) [m/s]": 346.1, "S1 [m/s]": 41.49},
         "hopf_points": [
             {"name": "H1", "V": 1.458, "freq_hz": 1.71, "band": "low", "dof": "torsional",
              "loses": True, "criticality": "supercritical"},
             {"name": "H3", "V": 144.27, "freq_hz": 13.09, "band": "high", "dof": "lateral",
              "loses": True, "criticality": "subcritical"}]}
FIG18 = {"kappa_star": 0.365, "numbers": {"kappa*: at F*": 0.1, "kappa*: at V [m/s]": 120.0}}


def test_answers_from_the_two_figures():
    found = gear_answers.answers(FIG10, FIG18)
    assert found["critical_V"] == 346.1 and found["bistable"] == (41.49, 144.27)
    assert found["allowed_mm"] == pytest.approx(0.0365, rel=1e-12)
    assert sorted(found["hopf"]) == ["H1", "H3"]
    # no fold below H3: no bistable band; nothing made: nothing known
    assert gear_answers.answers({**FIG10, "numbers": {"S1 [m/s]": 150.0}}, None)["bistable"] \
        is None
    assert gear_answers.answers(None, None)["made"] is False


@pytest.fixture
def roots(tmp_path, monkeypatch):
    """A base run root with the paper's gear's figures, and a geometry's
    tree with its own Fig. 10 (H1 vanished) and no Fig. 18."""
    base = tmp_path / "build"
    tree = base / "geometry" / "rho20_mu5_eom2"
    at = gear.Gear(geometry.Geometry(20, 5, 2))
    monkeypatch.setenv("MLG_RUN_ROOT", str(base))
    monkeypatch.setattr(gear, "current", lambda: gear.Gear())
    jobs.write("fig10", FIG10)
    jobs.write("fig18", FIG18)
    monkeypatch.setenv("MLG_RUN_ROOT", str(tree))
    monkeypatch.setenv(gear.ENV_BASE, str(base))
    monkeypatch.setattr(gear, "current", lambda: at)
    jobs.write("fig10", {**FIG10, "numbers": {"V_crit (zero freeplay) [m/s]": 330.5,
                                              "S1 [m/s]": 60.0},
                         "hopf_points": [FIG10["hopf_points"][1]]})
    return base, tree


def test_the_section_sets_the_gear_beside_the_papers(roots):
    text = gear_answers.section()
    assert "Your gear: side stay rho = 20 deg, mu = 5 deg, the complete equations of motion" \
        in text
    assert "<td>330.5 m/s</td><td>346.1 m/s</td>" in text
    assert "<td>60 to 144.3 m/s</td><td>41.49 to 144.3 m/s</td>" in text
    assert "<td>not made (make gear)</td><td>0.0365 mm (set at F* = 0.1, V = 120 m/s)</td>" \
        in text
    assert "<th>Hopf point H1 (y_fp = 1 mm, F* = 1)</th><td>vanished</td>" in text
    assert "<b>subcritical</b>" in text


def test_an_allowed_freeplay_set_inside_the_stage_switch_says_so():
    """At (20, 5) deg kappa* = 0 is set at F* = 0.66, inside the oleo's
    stage switch (0.633-0.695), where straight rolling is unstable below
    120 m/s without freeplay; the answer says where, and that it is there."""
    window = stage_switch_window(0.1, 2.0, rho=math.radians(20.0), mu=math.radians(5.0),
                                 eom_terms=2.0)
    assert window == pytest.approx((0.6334, 0.6948), abs=1e-4)
    fig18 = {"kappa_star": 0.0, "numbers": {"kappa*: at F*": 0.66, "kappa*: at V [m/s]": 100.08},
             "stage_switch": list(window)}
    inside = gear_answers.answers(FIG10, fig18)
    assert gear_answers._value(inside, "allowed_mm", "mm") == \
        "0 mm (set at F* = 0.66, V = 100.1 m/s; inside the oleo's stage switch, F* 0.633-0.695)"
    outside = gear_answers.answers(FIG10, {**FIG18, "stage_switch": list(window)})
    assert gear_answers._value(outside, "allowed_mm", "mm") == \
        "0.0365 mm (set at F* = 0.1, V = 120 m/s)"


def test_the_section_links_the_animations_where_the_report_puts_them(roots):
    """The link to the gear's motion is the animate study's section
    (report: id study-<name>); it pointed at #study-motion, which no page has."""
    assert re.findall(r'href="#([^"]+)"', gear_answers.section()) == ["study-animate"]
    assert "animate" in [name for name, *_ in report.STUDIES]


def test_the_papers_gear_has_no_section(monkeypatch):
    monkeypatch.setattr(gear, "current", lambda: gear.Gear())
    assert gear_answers.section() == ""
