"""Tests of shared/bautin.py: the second Lyapunov coefficient l2 on the
Bautin normal form written in other coordinates, where l1 and l2 are known
in closed form, its l1 against lyapunov.coefficient's (eq. 3.20), and l2
at Fig. 14's GH point against the fold of limit cycles of the reference
diagrams beside it."""
import os

import numpy as np
import pytest

import helpers
from mlgshimmy.shared import (bautin, lyapunov, mlgmodel, naming, rundirs, spectrum, yfp_codim2,
                               yfp_runs, yfp_stored)

REFERENCE = os.path.join(helpers.ROOT, "tests", "reference", "fig14")

OMEGA, LAM = 2.0, 0.7


class NormalFormSeenElsewhere:
    """x' = f(x): w = x1 + i x2 has w' = (i OMEGA + c1 |w|^2 + c2 |w|^4) w,
    x3' = -LAM x3, seen in y with x = Psi(y) = y + quadratic + cubic terms
    (DPsi(0) = I, so q and p at 0 are those of x): y' = DPsi(y)^-1 f(Psi(y)),
    whose forms B ... E at 0 all mix the three coordinates.  Along
    q = (1, -i, 0) / sqrt2 (<q, q> = 1) w = sqrt2 z, so Kuznetsov's
    coefficients are 2 c1 and 4 c2: l1 = 2 Re c1 / OMEGA, l2 = 4 Re c2 /
    OMEGA (the first nonzero one is invariant under Psi).  The forms come
    from the field's analytic continuation: the coefficient of s_1 ... s_n
    in g(sum s_k v_k), by the discrete Cauchy integral over s_k = R
    e^(2 pi i m / M) (aliasing ~ R^M, rounding ~ 1e-16 / R^(n-1)): l2 to
    2e-14 at R = 0.1, M = 14, to 1e-11 at M = 10."""
    R, M = 0.1, 14

    def __init__(self, c1, c2):
        self.c1, self.c2 = complex(c1), complex(c2)

    def field(self, x):
        """f at states x (..., 3), complex ones too: |w|^2 continued as
        x1^2 + x2^2, w' = (alpha + i beta) w with alpha, beta its real
        polynomials."""
        s = x[..., 0] ** 2 + x[..., 1] ** 2
        alpha = self.c1.real * s + self.c2.real * s ** 2
        beta = OMEGA + self.c1.imag * s + self.c2.imag * s ** 2
        return np.stack([alpha * x[..., 0] - beta * x[..., 1],
                         beta * x[..., 0] + alpha * x[..., 1], -LAM * x[..., 2]], axis=-1)

    @staticmethod
    def psi(y):
        y1, y2, y3 = y[..., 0], y[..., 1], y[..., 2]
        return np.stack([y1 + 0.3 * y1 * y3 - 0.2 * y2 ** 2 + 0.15 * y2 ** 3,
                         y2 + 0.25 * y1 ** 2 + 0.15 * y2 * y3 + 0.1 * y1 ** 3,
                         y3 + 0.4 * y1 * y2 - 0.3 * y3 ** 2 + 0.2 * y1 * y2 ** 2], axis=-1)

    @staticmethod
    def dpsi(y):
        y1, y2, y3 = y[..., 0], y[..., 1], y[..., 2]
        one, zero = np.ones_like(y1), np.zeros_like(y1)
        rows = [[one + 0.3 * y3, -0.4 * y2 + 0.45 * y2 ** 2, 0.3 * y1],
                [0.5 * y1 + 0.3 * y1 ** 2, one + 0.15 * y3, 0.15 * y2 + zero],
                [0.4 * y2 + 0.2 * y2 ** 2, 0.4 * y1 + 0.4 * y1 * y2, one - 0.6 * y3]]
        return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)

    def g(self, y):
        return np.linalg.solve(self.dpsi(y), self.field(self.psi(y))[..., None])[..., 0]

    def jacobian(self, u):
        J = np.zeros((3, 3))
        J[:2, :2] = [[0.0, -OMEGA], [OMEGA, 0.0]]
        J[2, 2] = -LAM
        return J

    def form(self, *vectors):
        n = len(vectors)
        sizes = [np.linalg.norm(v) for v in vectors]
        if min(sizes) == 0.0:
            return np.zeros(3, dtype=complex)
        s = self.R * np.exp(2j * np.pi * np.arange(self.M) / self.M)
        grid = np.meshgrid(*[s] * n, indexing="ij")
        y = sum(g[..., None] * (np.asarray(v) / size) for g, v, size in zip(grid, vectors, sizes))
        weight = 1.0 / np.prod(grid, axis=0)
        coefficient = np.mean(self.g(y) * weight[..., None], axis=tuple(range(n)))
        return coefficient * np.prod(sizes)


