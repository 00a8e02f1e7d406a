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

points: [(a, b)] of the curve in its two parameters, in order; at(a, b)
-> (model, u): the mlgmodel.Model and straight rolling's state there.  A
sign change between two stored points is bisected along the segment
joining them, each trial point moved back onto the curve along the
segment's normal (Re of the critical pair = 0), until the segment is
TOL of the curve's extent.  l2 at a GH point is not computed (it needs
fifth derivatives): its sign data instead, dl1/db between the stored points
that bracket it (the side of the GH point where the Hopf points are
subcritical).  kink(model, u): the oleo kink's a2 at a point of the curve
(where the mode moves eta', a2 decides the criticality up to an amplitude,
and l1 = 0 is then the one-sided expansion's).
"""
from typing import Callable, Dict, List, Sequence, Tuple

import numpy

from mlgshimmy.shared import lyapunov, spectrum

TOL = 1e-8       # of the curve's extent in each parameter
TYPES = ("GH", "BT", "ZH", "HH")


def kink(model, u):
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


def tests(model, u) -> Dict[str, float]:
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


def locate(at, p0, p1, kind: str, scale, along: int) -> Tuple[float, float]:
    """The point between stored points p0 and p1 where test `kind` is 0."""
    def sign(s):
        return numpy.sign(tests(*at(*_onto_curve(at, p0, p1, s, scale, along)))[kind])
    first = sign(0.0)
    s = spectrum.bisect(lambda s: sign(s) == first, 0.0, 1.0, tol=TOL)
    return _onto_curve(at, p0, p1, s, scale, along)


def along_hopf_curve(points: Sequence[Tuple[float, float]], at: Callable,
                     along: int = 0) -> Dict[str, List]:
    """{"l1", "omega": at each stored point, "points": the codimension-two
    points located between them, [{"type", "a", "b", "omega", "l1"}]};
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
                a, b = locate(at, points[k], points[k + 1], kind, scale, along)
                there = tests(*at(a, b))
                point = {"type": kind, "a": a, "b": b, "omega": there["omega"],
                         "l1": there["GH"]}
                if kind == "GH":
                    rise = values[k + 1]["GH"] - values[k]["GH"]
                    step = points[k + 1][1] - points[k][1]
                    point["dl1_db"] = rise / step if step else numpy.copysign(numpy.inf, rise)
                found.append(point)
    return {"l1": [v["GH"] for v in values], "omega": [v["omega"] for v in values],
            "points": found}
