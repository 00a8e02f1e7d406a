"""Tests of shared/lyapunov.py: Kuznetsov's first Lyapunov coefficient l1
(eq. 3.20) on systems whose l1 is known in closed form, then at the Hopf
points of straight rolling of the paper's gear, where the exact forms
(c/ library) and the differences of the Jacobian must agree, its sign
with the direction of the orbit branches AUTO continues from them and
its amplitude prediction with their first orbits."""
import os

import numpy as np
import pytest

import helpers
from mlgshimmy.shared import lyapunov, mlgmodel, spectrum

REFERENCE = os.path.join(helpers.ROOT, "tests", "reference")
OMEGA, LAM = 2.0, 0.7
# an orthogonal change of coordinates (l1 is invariant under it, as <q, q> = 1 is)
ROTATION = np.linalg.qr(np.random.default_rng(35).normal(size=(3, 3)))[0]


class Polynomial:
    """v' = g(v) seen in the coordinates u = R v: f(u) = R g(R^T u), with
    .jacobian(u) = R Dg(R^T u) R^T, as mlgmodel.Model gives it."""

    def __init__(self, dg, rotation):
        self.dg, self.R = dg, rotation

    def jacobian(self, u):
        return self.R @ self.dg(self.R.T @ np.asarray(u)) @ self.R.T


def cubic_focus(a):
    """x' = -w y + a x r^2, y' = w x + a y r^2 (r^2 = x^2 + y^2), i.e. s' = i w s
    + a |s|^2 s for s = x + iy; Kuznetsov's z = s / sqrt2 (along q = (1, -i) /
    sqrt2) has z' = i w z + c1 z|z|^2, c1 = 2a, so l1 = Re c1 / w = 2a / w."""
    def dg(v):
        x, y = v
        return np.array([[a * (3 * x * x + y * y), -OMEGA + 2 * a * x * y],
                         [OMEGA + 2 * a * x * y, a * (x * x + 3 * y * y)]])
    return dg


def slaved_radius(v):
    """x' = -w y + x z, y' = w x + y z, z' = -lam z + r^2: the centre manifold
    z = r^2 / lam gives r' = r^3 / lam, i.e. the focus above with a = 1/lam:
    l1 = 2 / (lam w), through the A^-1 B(q, qbar) term alone."""
    x, y, z = v
    return np.array([[z, -OMEGA, x], [OMEGA, z, y], [2 * x, 2 * y, -LAM]])


def slaved_second_harmonic(v):
    """x' = -w y + x z, y' = w x - y z, z' = -lam z + x^2 - y^2: with s = x + iy,
    s' = i w s + conj(s) z and z = Re(k s^2), k = 1/(lam + 2i w) on the centre
    manifold, so s' has (k/2)|s|^2 s, i.e. the focus above with a = Re k / 2:
    l1 = lam / (w (lam^2 + 4 w^2)), through the (2 i w I - A)^-1 B(q, q) term
    alone."""
    x, y, z = v
    return np.array([[z, -OMEGA, x], [OMEGA, -z, -y], [2 * x, -2 * y, -LAM]])


@pytest.mark.parametrize("system, l1", [
    (Polynomial(cubic_focus(-0.3), np.eye(2)), 2 * -0.3 / OMEGA),
    (Polynomial(cubic_focus(0.45), np.array([[0.6, -0.8], [0.8, 0.6]])), 2 * 0.45 / OMEGA),
    (Polynomial(slaved_radius, ROTATION), 2 / (LAM * OMEGA)),
    (Polynomial(slaved_second_harmonic, ROTATION), LAM / (OMEGA * (LAM ** 2 + 4 * OMEGA ** 2))),
], ids=["focus", "rotated focus", "3-d radius", "3-d second harmonic"])
def test_l1_of_systems_with_a_known_value(system, l1):
    """The forms of a cubic field are exact central differences of its
    Jacobian, so every step gives l1 to rounding (1e-9 relative)."""
    hopf = lyapunov.by_differences(system, np.zeros(len(system.R)))
    assert hopf.omega == pytest.approx(OMEGA, rel=1e-12)
    assert hopf.l1 == pytest.approx(l1, rel=1e-9)


def test_exact_forms_take_the_place_of_the_differences():
    """coefficient(A, B, C) with the forms of slaved_radius written out
    (B from x z, y z, r^2; C = 0), in the rotated coordinates, gives what
    the differences give, and the closed form 2 / (lam w), to 1e-12."""
    R = ROTATION

    def B(a, b):
        a, b = R.T @ a, R.T @ b
        return R @ np.array([a[0] * b[2] + a[2] * b[0], a[1] * b[2] + a[2] * b[1],
                             2 * (a[0] * b[0] + a[1] * b[1])])

    def C(a, b, c):
        return np.zeros(3, dtype=complex)

    system = Polynomial(slaved_radius, R)
    exact = lyapunov.coefficient(system.jacobian(np.zeros(3)), B, C)
    assert exact.l1 == pytest.approx(2 / (LAM * OMEGA), rel=1e-12)
    assert lyapunov.by_differences(system, np.zeros(3)).l1 == pytest.approx(exact.l1, rel=1e-9)


