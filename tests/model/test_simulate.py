"""Tests of build/bin/mlg_simulate (CVODE time simulation of the MLG model).

The expected behaviour comes from the linearisation at straight rolling for
the `figures` parameter set (eigenvalues of mlg_rhs_jacobian at the
equilibrium): at V = 100 m/s, F* = 1 every mode decays (the Hopf point is at
V = 346.1 m/s); at V = 300 m/s, F* = 0.2 the shimmy pair 0.41 +- 238.6i rad/s
(38 Hz) is unstable (at F* = 0.2 the Hopf lies between 250 and 300 m/s) and
grows into the limit cycle of Fig. 8.
"""
import os

import numpy as np
import pytest

from mlgshimmy.shared import simulator


def simulate(tmp, name, *args):
    """Run the simulator; return (exit status, summary dict, samples, stderr)."""
    csv = os.path.join(tmp, name + ".csv")
    proc = simulator.run(csv, *args)
    summary, data = {}, None
    if proc.returncode == 0:
        summary = simulator.summary(proc.stdout)
        data = np.genfromtxt(csv, delimiter=",", names=True)
    return proc.returncode, summary, data, proc.stderr


def ran(tmp, name, *args):
    """simulate(), asserting that the run succeeded: (summary, samples)."""
    status, summary, data, err = simulate(tmp, name, *args)
    assert status == 0, f"{name}: exit status {status}, stderr {err.strip()!r}"
    return summary, data


def half_range(data, name, t0, t1):
    """Half peak-to-peak of a state for t0 <= t <= t1."""
    window = (data["t"] >= t0) & (data["t"] <= t1)
    return 0.5 * np.ptp(data[name][window])


@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    return str(tmp_path_factory.mktemp("simulate"))


@pytest.fixture(scope="module")
def unstable(scratch):
    # V = 300, F* = 0.2, psi0 = 1e-4 grows at the shimmy rate 0.41 /s
    return ran(scratch, "unstable", "--V", "300", "--Fstar", "0.2", "--psi0", "1e-4",
               "--t-end", "3")


def test_rest_holds_the_exact_equilibrium_with_the_analytic_jacobian(scratch):
    """(a) zero perturbation: the exact equilibrium stays put for 1 s, and
    CVODE uses the analytic Jacobian (no finite-difference RHS calls)."""
    summary, data = ran(scratch, "rest", "--V", "100", "--Fstar", "1", "--psi0", "0",
                        "--t-end", "1")
    states = data.dtype.names[1:]
    deviation = max(np.max(np.abs(data[s] - data[s][0])) for s in states)
    assert deviation < 1e-9, f"equilibrium not held for 1 s: max deviation {deviation:.3g}"
    assert summary["jac_evals"] > 0 and summary["fd_rhs_evals"] == 0, \
        f"jac_evals {summary['jac_evals']}, fd_rhs_evals {summary['fd_rhs_evals']}"


def test_stable_psi_perturbation_decays(scratch):
    """(b) V = 100, F* = 1, psi0 = 1e-3 decays (shimmy mode -1.84 rad/s:
    expected factor ~exp(-1.84 * 2.5) = 0.01 from [0, 0.5] to [2.5, 3] s)."""
    _, data = ran(scratch, "stable", "--V", "100", "--Fstar", "1", "--psi0", "1e-3",
                  "--t-end", "3")
    early, late = half_range(data, "psi", 0.0, 0.5), half_range(data, "psi", 2.5, 3.0)
    assert late < 0.05 * early, f"psi half-range {early:.3g} -> {late:.3g} (late/early < 0.05)"


def test_unstable_psi_grows_at_the_linear_shimmy_rate(unstable):
    """(c) linear regime: expected ratio exp(0.41 * 2) = 2.27 between
    [0.5, 1] and [2.5, 3] s, accepted in [1.8, 2.8]."""
    _, data = unstable
    early, late = half_range(data, "psi", 0.5, 1.0), half_range(data, "psi", 2.5, 3.0)
    ratio = late / early
    assert 1.8 <= ratio <= 2.8, f"psi half-range {early:.3g} -> {late:.3g}, ratio {ratio:.3f}"


def test_unstable_shimmy_frequency_38_hz(unstable):
    summary, _ = unstable
    assert abs(summary["frequency_hz"] - 38.0) < 0.5, \
        f"frequency {summary['frequency_hz']:.3f} Hz, expected 38 +- 0.5"


def test_unstable_shimmy_is_torsional(unstable):
    summary, _ = unstable
    assert summary["psi_amplitude_rad"] > 3 * summary["delta_amplitude_rad"], \
        f"psi {summary['psi_amplitude_rad']:.3g}, delta {summary['delta_amplitude_rad']:.3g}"


def test_invalid_yfp_rejected_naming_yfp(scratch):
    """(d) invalid parameters: exit status 2 with a message naming the parameter."""
    status, _, _, err = simulate(scratch, "invalid", "--yfp", "-1", "--t-end", "0.1")
    assert status == 2 and "yfp" in err, f"exit status {status}, stderr {err.strip()!r}"


