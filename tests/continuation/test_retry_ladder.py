"""The one retry ladder of a continuation that stops with no convergence
(continuation.with_ladder), and the named points a regression reports
first (tests/regression/named_points.py).

Run: /usr/bin/python3 -m pytest -q tests/continuation/test_retry_ladder.py
"""
import pytest

import named_points
from mlgshimmy.shared import continuation, runerror


def attempts(outcomes):
    """An attempt(mx, **constants) that records its calls and answers in turn."""
    calls = []

    def attempt(mx, **constants):
        calls.append((mx, constants))
        outcome = outcomes[len(calls) - 1]
        if isinstance(outcome, Exception):
            raise outcome
        return outcome
    return attempt, calls


def OWN():
    """A run's own steps: Fig. 10's orbit runs, NTST of constants/c.mlg."""
    return {"DS": 0.05, "DSMIN": 1e-5, "DSMAX": 1.0, "NTST": 80}


MX = runerror.RunError("run po3 in x: no convergence (MX) at branch -2 label 4",
                       kind=runerror.MX)


def test_the_first_rung_that_completes_is_kept():
    attempt, calls = attempts([MX, MX, "finer mesh"])
    assert continuation.with_ladder(attempt, OWN, "po3") == "finer mesh"
    assert calls == [(False, {}), (False, {"DS": pytest.approx(0.005), "DSMIN": pytest.approx(1e-9)}),
                     (False, {"NTST": 160})]


def test_every_rung_stopping_raises_the_first_stop():
    attempt, calls = attempts([MX] * (1 + len(continuation.LADDER)))
    with pytest.raises(runerror.RunError) as error:
        continuation.with_ladder(attempt, OWN, "po3")
    assert error.value is MX and len(calls) == 1 + len(continuation.LADDER)
    assert calls[-2][1] == {"NTST": 160, "DS": pytest.approx(0.005),
                            "DSMIN": pytest.approx(1e-9), "DSMAX": pytest.approx(0.5)}
    assert calls[-1][1] == {"NTST": 400}


def test_a_non_finite_stop_goes_up_the_ladder_too():
    stop = runerror.RunError("run fold1- in x: non-finite solution (component 3) at V = -0.4 "
                             "m/s, F* = 2.27: run stopped", kind=runerror.NON_FINITE)
    attempt, calls = attempts([stop, "smaller steps"])
    assert continuation.with_ladder(attempt, OWN, "fold1-") == "smaller steps"
    assert len(calls) == 2


def test_keep_last_keeps_the_last_rung_and_reports_it(capsys):
    errors = []
    for rung in range(1 + len(continuation.LADDER)):
        error = runerror.RunError(f"run fold1- in x: no convergence (MX) at V = {300 + rung}",
                                  kind=runerror.MX)
        error.diagram = f"diagram of attempt {rung}"
        errors.append(error)
    attempt, calls = attempts(errors)
    kept = continuation.with_ladder(attempt, OWN, "fold1-", keep_last=True)
    assert kept == f"diagram of attempt {len(continuation.LADDER)}"
    assert "REPORTED: run fold1- in x: no convergence (MX) at V = 304 with every rung" \
        in capsys.readouterr().out


def probed_ladder(V, Fstar, passing):
    """with_ladder on a fold curve stopped (MX) at (V, F*), its rungs
    probed by passes(constants) -> passing(constants): (its result, the
    constants of each run from the start, the constants probed)."""
    stop = runerror.RunError(f"run fold_upper3- in x: no convergence (MX) at V = {V}",
                             kind=runerror.MX)
    stop.diagram, stop.stop = "diagram up to the stop", {"V": V, "Fstar": Fstar}
    attempt, calls = attempts([stop, "the whole curve"])
    probed = []

    def passes(error, **constants):
        assert error.stop["V"] == V
        probed.append(constants)
        return passing(constants)
    result = continuation.with_ladder(attempt, OWN, "run fold_upper3-", keep_last=True,
                                      passes=passes)
    return result, [c for _, c in calls], probed


def test_rungs_that_stop_where_the_run_stopped_are_not_run_again(capsys):
    """A rung is tried from the stop first (passes); the ones that stop
    there too are skipped, and only the five times finer mesh, which gets
    past it, runs the branch again from its start."""
    result, runs, probed = probed_ladder(501.2, 1.05, lambda c: c == {"NTST": 400})
    assert result == "the whole curve" and runs == [{}, {"NTST": 400}], runs
    assert len(probed) == len(continuation.LADDER) - 1, probed
    assert capsys.readouterr().out.count("stops where the run stopped too") == 3


def test_the_last_rung_runs_from_the_start_whatever_its_probe():
    """Every rung stops where the run stopped when tried from there (the
    probes fail), yet the five times finer mesh, the last rung, runs the
    branch from its start and completes it (rho = mu = 10 deg: the fold
    curve that NTST 400 takes past (473.5 m/s, F* = 0.980))."""
    result, runs, probed = probed_ladder(473.5, 0.98, lambda c: False)
    assert result == "the whole curve" and runs == [{}, {"NTST": 400}], runs
    assert len(probed) == len(continuation.LADDER) - 1 and {"NTST": 400} not in probed


def test_a_stop_without_its_point_is_not_probed():
    """A non-finite stop has no converged point to try a rung from: the
    rungs run from the start, as without passes."""
    stop = runerror.RunError("run fold1- in x: non-finite solution (component 3)",
                             kind=runerror.NON_FINITE)
    attempt, calls = attempts([stop, "smaller steps"])
    assert continuation.with_ladder(attempt, OWN, "fold1-",
                                    passes=lambda error, **c: False) == "smaller steps"
    assert len(calls) == 2