PAPER_GEAR = {"Fstar": 1.0, "yfp": 1.0, "eps_rel": 0.1}
ZERO_FREEPLAY = {"Fstar": 1.0, "yfp": 0.0}
# name: (gear, bracket of V [m/s], V_H named by the AUTO runs (tests/reference/fig10/named.json),
#        l1 (Kuznetsov's, per unit <q, q>), where the orbit branch from it starts in the reference
#        runs, its first or last points near V_H)
HOPF = {
    "H1": (PAPER_GEAR, (1.3, 1.6), 1.4581594746679292, -413.7354, ("fig10/b.po1", "first")),
    "H2": (PAPER_GEAR, (28.0, 28.6), 28.306722207961514, -4.094648, ("fig10/b.po1", "last")),
    "H3": (PAPER_GEAR, (144.0, 144.5), 144.26969033434705, 0.03377912, ("fig10/b.po3", "first")),
    "V_crit": (ZERO_FREEPLAY, (340.0, 350.0), 346.09999745081984, -3.032322e-6,
               ("fig07/b.po_F1", "first")),
}


def rolling_at(V, gear):
    model = mlgmodel.Model("figures", V=V, **gear)
    u = model.equilibrium()
    return model, np.array([u[name] for name in mlgmodel.UNAMES])


def hopf_point(name):
    """V_H by bisection on the sign of the critical pair's real part (60
    halvings of the bracket), l1 there (exact forms), and mu' = d Re lambda / dV."""
    gear, bracket = HOPF[name][:2]
    (V, kind, _), = spectrum.stability_changes("figures", "V", bracket, **gear)
    assert kind == "HB"
    model, u = rolling_at(V, gear)
    mu = [lyapunov.critical_pair(m.jacobian(v))[3]
          for m, v in (rolling_at(V + dV, gear) for dV in (1e-4, -1e-4))]
    return V, model, u, lyapunov.first_lyapunov(model, u), (mu[0] - mu[1]) / 2e-4


def orbits(run, end, count):
    """(V, psi_amp) of the first or last `count` orbits of a reference run
    (b-file columns: BR PT TY LAB V L2-NORM T psi_amp ...)."""
    rows = [line.split() for line in open(os.path.join(REFERENCE, run))]
    rows = [(float(r[4]), float(r[7])) for r in rows if r[0] != "0"]
    # the first row is the Hopf point itself
    return np.array(rows[1:1 + count] if end == "first" else rows[-count:])


@pytest.mark.parametrize("name", HOPF)
def test_l1_at_the_hopf_points_of_straight_rolling(name):
    """Straight rolling at F* = 1 (psi = 0: the links centred in the
    freeplay): l1 < 0 (supercritical) at H1, H2 and V_crit, l1 > 0
    (subcritical) at H3, as the orbit branches continued by AUTO say."""
    V, model, u, hopf, _ = hopf_point(name)
    assert V == pytest.approx(HOPF[name][2], abs=1e-6)
    assert abs(hopf.real_part) < 1e-12
    assert hopf.l1 == pytest.approx(HOPF[name][3], rel=1e-5)


@pytest.mark.parametrize("name", HOPF)
def test_exact_l1_agrees_with_the_differences_of_the_jacobian(name):
    """by_differences converged in the step: within 1e-5 relative over the
    steps 2h, h, h/2 chosen (its spread: 2.8e-6 at H1, 2.0e-6 H2, 1.2e-6 H3,
    2.2e-7 V_crit), at_step(h) against at_step(h/2) within 1e-4; the exact
    l1 within three spreads and 2e-6 of it (-9.6e-8, -1.0e-6, -9.2e-9,
    +5.8e-7 relative): the spread estimates the error, it does not bound it."""
    _, model, u, exact, _ = hopf_point(name)
    fd = lyapunov.by_differences(model, u)
    assert fd.spread < 1e-5 * abs(fd.l1)
    half = lyapunov.at_step(model, u, fd.h / 2)
    assert abs(half.l1 / fd.l1 - 1) < 1e-4
    assert abs(exact.l1 - fd.l1) < min(3 * fd.spread, 2e-6 * abs(fd.l1))


@pytest.mark.parametrize("name", ["H1", "H2", "H3"])
def test_the_step_resolves_the_freeplay_smoothing(name):
    """The step chosen moves psi by at most 1/200 of eps / r_tlk (2.1e-4 rad,
    over which eq. (15) bends): each direction of the differences (Re q,
    Im q) is scaled to max-norm 1, psi moving by h |q_psi| / max |q|.
    (1.5e-3 of it at H1, 2.8e-3 at H2, 1.8e-3 at H3.)"""
    _, model, u, _, _ = hopf_point(name)
    hopf = lyapunov.by_differences(model, u)
    psi_step = hopf.h * max(abs(part[0]) / np.max(np.abs(part))
                            for part in (hopf.q.real, hopf.q.imag))
    assert psi_step < model.epsilon_m() / model.r_tlk(u[3]) / 200


