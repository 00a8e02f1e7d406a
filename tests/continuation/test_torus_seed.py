"""The torus-curve seed (drivers/mlgshimmy/shared/torus.py) on an orbit
whose monodromy matrix is known exactly: straight rolling held as a
"periodic orbit" of period T, so Phi(1) = expm(T J) and its eigenvalues are
exp(T lambda), lambda the eigenvalues of the library's exact Jacobian there
(F* = 1, V = 200 m/s, y_fp = 1 mm, epsilon = 0.1 mm).  Checked: the RK4
monodromy matrix against them (rel. 1e-8), and the seeded eigenfunction
against the boundary condition AUTO's torus continuation imposes,
v(1) = exp(i theta) v(0) (BCTR), and its norm, the integral of |v|^2 =
PAR(NPAR) = 1 (ICTR)."""
import math

import numpy as np
import pytest

from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import torus

VALUES = {"V": 200.0, "Fstar": 1.0, "yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.1}
PERIOD = 0.025          # s, about the large orbits' period
POINTS = 81             # stored points of the fake orbit


class Solution(dict):
    """The parts of an AUTO solution the seed reads and writes: columns by
    name ("t", the states, U(k)) and PAR by name."""

    def __init__(self, par, u):
        super().__init__(t=np.linspace(0.0, 1.0, POINTS))
        for name, value in u.items():
            self[name] = np.full(POINTS, value)
        self.PAR = Par(par)


class Par(dict):
    @property
    def coordnames(self):
        return list(self)


@pytest.fixture(scope="module")
def orbit():
    """(make_solution, exact multipliers exp(T lambda) sorted): straight
    rolling as an orbit of period PERIOD; make_solution() gives a fresh
    Solution (the seed writes into the one it is given)."""
    model = mlgmodel.Model("figures", **VALUES)
    u = model.equilibrium()
    par = {name: model[name] for name in mlgmodel.PARNAMES
           if name and name != mlgmodel.CONSTANTS_FILE}
    par[mlgmodel.CONSTANTS_FILE] = 0
    par.update({"T": PERIOD, "PAR(12)": 0.0, "PAR(31)": 0.0})
    lam = np.linalg.eigvals(np.array(model.jacobian(u)))
    return (lambda: Solution(dict(par), u)), np.sort_complex(np.exp(PERIOD * lam))


@pytest.fixture(scope="module")
def pairs(orbit):
    """(mu, other): the complex multiplier nearest the unit circle plays the
    critical one; other is the pair farthest from it in angle (2.24 rad
    against 0.25)."""
    exact = orbit[1]
    pair = exact[exact.imag > 1e-3]
    mu = pair[np.argmin(np.abs(np.abs(pair) - 1))]
    other = pair[np.argmax(np.abs(np.angle(pair) - np.angle(mu)))]
    return mu, other


def start_off_the_pair(orbit, pairs):
    """A fresh start whose own PAR(12) is set off the critical pair: the
    seed follows the angle given (the TR label's), as on a tongue, where
    the other pair must not be taken."""
    sol = orbit[0]()
    sol.PAR["PAR(12)"] = float(abs(np.angle(pairs[1])))
    return sol


@pytest.fixture(scope="module")
def seeded(orbit, pairs):
    """(seeded solution, v as an [n, points] complex array, mu)."""
    mu = pairs[0]
    seeded = torus.seeded(start_off_the_pair(orbit, pairs), float(abs(np.angle(mu))))
    n = len(mlgmodel.UNAMES)
    v = np.array([seeded[f"U({n + i + 1})"] + 1j * seeded[f"U({2 * n + i + 1})"]
                  for i in range(n)])
    return seeded, v, mu


def test_monodromy_matrix_of_a_constant_orbit_has_eigenvalues_exp_T_lambda(orbit):
    exact = orbit[1]
    _, phi = torus.monodromy_path(orbit[0]())
    found = np.sort_complex(np.linalg.eigvals(phi[-1]))
    error = np.max(np.abs(found - exact) / np.abs(exact).max())
    assert error < 1e-8, f"eigenvalues off exp(T lambda) by {np.max(np.abs(found - exact))}"


def test_seed_refuses_an_angle_with_no_pair_within_angle_tol(orbit, pairs):
    with pytest.raises(ValueError, match="no Floquet pair"):
        torus.seeded(start_off_the_pair(orbit, pairs),
                     abs(np.angle(pairs[0])) + 3 * torus.ANGLE_TOL)


def test_seed_angle_is_the_pair_argument(seeded):
    sol, _, mu = seeded
    got, expected = sol.PAR["PAR(12)"], abs(np.angle(mu))
    assert math.isclose(got, expected, rel_tol=0.0, abs_tol=1e-8), \
        f"got {got!r}, expected {expected!r} (abs 1e-8)"


def test_seed_eigenfunction_satisfies_v1_equals_mu_v0(seeded):
    _, v, mu = seeded
    error = np.max(np.abs(v[:, -1] - mu * v[:, 0]))
    assert error < 1e-8 * np.max(np.abs(v)), \
        f"|v(1) - mu v(0)| = {error} (|mu| = {abs(mu):.6f})"


def test_seed_eigenfunction_norm_is_par_npar_1(seeded):
    sol, v, _ = seeded
    norm = np.trapz(np.sum(np.abs(v) ** 2, axis=0), sol["t"])
    assert math.isclose(norm, 1.0, rel_tol=1e-12), f"integral of |v|^2 = {norm!r} (rel 1e-12)"
    assert sol.PAR["PAR(31)"] == 1.0, f"PAR(NPAR) = {sol.PAR['PAR(31)']!r}, expected 1"