@pytest.mark.parametrize("args, option", [
    (["--t-end", "1e20", "--dt-out", "1"], "--t-end"),
    (["--dt-out", "inf"], "--dt-out"),
    (["--t-end", "0.01", "--dt-out", "0.1"], "--dt-out"),
    (["--t-end", "nan"], "--t-end"),
    (["--u0", "0,0,0"], "--u0"),
    (["--u0", "0,0,0,0.3,0,0,0,0,0,nan"], "--u0"),
    (["--u0", "0,0,0,0.3,0,0,0,0,0,0,0"], "--u0")])
def test_invalid_window_or_state_refused_naming_the_option(scratch, args, option):
    """(d2) no output window, no steps, or not a state: exit status 2 naming the option."""
    status, _, _, err = simulate(scratch, "window", *args)
    assert status == 2 and option in err, f"exit status {status}, stderr {err.strip()!r}"


@pytest.mark.parametrize("args, epsilon", [
    (["--eps-abs", "0.1"], 0.1), (["--eps-rel", "0.3"], 0.3),
    (["--param", "eps_abs=0.05"], 0.05), ([], 0.1),
    (["--eps-abs", "0.1", "--eps-rel", "0.2"], 0.3)])
def test_epsilon_is_what_was_given(scratch, args, epsilon):
    """(d3) one part alone sets the other to 0 (defaults eps_abs = 0,
    eps_rel = 0.1); the summary prints epsilon in mm (y_fp = 1 mm)."""
    status, summary, _, err = simulate(scratch, "epsilon", "--yfp", "1", "--t-end", "0.01",
                                       *args)
    got = summary.get("epsilon_mm")
    assert status == 0 and got is not None and abs(got - epsilon) <= 1e-12, \
        f"exit {status}, epsilon {got} (expected {epsilon} mm, 1e-12), stderr {err.strip()!r}"


def test_domain_psi0_out_of_the_domain_stops_with_a_liftoff_error(scratch):
    """(e) a state outside the model's domain stops the run with its reason."""
    status, _, _, err = simulate(scratch, "domain", "--psi0", "1.5", "--t-end", "0.1")
    assert status == 1 and "lifts off" in err, f"exit status {status}, stderr {err.strip()!r}"


def test_u0_starts_from_the_given_state(scratch):
    """--u0 replaces the simulator's Newton equilibrium: given that very
    equilibrium the run is bit for bit the same; given a state at side-stay
    angles where Newton from psi = 0 does not converge (rho = mu = 10 deg,
    F* = 0.2, y_fp = 1 mm: straight rolling continued from zero freeplay,
    shared.rolling) the run starts there and stays (psi0 = 0)."""
    import math
    from mlgshimmy.shared import mlgmodel, rolling
    args = ["--V", "100", "--Fstar", "0.2", "--yfp", "1", "--eps-rel", "0.1", "--psi0", "1e-4",
            "--t-end", "0.5"]
    _, own = ran(scratch, "own", *args)
    u = mlgmodel.Model("figures", Fstar=0.2, yfp=1.0, eps_abs=0.0, eps_rel=0.1).equilibrium()
    u0 = ",".join(repr(u[n]) for n in mlgmodel.UNAMES)
    _, given = ran(scratch, "given", *args, "--u0", u0)
    assert all(np.array_equal(own[n], given[n]) for n in own.dtype.names), \
        "--u0 at the simulator's own equilibrium changed the run"
    at = ["--param", f"rho={math.radians(10)!r}", "--param", f"mu={math.radians(10)!r}",
          "--param", "eom_terms=2"]
    status, _, _, err = simulate(scratch, "newton", *args, "--psi0", "0", *at)
    assert status == 1 and "Newton did not converge" in err, (status, err)
    u = rolling.state("figures", 0.2, 1.0, {"eps_abs": 0.0, "eps_rel": 0.1},
                      rho=math.radians(10), mu=math.radians(10), eom_terms=2)
    u0 = ",".join(repr(u[n]) for n in mlgmodel.UNAMES)
    _, data = ran(scratch, "tilted", *args, "--psi0", "0", "--u0", u0, *at)
    assert np.max(np.abs(data["psi"] - u["psi"])) < 1e-9, \
        f"psi left the given state {u['psi']:.6g} by {np.max(np.abs(data['psi'] - u['psi'])):.3g}"


@pytest.mark.parametrize("u0", ("1,2,3", "1,2,3,4,5,6,7,8,9,10,11", "1,2,3,4,5,6,7,8,9,nan",
                                "1,2,3,4,5,6,7,8,9,x"))
def test_u0_refuses_a_bad_state_naming_the_option(scratch, u0):
    status, _, _, err = simulate(scratch, "bad_u0", "--u0", u0)
    assert status == 2 and "--u0 needs 10 finite numbers" in err, (u0, status, err)
