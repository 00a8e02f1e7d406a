"""Codimension-two points on a computed curve of Hopf points of straight
rolling, located by test functions that change sign there, by bisection
between the curve's stored points (Kuznetsov, Elements of Applied
Bifurcation Theory, 3rd ed., sections 8.3-8.5 and 10.2):

  GH  generalised Hopf: l1 = 0 (shared.lyapunov, exact forms);
  BT  Bogdanov-Takens: kappa = lambda_i lambda_j of the two eigenvalues with
      lambda_i + lambda_j = 0 is omega^2 on the Hopf curve and -k^2 on the
      neutral saddles beyond, 0 where omega -> 0 and the curve meets a fold;
  ZH  zero-Hopf: det A / kappa = 0, a real eigenvalue through zero;
  HH  Hopf-Hopf: the product of lambda_i + lambda_j over every pair of
      eigenvalues but the critical pair vanishes where a second pair
      reaches the imaginary axis.

    found = along_hopf_curve(points, at)
    found["points"]    # [{"type": "GH", "a": V, "b": F*, "omega", "l1", ...}]
    found["l1"]        # l1 at each stored point

and on a computed curve of folds of equilibria (section 8.2):

  CP  cusp: a = <p, B(q, q)> / 2, the fold's quadratic normal-form
      coefficient (A q = 0, A^T p = 0, <p, q> = 1, q oriented along the
      curve), changes sign.

    found = along_fold_curve(points, at)   # points: [(a, b, state)]
    found["points"]    # [{"type": "CP", "a", "b", "u"}]
    found["a"]         # a at each stored point

points: [(a, b)] of the curve in its two parameters, in order; at(a, b)
-> (model, u): the mlgmodel.Model and straight rolling's state there.  A
sign change between two stored points is bisected along the segment
joining them, each trial point moved back onto the curve along the
segment's normal (Re of the critical pair = 0), until the segment is
TOL of the curve's extent.  At a GH point the second Lyapunov coefficient
l2 (shared.bautin: on which side the fold of limit cycles leaves) and
dl1/db across it (_slope: the side of the GH point where the Hopf points
are subcritical).  kink(model, u): the oleo kink's a2 at a point of the curve
(where the mode moves eta', a2 decides the criticality up to an amplitude,
and l1 = 0 is then the one-sided expansion's).
"""
from __future__ import annotations

from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import bautin, lyapunov, mlgmodel, spectrum

TOL = 1e-8       # of the curve's extent in each parameter
TYPES = ("GH", "BT", "ZH", "HH")


def kink(model: Any, u: Any) -> Tuple[float, float]:
    """(Re a2, the psi amplitude up to which it decides) at a Hopf point of
    the curve (lyapunov.kink_coefficient, lyapunov.kink_amplitude)."""
    hopf = lyapunov.first_lyapunov(model, u)
    a2 = lyapunov.kink_coefficient(model, u, hopf)
    return float(a2.real), lyapunov.kink_amplitude(hopf, a2)


def _pair_sums(eig):
    """[(i, j, lambda_i + lambda_j)] over the pairs i < j."""
    return [(i, j, eig[i] + eig[j]) for i in range(len(eig)) for j in range(i + 1, len(eig))]


def _critical(A):
    """(eigenvalues, i, j): the pair whose sum is nearest 0, the critical
    pair on a Hopf curve (lambda, conj lambda) or on neutral saddles (k, -k)."""
    eig = numpy.linalg.eigvals(A)
    i, j, _ = min(_pair_sums(eig), key=lambda s: abs(s[2]))
    return eig, i, j


def tests(model: mlgmodel.Model, u: ArrayLike) -> Dict[str, float]:
    """The test functions at a point of the Hopf curve, and omega there
    (GH NaN on neutral saddles, which have no l1, omega 0 there)."""
    A = model.jacobian(u)
    eig, i, j = _critical(A)
    kappa = (eig[i] * eig[j]).real
    # only the sign tells: each factor reduced to its phase (the product can overflow)
    sums = [s for k, l, s in _pair_sums(eig) if (k, l) != (i, j)]
    others = 0.0 if 0 in sums else numpy.prod([s / abs(s) for s in sums]).real
    hopf = None
    if kappa > 0 and eig[i].imag != 0:
        try:
            hopf = lyapunov.first_lyapunov(model, u)
        except numpy.linalg.LinAlgError:   # A singular: exactly at a zero-Hopf point
            pass
    return {"GH": hopf.l1 if hopf else numpy.nan, "BT": float(kappa),
            "ZH": float(numpy.linalg.det(A) / kappa), "HH": float(others),
            "omega": hopf.omega if hopf else abs(eig[i].imag)}