def test_the_field_is_the_normal_form_to_first_order():
    """The discrete Cauchy integral of the first order gives the Jacobian."""
    system = NormalFormSeenElsewhere(0.35j, -0.4 + 0.25j)
    for e in np.eye(3):
        assert system.form(e) == pytest.approx(system.jacobian(0) @ e, abs=1e-13)


@pytest.mark.parametrize("c1, c2", [(0.35j, -0.4 + 0.25j), (-0.2j, 0.3 - 0.5j), (0.0, 0.15)],
                         ids=["l2 < 0", "l2 > 0", "c1 = 0"])
def test_l2_of_the_normal_form_in_other_coordinates(c1, c2):
    """At Re c1 = 0: l1 = 0 to 1e-13, g_21 = 2 c1 to 1e-13 and l2 = 4 Re c2
    / OMEGA to 1e-12 relative (found within 3e-14: the forms' rounding)."""
    system = NormalFormSeenElsewhere(c1, c2)
    gh = bautin.coefficients(system.jacobian(0), system.form)
    assert gh.omega == pytest.approx(OMEGA, rel=1e-14)
    assert gh.l1 == pytest.approx(0.0, abs=1e-13)
    assert gh.g21 == pytest.approx(2 * c1, abs=1e-13)
    assert gh.l2 == pytest.approx(4 * np.real(c2) / OMEGA, rel=1e-12)


def test_l1_agrees_with_eq_3_20_away_from_a_gh_point():
    """Re c1 = -0.3: bautin's l1 is lyapunov.coefficient's, 2 Re c1 / OMEGA."""
    system = NormalFormSeenElsewhere(-0.3 + 0.1j, 0.2)
    A = system.jacobian(0)
    assert bautin.coefficients(A, system.form).l1 == pytest.approx(-0.3, rel=1e-10)
    assert lyapunov.coefficient(A, system.form, system.form).l1 == pytest.approx(-0.3, rel=1e-10)


def hopf_speed(yfp):
    """Fig. 14's high-frequency Hopf point at this y_fp (F* = 1, eps = 0.1 mm)."""
    (V, _), = spectrum.hopf_scan("figures", "V", np.linspace(35.0, 50.0, 16),
                                 **yfp_runs.values("fixed", yfp))
    return V


def reference_orbits(yfp):
    """(V, psi_amp) along the orbits from the Hopf point of the reference
    diagram at this y_fp (b.y<y_fp>_po0: BR PT TY LAB V L2-NORM T psi_amp ...),
    the Hopf point first."""
    path = os.path.join(REFERENCE, f"y{yfp:g}", f"b.y{yfp:g}_po0")
    rows = [line.split() for line in open(path)]
    return np.array([(float(r[4]), float(r[7])) for r in rows if r[0] != "0"])


@pytest.fixture(scope="module")
def fig14_gh():
    """Fig. 14's GH point, located from the Hopf curve's points at y_fp =
    0.098 ... 0.106 as test_codim2 does."""
    yfps = (0.098, 0.100, 0.102, 0.104, 0.106)
    gh, = yfp_codim2.codim2_points([{"V": [hopf_speed(y) for y in yfps], "yfp": yfps}], "fixed")
    return gh


def fold_predicted(gh, yfp):
    """(Hopf speed, the normal form's fold: distance in V, psi amplitude) at
    this y_fp, with l1, omega, d Re lambda/dV of its Hopf point and l2 of
    the GH point (bautin.fold_of_cycles)."""
    V_H = hopf_speed(yfp)
    values = yfp_runs.values("fixed", yfp)
    mode = naming.mode("figures", "V", V_H, **values)
    distance, r2 = bautin.fold_of_cycles(mode["l1"], gh["l2"], 2 * np.pi * mode["freq_hz"],
                                         mode["mu_slope"])
    model = mlgmodel.Model("figures", V=V_H, **values)
    q_psi = abs(lyapunov.first_lyapunov(model, model.equilibrium()).q[0])
    return V_H, distance, 2 * q_psi * np.sqrt(r2)


