"""Tests of shared/codim2.py: codimension-two points located on Hopf
curves and a cusp on a fold curve of systems where they are known in
closed form, then on Fig. 9's zero-freeplay Hopf curve of the paper's gear,
which has none, and a GH point on a Hopf curve of the gear with side-stay
angles against l1 bisected along it."""
import numpy as np
import pytest

from mlgshimmy.shared import (codim2, continuation, lyapunov, mlgmodel, rolling, yfp_codim2, yfp_runs,
                               spectrum)


class Cubic:
    """x' = a x - y + b x r^2, y' = x + a y + b y r^2 (r^2 = x^2 + y^2),
    w' = (b - 0.6) w, p' = (b - 0.3) p - 3.3 q, q' = 3.3 p + (b - 0.3) q, at
    its equilibrium 0: on the Hopf curve a = 0, l1 = 2 b (GH at b = 0), a
    second pair reaches the axis at b = 0.3 (HH) and a real eigenvalue
    crosses 0 at b = 0.6 (ZH)."""

    def __init__(self, a, b):
        self.a, self.b = a, b

    def jacobian(self, u):
        a, b = self.a, self.b
        J = np.zeros((5, 5))
        J[:2, :2] = [[a, -1.0], [1.0, a]]
        J[2, 2] = b - 0.6
        J[3:, 3:] = [[b - 0.3, -3.3], [3.3, b - 0.3]]
        return J

    def form(self, u, *vectors):
        """B, D, E = 0; C: D^3 of b (x^3 + x y^2) and b (y^3 + y x^2)."""
        if len(vectors) != 3:
            return np.zeros(5)
        x, y, z = vectors

        def mixed(i, j):   # D^3 of v_i v_j^2 in the directions x, y, z
            return 2 * (x[i] * y[j] * z[j] + x[j] * y[i] * z[j] + x[j] * y[j] * z[i])
        return self.b * np.array([6 * x[0] * y[0] * z[0] + mixed(0, 1),
                                  6 * x[1] * y[1] * z[1] + mixed(1, 0), 0.0, 0.0, 0.0])


class Nilpotent:
    """x' = y, y' = -b x + a y + x^2 (a double-zero linear part at a = b =
    0): at 0 the Hopf curve a = 0 has omega^2 = b for b > 0 and becomes
    the neutral saddles +-sqrt(-b) for b < 0: BT at (0, 0)."""

    def __init__(self, a, b):
        self.a, self.b = a, b

    def jacobian(self, u):
        return np.array([[0.0, 1.0], [-self.b + 2 * u[0], self.a]])

    def form(self, u, *vectors):
        """B from x^2; C = 0."""
        if len(vectors) == 2:
            return np.array([0.0, 2 * vectors[0][0] * vectors[1][0]])
        return np.zeros(2)


def cubic_at(a, b):
    return Cubic(a, b), np.zeros(5)


def nilpotent_at(a, b):
    return Nilpotent(a, b), np.zeros(2)


def test_gh_hh_zh_located_on_a_hopf_curve():
    """Stored points b = -0.95, -0.85, ... (none at a zero); each point
    located to 1e-8 of the curve's extent, l1 = 2 b along it; at GH the
    field is linear to fifth order, l2 = 0."""
    b = np.linspace(-0.95, 0.95, 20)
    found = codim2.along_hopf_curve([(0.0, v) for v in b], cubic_at)
    assert np.array(found["l1"]) == pytest.approx(2 * b, rel=1e-12)
    assert [p["type"] for p in found["points"]] == ["GH", "HH", "ZH"]
    for point, b_there in zip(found["points"], (0.0, 0.3, 0.6)):
        assert point["b"] == pytest.approx(b_there, abs=2e-8)
        assert point["a"] == pytest.approx(0.0, abs=2e-8)
        assert point["omega"] == pytest.approx(1.0, rel=1e-9)
    assert found["points"][0]["l1"] == pytest.approx(0.0, abs=1e-7)
    assert found["points"][0]["l2"] == pytest.approx(0.0, abs=1e-12)   # no quintic terms


def test_bt_located_where_the_hopf_curve_meets_the_neutral_saddles():
    b = np.linspace(0.9, -0.8, 12)
    found = codim2.along_hopf_curve([(0.0, v) for v in b], nilpotent_at)
    assert [p["type"] for p in found["points"]] == ["BT"]
    bt = found["points"][0]
    assert (bt["a"], bt["b"]) == pytest.approx((0.0, 0.0), abs=2e-8)
    assert np.isnan(found["l1"][-1]) and found["omega"][-1] == 0.0   # saddles have no l1
    assert found["omega"][0] == pytest.approx(np.sqrt(0.9), rel=1e-12)