def _critical_sum(model, u, ref: complex) -> float:
    """lambda + lambda' for the eigenvalue lambda nearest ref and its partner
    (the eigenvalue that sums with it nearest 0): 2 Re lambda on a Hopf
    curve, the trace of a saddle pair on neutral saddles.  Following ref,
    not the pair nearest the axis: near a Hopf-Hopf point both pairs are."""
    eig = numpy.linalg.eigvals(model.jacobian(u))
    k = int(numpy.argmin(numpy.abs(eig - ref)))
    partner = min((j for j in range(len(eig)) if j != k), key=lambda j: abs(eig[k] + eig[j]))
    return float((eig[k] + eig[partner]).real)


def _critical_eigenvalue(model, u) -> complex:
    """The critical pair's member with Im >= 0 (the larger of a real pair)."""
    eig, i, j = _critical(model.jacobian(u))
    return max(eig[i], eig[j], key=lambda lam: (lam.imag, lam.real))


def _onto_curve(at, p0, p1, s, scale, along):
    """The curve's point near the segment p0-p1's point at s (scaled
    coordinates), moved in parameter `along` by at most the segment's
    length, by bisection on the critical pair's sum."""
    p0, p1 = numpy.asarray(p0) / scale, numpy.asarray(p1) / scale
    base = p0 + s * (p1 - p0)
    move = numpy.zeros(2)
    move[along] = numpy.hypot(*(p1 - p0))
    ref = _critical_eigenvalue(*at(*(p0 * scale)))

    def real_part(t):
        return _critical_sum(*at(*((base + t * move) * scale)), ref)
    lo_sign = numpy.sign(real_part(-1.0))
    if lo_sign == numpy.sign(real_part(1.0)):
        raise RuntimeError(f"codim2: the Hopf curve is not within a segment's length of "
                           f"{tuple((base * scale).tolist())} in its parameter {along + 1}")
    t = spectrum.bisect(lambda t: numpy.sign(real_part(t)) == lo_sign, -1.0, 1.0, tol=TOL)
    return tuple(((base + t * move) * scale).tolist())


def locate(at: Callable, p0: Sequence[float], p1: Sequence[float], kind: str, scale: numpy.ndarray,
           along: int) -> Tuple[float, float, float]:
    """(a, b, s): the point between stored points p0 and p1 where test
    `kind` is 0, and its place s along the segment."""
    def sign(s):
        return numpy.sign(tests(*at(*_onto_curve(at, p0, p1, s, scale, along)))[kind])
    first = sign(0.0)
    s = spectrum.bisect(lambda s: sign(s) == first, 0.0, 1.0, tol=TOL)
    return (*_onto_curve(at, p0, p1, s, scale, along), s)


# l1's slope at a GH point: from the curve's points this fraction of the
# segment either side (l1 carries noise ~1e-5 from the rolling state at
# side-stay angles; over 5 % of a 0.002 segment in F* that is 5 % of a
# slope of 10)
SLOPE_SPAN = 0.05


def _slope(at, p0, p1, s, scale, along) -> float:
    """dl1/db at the curve's point at s on the segment p0-p1, by l1 at its
    points SLOPE_SPAN of the segment either side."""
    ends = [_onto_curve(at, p0, p1, t, scale, along)
            for t in (s - SLOPE_SPAN, s + SLOPE_SPAN)]
    l1 = [tests(*at(*e))["GH"] for e in ends]
    return float((l1[1] - l1[0]) / (ends[1][1] - ends[0][1]))


def along_hopf_curve(points: Sequence[Tuple[float, float]], at: Callable,
                     along: int = 0) -> Dict[str, List]:
    """{"l1", "omega": at each stored point, "points": the codimension-two
    points located between them, [{"type", "a", "b", "omega", "l1", and at
    GH "l2", "dl1_db"}]};
    along: the parameter (0: a, 1: b) in which a trial point is moved back
    onto the curve, one the equilibrium does not depend on where there is
    one (V for straight rolling, docs/model.md 4.20)."""
    points = [tuple(map(float, p)) for p in points]
    values = [tests(*at(*p)) for p in points]
    scale = numpy.ptp(numpy.array(points), axis=0)
    scale[scale == 0.0] = 1.0
    found = []
    for k in range(len(points) - 1):
        for kind in TYPES:
            if numpy.sign(values[k][kind]) * numpy.sign(values[k + 1][kind]) < 0:
                a, b, s = locate(at, points[k], points[k + 1], kind, scale, along)
                there = tests(*at(a, b))
                point = {"type": kind, "a": a, "b": b, "omega": there["omega"],
                         "l1": there["GH"]}
                if kind == "GH":
                    point["l2"] = bautin.second_lyapunov(*at(a, b)).l2
                    point["dl1_db"] = _slope(at, points[k], points[k + 1], s, scale, along)
                found.append(point)
    return {"l1": [v["GH"] for v in values], "omega": [v["omega"] for v in values],
            "points": found}


# Newton on a fold curve of equilibria (_onto_fold): steps and stop
NEWTON_STEPS = 30
NEWTON_TOL = 1e-11      # max-norm of the residual (f, g)
FD_STEP = 1e-7          # step of the residual's difference Jacobian, scaled coordinates