def test_l2_at_fig14s_gh_point_puts_the_fold_of_cycles_where_the_diagrams_have_it(fig14_gh):
    """Fig. 14's GH point (located from the Hopf curve's points at y_fp =
    0.098 ... 0.106, as test_codim2 does): l2 < 0 and dl1/dy_fp > 0, so the
    fold of cycles runs beside the Hopf curve where l1 > 0, above the point
    in y_fp.  The reference diagrams agree: at y_fp = 0.11 (l1 > 0) the
    orbits leave the Hopf point down in V and turn at a fold; at 0.098
    (l1 < 0) they leave upwards and never come below it.  The normal form
    truncated at r^5, with l2 of the GH point and l1, omega, d Re lambda/dV
    of the Hopf point at 0.11 (bautin.fold_of_cycles), puts that fold 1.12
    m/s below the Hopf point at psi = 1.16e-4 rad; AUTO's is 1.224 m/s
    below at 1.141e-4 rad.  Tolerances 15 % and 5 %: the terms left out are
    of relative order l1 r^2 / (l2 r^4) ~ 1 at the fold, and 0.11 is 0.0075
    mm from the point (l1 = 50 there, 0 at the point).  And bautin's l1
    equals lyapunov's at both points, to rounding."""
    gh = fig14_gh
    assert gh["type"] == "GH" and gh["l2"] < 0 and gh["dl1_dyfp"] > 0
    model = mlgmodel.Model("figures", V=gh["V"], **yfp_runs.values("fixed", gh["yfp"]))
    u = model.equilibrium()
    assert bautin.second_lyapunov(model, u).l1 == pytest.approx(
        lyapunov.first_lyapunov(model, u).l1, abs=1e-12)

    above, below = reference_orbits(0.11), reference_orbits(0.098)
    # the sides they leave on, from the first orbit past 1e-6 rad (AUTO's
    # first step may go 1e-8 m/s either way)
    for orbits, side in ((above, -1), (below, +1)):
        first = orbits[np.argmax(orbits[:, 1] > 1e-6)]
        assert np.sign(first[0] - orbits[0, 0]) == side
    assert below[:, 0].min() >= below[0, 0] - 1e-6                      # no fold at 0.098
    fold = above[np.argmin(above[:, 0])]
    assert 0.5 < above[0, 0] - fold[0] < 5.0                            # a fold at 0.11

    V_H, distance, amplitude = fold_predicted(gh, 0.11)
    assert V_H == pytest.approx(above[0, 0], abs=1e-6)
    values = yfp_runs.values("fixed", 0.11)
    model = mlgmodel.Model("figures", V=V_H, **values)
    hopf = lyapunov.first_lyapunov(model, model.equilibrium())
    assert hopf.l1 > 0
    assert bautin.second_lyapunov(model, model.equilibrium()).l1 == pytest.approx(hopf.l1,
                                                                                 rel=1e-12)
    assert distance == pytest.approx(fold[0] - V_H, rel=0.15)
    assert amplitude == pytest.approx(fold[1], rel=0.05)
    # on the other side the normal form has no fold
    assert np.isnan(bautin.fold_of_cycles(-1.0, gh["l2"], 100.0, 0.07)[0])