def test_a_rung_costs_its_mesh_times_its_steps():
    assert continuation.rung_cost(OWN(), {"DS": 0.005}) == 1.0
    assert continuation.rung_cost(OWN(), {"NTST": 400}) == 5.0
    assert continuation.rung_cost(OWN(), {"NTST": 160, "DSMAX": 0.5}) == 4.0


def test_other_errors_and_allowed_stops_are_not_retried():
    attempt, calls = attempts([runerror.RunError("run x: AUTO wrote no b.x")])
    with pytest.raises(runerror.RunError, match="wrote no"):
        continuation.with_ladder(attempt, OWN, "x")
    attempt, calls = attempts(["kept up to its MX"])
    assert continuation.with_ladder(attempt, OWN, "x", keep_mx=True) == "kept up to its MX"
    assert calls == [(True, {})]


def test_named_points_reference_to_ours():
    reference = {"H1 [m/s]": 1.458, "H2 [m/s]": 28.307, "S1 [m/s]": 41.491}
    ours = {"H2 [m/s]": 28.324, "S1 [m/s]": 41.352, "Hhf2 [m/s]": 300.0,
            "po1: stops (MX, numerical) at V [m/s]": 29.79}
    lines = named_points.report(reference, ours)
    assert lines[1].split() == ["H2", "[m/s]", "28.307", "->", "28.324", "(+0.017,", "+0.060%)"]
    assert "S1 [m/s]" in lines[2] and "-0.335%" in lines[2]
    assert lines[3].split()[-2:] == ["->", "vanished"] and "H1" in lines[3]
    assert "new: 300" in lines[4]
    assert named_points.unfollowed(ours) == ["po1: stops (MX, numerical) at V [m/s]"]


def test_an_mx_at_wheel_lift_off_is_an_end_not_a_stop(tmp_path):
    """allow_mx=EDGE keeps an orbit branch that ends where a wheel lifts off
    (k_tlk x0.8, F* = 0.2: at 591.2 m/s, below the figure's 600) and sends
    any other MX up the ladder."""
    from mlgshimmy.shared import domain
    rundir = str(tmp_path)
    start = continuation.Start("figures", Fstar=0.2, V=0.0, k_tlk=3.12e7)
    eq = continuation.equilibria(rundir, "eq", start, stop={"V": 600.0})
    po = continuation.periodic_from(rundir, "po", eq("HB1"), stop={"V": 600.0},
                                    allow_mx=continuation.EDGE)
    ends = [(p["V"], domain.stop_reason(p)) for p in po("MX")]
    assert len(ends) == 1 and ends[0][1] == "wheel lift-off"
    assert ends[0][0] == pytest.approx(591.19, abs=0.1)


def test_a_solution_knows_its_constants_file():
    from mlgshimmy.shared import mlgmodel
    model = mlgmodel.Model("figures", I_psi=160.0, k_relax=0.75)
    k = mlgmodel.register_constants(model)
    assert mlgmodel.registered_constants(k) == {"I_psi": 160.0, "k_relax": 0.75}
    assert mlgmodel.registered_constants(0) == {}


def test_a_branch_that_uses_its_step_budget_is_reported_not_silent(tmp_path, capsys):
    """With allow_mx=Ends(...), a run whose branch ends at NMX (cut short, not
    at a stop) is kept and says so; one that reaches its stop does not."""
    start = continuation.Start("figures", Fstar=1.0, V=5.0)
    keep = continuation.Ends(lambda point, parameter: True, "", keep=True)
    continuation.equilibria(str(tmp_path / "a"), "eq", start, stop={"V": 50.0}, DS=1.0,
                            DSMAX=1.0, NMX=4, allow_mx=keep)
    out = capsys.readouterr().out
    assert "REPORTED: run eq in" in out and "step budget (NMX = 4) at V = 9;" in out, out
    continuation.equilibria(str(tmp_path / "b"), "eq", start, stop={"V": 7.5}, DS=1.0,
                            DSMAX=1.0, NMX=40, allow_mx=keep)
    assert "REPORTED" not in capsys.readouterr().out


def test_an_mx_at_a_connection_of_saddles_is_an_end_not_a_stop(tmp_path):
    """With the tanh law (Fig. 10's case) the orbits born at H2 = 28.48 m/s
    grow onto a heteroclinic cycle of the yawed saddles psi = +-1.754e-3
    rad, their period from 0.32 to 2.4 s near 29.753 m/s, where AUTO stops
    (MX): allow_mx=EDGE keeps it as the branch's end."""
    from mlgshimmy.shared import domain, saddle_connection
    values = {"Fstar": 1.0, "yfp": 1.0, "eps_rel": 0.1, "freeplay_law": 2}
    hb = continuation.hopf_points(str(tmp_path), "hb", "figures", "V",
                                  [27.0 + 0.05 * k for k in range(41)], **values)
    assert [p["V"] for p in hb] == [pytest.approx(28.4815, abs=1e-3)]
    po = continuation.periodic_from(str(tmp_path), "po", hb[0], stop={"V": 40.0},
                                    allow_mx=continuation.EDGE,
                                    **continuation.SPEED_ORBIT_STEPS)
    ends = po("MX")
    assert len(ends) == 1 and ends[0]["V"] == pytest.approx(29.75, abs=0.02)
    assert domain.stop_reason(ends[0]) == domain.SADDLES
    saddles, share = saddle_connection.saddle_stays(domain.solution_model(ends[0]), ends[0])
    assert sorted(u[0] for u in saddles) == [pytest.approx(-1.7541e-3, rel=1e-3),
                                             pytest.approx(1.7541e-3, rel=1e-3)]
    assert share > 0.7