@pytest.mark.parametrize("name", HOPF)
def test_orbits_are_born_on_the_side_l1_says(name):
    """The normal form has orbits where mu / l1 < 0 (mu = Re lambda ~ mu' (V -
    V_H)): they start towards higher V at H1 and V_crit, lower at H2 and H3,
    as in the reference runs."""
    V, _, _, hopf, slope = hopf_point(name)
    V_orbits = orbits(*HOPF[name][4], 1)[0, 0]
    assert np.sign(V_orbits - V) == -np.sign(slope * hopf.l1)


@pytest.mark.parametrize("name, rel", [("H2", 0.01), ("H3", 0.02), ("V_crit", 1e-4)])
def test_amplitude_predicted_by_l1_matches_the_first_orbits(name, rel):
    """psi_amp = K sqrt|V - V_H| near V_H, K = 2 |q_psi| sqrt(|mu'| / (omega |l1|))
    (lyapunov.amplitude); from the two reference orbits nearest V_H, K^2 is
    psi_amp^2 / |V - V_H| extrapolated linearly to V_H.  K = 4.083e-3 (H2;
    the orbits give -0.4 %), 3.274e-3 (H3; -1.1 %: they reach a quarter of
    the freeplay angle, where the link law bends), 2.0336e-2 rad/sqrt(m/s)
    (V_crit; 5e-7).  H1 is left out: the reference's first orbit is
    0.52 m/s past it, at 70 % of the freeplay angle."""
    V, _, _, hopf, slope = hopf_point(name)
    K = lyapunov.amplitude(hopf, -np.sign(hopf.l1) * abs(slope))[0]   # at |V - V_H| = 1
    near = orbits(*HOPF[name][4], 2)
    distance = np.abs(near[:, 0] - V)
    K2 = np.polyfit(distance, near[:, 1] ** 2 / distance, 1)[1]
    assert K == pytest.approx(np.sqrt(K2), rel=rel)


@pytest.mark.parametrize("vectors, bad", [
    ([np.ones(9), np.ones(10)], "vector 1"),
    ([np.ones(10), np.ones(10), np.ones((10, 1))], "vector 3"),
    ([np.ones(10)] * 4 + [np.ones(11)], "vector 5"),
])
def test_model_forms_name_a_vector_of_the_wrong_shape(vectors, bad):
    """A short vector would reach C padded with zeros: refused, named."""
    model, u = rolling_at(100.0, PAPER_GEAR)
    with pytest.raises(ValueError, match=f"form: {bad} has shape"):
        model.form(u, *vectors)


@pytest.mark.parametrize("count", [0, 6])
def test_model_forms_of_an_order_the_library_lacks_are_refused(count):
    model, u = rolling_at(100.0, PAPER_GEAR)
    with pytest.raises(ValueError, match=f"form: {count} vectors; the library's forms take 1 to 5"):
        model.form(u, *[np.ones(10)] * count)


class KinkDamped:
    """x' = y, y' = -x - c |y| y at 0: A has +-i with q = p = (1, i)/sqrt2,
    and on x(theta) = 2 Re(q e^(i theta)) the one-sided second-order term is
    (0, -c |y| y): a2 = -4 sqrt2 c / (3 pi), from the integral of
    |sin| sin e^(-i theta) = -8i/3."""

    def __init__(self, c):
        self.c = c

    def jacobian(self, u):
        return np.array([[0.0, 1.0], [-1.0, -2 * self.c * abs(u[1])]])

    def form(self, u, *vectors):
        return np.zeros(2)      # at y = 0 the kink has no second derivative

    def taylor(self, u, d):
        """f(u + t d) = f(u) + t A d + t^2 (0, -c |d_y| d_y) for t > 0."""
        return np.array([[0.0, 0.0], self.jacobian(u) @ d,
                         [0.0, -2 * self.c * abs(d[1]) * d[1]], [0.0, 0.0]])


@pytest.mark.parametrize("c", [0.7, -0.2])
def test_kink_coefficient_of_quadratic_damping(c):
    system = KinkDamped(c)
    hopf = lyapunov.first_lyapunov(system, np.zeros(2))
    assert hopf.l1 == pytest.approx(0.0, abs=1e-15)
    a2 = lyapunov.kink_coefficient(system, np.zeros(2), hopf)
    assert a2.real == pytest.approx(-4 * np.sqrt(2) * c / (3 * np.pi), rel=1e-3)
    assert abs(a2.imag) < 1e-12


def test_no_kink_where_the_mode_leaves_the_oleo_still():
    """H3 of the paper's gear: q_eta' = 0 to rounding, a2 ~ 1e-17."""
    _, model, u, hopf, _ = hopf_point("H3")
    assert abs(lyapunov.kink_coefficient(model, u, hopf)) < 1e-15