def test_the_fold_of_cycles_nearer_the_gh_point_converges_on_the_normal_forms(fig14_gh,
                                                                               tmp_path):
    """Fig. 14's diagram in V at y_fp = 0.103 mm, 0.00054 mm from the GH
    point (l1 = +3.8 at its Hopf point), run by AUTO as the figure runs it
    (yfp_runs.diagram_in_V): its orbits turn 0.00795 m/s below the Hopf
    point at psi = 3.0737e-5 rad, where the normal form with the GH point's
    l2 puts the fold 0.00790 m/s below at 3.074e-5.  The error of the
    distance falls with l1 (8.3 % at 0.11 mm, l1 = 49.9; 2.0 % at 0.104,
    l1 = 10.8; 0.7 % here), as the next term of the normal form does:
    tolerances 2 % and 0.5 %."""
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        diagram = yfp_stored.stored_diagram(yfp_runs.diagram_in_V(
            str(tmp_path), "y0.103", "fixed", 0.103, uzr=(), figure="test_bautin"))
    V_H, distance, amplitude = fold_predicted(fig14_gh, 0.103)
    branch, = [b["columns"] for b in diagram["branches"] if abs(b["columns"]["V"][0] - V_H) < 1e-3]
    turn = yfp_codim2.first_turn(branch["V"])
    at_turn = np.asarray(branch["psi_amp"])[np.argmin(np.abs(np.asarray(branch["V"]) - turn))]
    assert turn - V_H == pytest.approx(distance, rel=0.02)
    assert at_turn == pytest.approx(amplitude, rel=0.005)


def differenced_forms(model, u, h):
    """The real forms with D and E as central differences of the exact C
    (step h along each direction scaled to max-norm 1): D(x, y, z, w) =
    d/ds C(x, y, z) at u + s w, E the four-point mixed difference in w, v."""
    def form(*v):
        if len(v) <= 3:
            return model.form(u, *v)
        scales = [np.max(np.abs(w)) for w in v[3:]]
        steps = [h * w / size for w, size in zip(v[3:], scales)]
        if len(v) == 4:
            return (model.form(u + steps[0], *v[:3]) - model.form(u - steps[0], *v[:3])) \
                * scales[0] / (2 * h)
        a, b = steps
        return sum(sa * sb * model.form(u + sa * a + sb * b, *v[:3])
                   for sa in (1, -1) for sb in (1, -1)) * scales[0] * scales[1] / (4 * h * h)
    return form


def test_l2_with_the_fourth_and_fifth_forms_by_differences_of_the_third():
    """At Fig. 14's Hopf point at y_fp = 0.104 mm: l2 from the exact D and
    E (Taylor arithmetic to fifth order) against l2 with D and E as central
    differences of the exact C, an independent path for both.  The
    differences converge on it as h^2 (error 3.8e-7 at h = 1e-5, 3.4e-8 at
    3e-6, a ratio of 11.1 for (10/3)^2 = 11.1): within 1e-7 at 3e-6, and
    the ratio of the two errors between 8 and 14."""
    model = mlgmodel.Model("figures", V=hopf_speed(0.104), **yfp_runs.values("fixed", 0.104))
    u = lyapunov.state(model.equilibrium())
    exact = bautin.second_lyapunov(model, u)
    errors = []
    for h in (1e-5, 3e-6):
        differenced = bautin.coefficients(model.jacobian(u),
                                          lyapunov.complex_form(differenced_forms(model, u, h)))
        assert differenced.l1 == pytest.approx(exact.l1, rel=1e-12)
        errors.append(abs(differenced.l2 / exact.l2 - 1))
    assert errors[1] < 1e-7 and 8 < errors[0] / errors[1] < 14

@pytest.mark.parametrize("V, turn", [
    ([41.1, 41.1 - 1e-8, 41.0, 40.2, 39.9, 40.5, 45.0], 39.9),   # down, a fold, back up
    ([40.5, 40.5 - 1e-8, 40.6, 41.0, 44.0], None),               # up from the Hopf point
    ([41.1, 40.0, 30.0], None),                                  # down to the run's end
])
def test_first_turn_of_a_branch_of_orbits(V, turn):
    """yfp_codim2.first_turn: AUTO's first step 1e-8 m/s the wrong way is
    no direction (STEP_NOISE); a branch that only ends has no turn."""
    assert yfp_codim2.first_turn(V) == turn


def test_fold_check_agrees_only_where_folds_lie_as_the_normal_form_says():
    one = {"yfp": 0.11, "fold": 39.878, "predicted": 39.98}
    other = {"yfp": 0.098, "fold": None, "predicted": None}
    assert yfp_codim2.agrees([one, other])
    assert not yfp_codim2.agrees([{**one, "fold": None}, other])
    assert not yfp_codim2.agrees([one, {**other, "fold": 40.1}])