def _null_vectors(A, ref=None):
    """(q, p): A q ~ 0 for the eigenvalue nearest 0 (|q| = 1, oriented as
    `ref` where given), A^T p ~ 0, <p, q> = 1 (real at a fold)."""
    eig, vec = numpy.linalg.eig(A)
    q = vec[:, numpy.argmin(numpy.abs(eig))].real
    q /= numpy.linalg.norm(q)
    if ref is not None and numpy.dot(q, ref) < 0:
        q = -q
    eig_t, vec_t = numpy.linalg.eig(A.T)
    p = vec_t[:, numpy.argmin(numpy.abs(eig_t))].real
    return q, p / numpy.dot(p, q)


def fold_coefficient(model: Any, u: ArrayLike,
                     ref: Optional[numpy.ndarray] = None) -> Tuple[float, numpy.ndarray]:
    """(a, q) at a fold of equilibria: a = <p, B(q, q)> / 2, the quadratic
    coefficient on the centre manifold (Kuznetsov, section 5.4), q oriented
    as `ref`; zero at a cusp (section 8.2)."""
    q, p = _null_vectors(numpy.asarray(model.jacobian(u)), ref)
    return 0.5 * float(numpy.dot(p, model.form(u, q, q))), q


def _singularity(A, q, p):
    """g of the bordered system [[A, p], [q^T, 0]] [v; g] = [0; 1]: zero
    exactly where A is singular (Kuznetsov, section 10.2)."""
    n = len(q)
    M = numpy.zeros((n + 1, n + 1))
    M[:n, :n], M[:n, n], M[n, :n] = A, p, q
    return numpy.linalg.solve(M, numpy.r_[numpy.zeros(n), 1.0])[n]


def _onto_fold(at, p0, p1, s, scale):
    """(a, b, u): the fold curve's point on the hyperplane through the
    segment p0-p1's point at s normal to it, in (u, a, b) scaled by
    `scale`: Newton on (f(u), g, the hyperplane) = 0 (g: _singularity,
    bordered by the null vectors at p0).  In (u, a, b) the curve is smooth
    through a cusp, where it has a cusp in (a, b) alone."""
    z0, z1 = (numpy.r_[p[2], p[:2]] / scale for p in (p0, p1))
    along = z1 - z0
    base = z0 + s * along
    model0 = at(*p0[:2])
    q, p = _null_vectors(numpy.asarray(model0.jacobian(p0[2])))

    def residual(z):
        u, (a, b) = z[:-2] * scale[:-2], z[-2:] * scale[-2:]
        model = at(a, b)
        return numpy.r_[model.rhs(u), _singularity(numpy.asarray(model.jacobian(u)), q, p),
                        numpy.dot(z - base, along)]
    z = base.copy()
    for _ in range(NEWTON_STEPS):
        r = residual(z)
        if numpy.max(numpy.abs(r)) < NEWTON_TOL:
            u, (a, b) = z[:-2] * scale[:-2], z[-2:] * scale[-2:]
            return float(a), float(b), u
        J = numpy.column_stack([(residual(z + FD_STEP * e) - r) / FD_STEP
                                for e in numpy.eye(len(z))])
        z = z - numpy.linalg.solve(J, r)
    raise RuntimeError(f"codim2: no fold of equilibria found near "
                       f"{tuple((base[-2:] * scale[-2:]).tolist())}")


def along_fold_curve(points: Sequence[Tuple[float, float, Any]], at: Callable) -> Dict[str, List]:
    """{"a": the cusp coefficient at each stored point, "points": the cusp
    points located between them, [{"type": "CP", "a", "b", "u"}]} on a
    fold curve of equilibria: points [(a, b, state)] in order, at(a, b) ->
    the model (an mlgmodel.Model or one with .rhs, .jacobian and .form).  q is oriented along the curve by continuity."""
    points = [(float(a), float(b), numpy.asarray(u, float)) for a, b, u in points]
    values, ref = [], None
    for a, b, u in points:
        coefficient, ref = fold_coefficient(at(a, b), u, ref)
        values.append(coefficient)
    # each state component and parameter scaled by its extent along the curve
    scale = numpy.ptp(numpy.array([numpy.r_[u, a, b] for a, b, u in points]), axis=0)
    scale[scale == 0.0] = 1.0
    found = []
    for k in range(len(points) - 1):
        if numpy.sign(values[k]) * numpy.sign(values[k + 1]) >= 0:
            continue
        _, ref = fold_coefficient(at(*points[k][:2]), points[k][2])

        def sign(s):
            a, b, u = _onto_fold(at, points[k], points[k + 1], s, scale)
            return numpy.sign(fold_coefficient(at(a, b), u, ref)[0])
        first = sign(0.0)
        s = spectrum.bisect(lambda s: sign(s) == first, 0.0, 1.0, tol=TOL)
        a, b, u = _onto_fold(at, points[k], points[k + 1], s, scale)
        found.append({"type": "CP", "a": a, "b": b, "u": u.tolist()})
    return {"a": values, "points": found}