def test_fig09_hopf_curve_is_supercritical_throughout():
    """The zero-freeplay Hopf curve of Fig. 9, sampled by the eigenvalue
    scan at F* = 0.1 ... 3.5: l1 < 0 at every point (-1.2e-4 at F* = 0.1,
    -1.26e-6 at 3.5), no codimension-two point between them."""
    def at(V, F):
        model = mlgmodel.Model("figures", V=V, Fstar=F)
        return model, model.equilibrium()
    loads = (0.1, 0.3, 1.0, 2.0, 3.5)
    points = [(spectrum.hopf_scan("figures", "V", continuation.SPEED_SCAN, Fstar=F,
                                  yfp=0.0)[0][0], F) for F in loads]
    found = codim2.along_hopf_curve(points, at)
    assert max(found["l1"]) < 0 and found["points"] == []
    assert found["l1"][0] == pytest.approx(-1.2e-4, rel=0.05)
    assert found["l1"][-1] == pytest.approx(-1.26e-6, rel=0.05)


class Cusp:
    """x' = a + b x - x^3, y' = -y: its folds x^2 = b / 3 lie on the curve
    (a, b) = (-2 x^3, 3 x^2), a cusp at the origin; there A q = 0 for
    q = (1, 0), p = (1, 0), and <p, B(q, q)> / 2 = -3 x."""

    def __init__(self, a, b):
        self.a, self.b = a, b

    def rhs(self, u):
        return np.array([self.a + self.b * u[0] - u[0] ** 3, -u[1]])

    def jacobian(self, u):
        return np.array([[self.b - 3 * u[0] ** 2, 0.0], [0.0, -1.0]])

    def form(self, u, x, y):
        """B, the only form codim2.fold_coefficient asks for."""
        return np.array([-6 * u[0] * x[0] * y[0], 0.0])


def test_cusp_located_on_a_fold_curve_of_equilibria():
    """Stored folds at x = -0.5 ... 0.5 (none at 0): a = -3 x along the curve
    to rounding (q oriented by continuity), the cusp located by bisection
    with each trial point put back on the fold curve by Newton normal to
    the chord in (x, y, a, b)."""
    x = np.linspace(-0.5, 0.5, 8)
    points = [(-2 * v ** 3, 3 * v ** 2, (v, 0.0)) for v in x]
    found = codim2.along_fold_curve(points, Cusp)
    assert np.abs(found["a"]) == pytest.approx(3 * np.abs(x), rel=1e-12)
    assert np.sign(found["a"][0]) == -np.sign(found["a"][-1])   # one orientation along it
    cusp, = found["points"]
    assert cusp["type"] == "CP"
    # located in (x, a, b), where the curve is smooth: x to 1e-8 of its extent
    assert cusp["u"] == pytest.approx([0.0, 0.0], abs=1e-8)
    assert (cusp["a"], cusp["b"]) == pytest.approx((0.0, 0.0), abs=1e-12)


def test_a_fold_curve_without_a_cusp_has_none():
    """The curve's upper half alone (x > 0): a = -3 x < 0 throughout."""
    x = np.linspace(0.1, 0.5, 5)
    found = codim2.along_fold_curve([(-2 * v ** 3, 3 * v ** 2, (v, 0.0)) for v in x], Cusp)
    assert found["points"] == [] and len(set(np.sign(found["a"]))) == 1


SIDE_STAY = {"rho": np.radians(15.0), "mu": np.radians(-5.0), "eom_terms": 2.0}
FREEPLAY = {"yfp": 1.0, "eps_rel": 0.1}


def straight(Fstar):
    """Straight rolling continued from zero freeplay (Fig. 11's start at
    side-stay angles: Newton from psi = 0 can miss it at light load)."""
    return rolling.state("figures", Fstar, 1.0, {"eps_abs": 0.0, "eps_rel": 0.1}, **SIDE_STAY)


def side_stay_at(V, Fstar):
    return mlgmodel.Model("figures", V=V, Fstar=Fstar, **FREEPLAY, **SIDE_STAY), straight(Fstar)


def hopf_speed(Fstar):
    """The Hopf point of straight rolling in V = 125-140 m/s at this load
    (eigenvalue scan, bisected)."""
    V, = spectrum.hopf_scan("figures", "V", np.linspace(125.0, 140.0, 16),
                            state=lambda V: straight(Fstar), Fstar=Fstar,
                            **FREEPLAY, **SIDE_STAY)
    return V[0]


def test_gh_on_a_side_stay_hopf_curve_agrees_with_l1_bisected_along_it():
    """(rho, mu) = (15, -5) deg: the Hopf curve of the high-frequency pair
    near F* = 0.028, V = 133.5 m/s, where Fig. 11 at this geometry has a
    fold curve of orbits end.  codim2 locates GH between its points at
    F* = 0.024 ... 0.032; l1 of the Hopf point at each load, bisected in
    F* directly, gives the same point.  Tolerance: l1 near its zero carries
    noise of about 1e-5 (the rolling state is a Newton solve per load, and
    the freeplay corners make l1 sensitive to it) against dl1/dF* = -7.3,
    about 1.4e-6 in F*; dV/dF* = -400 m/s, so 1e-3 m/s in V."""
    loads = (0.024, 0.026, 0.028, 0.030, 0.032)
    found = codim2.along_hopf_curve([(hopf_speed(F), F) for F in loads], side_stay_at)
    gh, = found["points"]
    assert gh["type"] == "GH"

    def l1(F):
        return lyapunov.first_lyapunov(*side_stay_at(hopf_speed(F), F)).l1
    direct = spectrum.bisect(lambda F: l1(F) > 0, 0.026, 0.028, tol=1e-10)
    assert gh["b"] == pytest.approx(direct, abs=2e-6)
    assert gh["a"] == pytest.approx(hopf_speed(direct), abs=1e-3)
    # the sign data beside it: l1's slope over the bracket against the
    # central difference at the point (l1 is nearly linear over 0.002)
    slope = (l1(direct + 1e-4) - l1(direct - 1e-4)) / 2e-4
    assert slope < 0 and gh["dl1_db"] == pytest.approx(slope, rel=0.05)


def test_gh_on_fig14s_hopf_curve_at_the_papers_gear_agrees_with_l1_bisected_along_it():
    """Fig. 14's high-frequency Hopf curve in (y_fp, V) (F* = 1, eps = 0.1
    mm) turns in V at y_fp ~ 0.1025 mm and has a GH point there: l1 goes
    from -17.7 at y_fp = 0.100 to +10.8 at 0.104.  yfp_codim2.codim2_points
    on the curve's points at y_fp = 0.098 ... 0.106 (Hopf speeds from the
    eigenvalue scan) against l1 of the Hopf point at each y_fp bisected in
    y_fp: the same point to 1e-9 mm and 1e-6 m/s (both to rounding of l1,
    dl1/dy_fp = 7100 /mm), and the slope beside it to 1e-3."""
    def hopf_speed(yfp):
        (V, _), = spectrum.hopf_scan("figures", "V", np.linspace(35.0, 50.0, 16),
                                     **yfp_runs.values("fixed", yfp))
        return V

    def l1(yfp):
        model = mlgmodel.Model("figures", V=hopf_speed(yfp), **yfp_runs.values("fixed", yfp))
        return lyapunov.first_lyapunov(model, model.equilibrium()).l1
    yfps = (0.098, 0.100, 0.102, 0.104, 0.106)
    gh, = yfp_codim2.codim2_points([{"V": [hopf_speed(y) for y in yfps], "yfp": yfps}], "fixed")
    direct = spectrum.bisect(lambda y: l1(y) < 0, 0.102, 0.104, tol=1e-12)
    assert gh["type"] == "GH"
    assert gh["yfp"] == pytest.approx(direct, abs=1e-9)
    assert gh["V"] == pytest.approx(hopf_speed(direct), abs=1e-6)
    slope = (l1(direct + 1e-5) - l1(direct - 1e-5)) / 2e-5
    assert gh["dl1_dyfp"] == pytest.approx(slope, rel=1e-3) and slope > 0


def test_zh_on_fig11s_h3_curve_at_the_pitchforks():
    """Fig. 11 at the paper's gear (y_fp = 1 mm, eps = 0.1 y_fp): its H3
    Hopf curve runs down through both pitchfork loads of straight rolling,
    where a real eigenvalue crosses zero: two ZH points.  Located by
    codim2 between its Hopf speeds at F* = 0.02 ... 0.5, they lie at the
    pitchfork loads that stability_changes finds in F* at V = 50 m/s
    (straight rolling and its real eigenvalues do not depend on V), to
    1e-9 (each bisected to 1e-8 of its bracket)."""
    freeplay_ = {"yfp": 1.0, "eps_rel": 0.1}

    def at(V, F):
        model = mlgmodel.Model("figures", V=V, Fstar=F, **freeplay_)
        return model, model.equilibrium()
    loads = (0.02, 0.03, 0.05, 0.1, 0.2, 0.3, 0.4, 0.45, 0.5)
    points = [(max(V for V, _ in spectrum.hopf_scan("figures", "V", np.linspace(100, 160, 13),
                                                    Fstar=F, **freeplay_)), F) for F in loads]
    found = codim2.along_hopf_curve(points, at)
    pitchforks = [F for F, kind, _ in spectrum.stability_changes(
        "figures", "Fstar", np.linspace(0.02, 0.5, 49), V=50.0, **freeplay_) if kind == "BP"]
    assert [p["type"] for p in found["points"]] == ["ZH", "ZH"]
    assert [p["b"] for p in found["points"]] == pytest.approx(pitchforks, abs=1e-9)
    assert all(p["l1"] > 0 for p in found["points"])   # on H3's subcritical curve
