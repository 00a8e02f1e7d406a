"""The first Lyapunov coefficient l1 at a Hopf point: its sign says whether
the orbits born there are stable (l1 < 0, supercritical) or unstable
(l1 > 0, subcritical), from the vector field's derivatives at the
equilibrium alone (numpy and the c/ library, no AUTO).

    model = Model("figures", Fstar=1.0, yfp=1.0, eps_rel=0.1, V=144.26969033)
    hopf = first_lyapunov(model, model.equilibrium())   # H3
    hopf.l1, hopf.omega    # 0.0338 (> 0: subcritical), 82.2 rad/s

Kuznetsov, Elements of Applied Bifurcation Theory (3rd ed.), section 3.5,
eq. (3.20): coefficient(A, B, C).  first_lyapunov takes the forms B and C
exact to rounding from the c/ library (Model.form: Taylor arithmetic,
c/vector_field_taylor.c); by_differences takes them
from central differences of the exact Jacobian, for a model that has only
.jacobian(u) and as the independent check of the exact forms.

f need only be smooth along q: the oleo's quadratic damping |eta'| eta'
is not at eta' = 0, but the critical modes of straight rolling have no axial
part (q_eta = q_eta' = 0), so f is differentiated only where it is smooth.
"""
from __future__ import annotations

import itertools
from typing import Any, Callable, NamedTuple, Tuple

import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import mlgmodel

# by_differences: steps tried, along directions scaled to max-norm 1 in the state's units
# (rad, m, rad/s, m/s).  No one step serves every Hopf point: with freeplay
# the link law (15) changes its curvature over psi ~ eps / r_tlk ~ 2e-4 rad,
# so the truncation error (falling as h^2) needs psi steps of a few 1e-7 rad,
# while at zero freeplay l1 is 1e5 times smaller and the rounding of J
# divided by h^2 needs h near 1e-3.  by_differences takes the step where
# three successive halvings agree best, where truncation meets rounding.
# The last step, 7.6e-8, stops where a field varying on unit scales keeps
# two digits in C (rounding eps |J| / h^2 ~ 1e-2 |J|); below it the
# differences of J round to steady wrong values that would agree.
STEPS = 1e-2 * 0.5 ** numpy.arange(18)


class Hopf(NamedTuple):
    l1: float              # Kuznetsov's first Lyapunov coefficient, eq. (3.20)
    omega: float           # the critical pair +- i omega [rad/s]
    q: numpy.ndarray       # A q = i omega q, <q, q> = 1
    p: numpy.ndarray       # A^T p = -i omega p, <p, q> = 1
    real_part: float       # Re of the pair used (0 at an exact Hopf point)
    h: float = numpy.nan   # by_differences: the step of B and C
    spread: float = numpy.nan  # by_differences: max - min of l1 over the steps 2h, h, h/2


def _directional(model, u, x, h):
    """d/ds J(u + s x) at s = 0 for a real direction x, by the central
    difference (J(u + h d) - J(u - h d)) / 2h along d = x / max|x|
    (then scaled back), error O(h^2)."""
    size = numpy.max(numpy.abs(x))
    if size == 0.0:
        return numpy.zeros((len(u), len(u)))
    d = h * x / size
    return (model.jacobian(u + d) - model.jacobian(u - d)) * (size / (2 * h))


def _mixed(model, u, x, y, h):
    """d^2/ds dt J(u + s x + t y) at 0 for real x, y, by the four-point
    central difference (x, y each scaled to max-norm 1, then back)."""
    sx, sy = numpy.max(numpy.abs(x)), numpy.max(numpy.abs(y))
    if sx == 0.0 or sy == 0.0:
        return numpy.zeros((len(u), len(u)))
    a, b = h * x / sx, h * y / sy
    J = model.jacobian
    return (J(u + a + b) - J(u + a - b) - J(u - a + b) + J(u - a - b)) * (sx * sy / (4 * h * h))


def complex_form(real_form: Callable) -> Callable:
    """A multilinear form of complex vectors from its values at real ones:
    each argument split into its real and imaginary parts,
    F(x, y, ...) = sum over the parts of i^(number of imaginary parts) F(parts)."""
    def form(*vectors):
        vectors = [numpy.asarray(v, dtype=complex) for v in vectors]
        out = numpy.zeros(len(vectors[0]), dtype=complex)
        for parts in itertools.product((0, 1), repeat=len(vectors)):
            real = [v.imag if part else v.real for v, part in zip(vectors, parts)]
            if all(numpy.any(r) for r in real):   # a zero part adds nothing
                out += 1j ** sum(parts) * numpy.asarray(real_form(*real))
        return out
    return form


def exact_form(model: Any, u: ArrayLike) -> Callable:
    """The multilinear forms at u for complex arguments, exact to rounding:
    F(x, y) = B, F(x, y, z) = C, ... by the number of arguments (the c/
    library's real forms, Model.form)."""
    u = numpy.asarray(u, dtype=float)
    return complex_form(lambda *vectors: model.form(u, *vectors))


def difference_forms(model: Any, u: ArrayLike, h: float) -> Tuple[Callable, Callable]:
    """(B, C) at u for complex arguments from central differences of the
    exact Jacobian, step h: B(x, y) = d/ds J(u + s x) y, C(x, y, z) =
    d2/ds dt J(u + s x + t y) z."""
    u = numpy.asarray(u, dtype=float)
    return (complex_form(lambda x, y: _directional(model, u, x, h) @ y),
            complex_form(lambda x, y, z: _mixed(model, u, x, y, h) @ z))


def critical_pair(A: numpy.ndarray) -> Tuple[float, numpy.ndarray, numpy.ndarray, float]:
    """(omega, q, p, Re lambda) of the eigenvalue lambda of A nearest the
    imaginary axis with Im lambda > 0: A q = lambda q, <q, q> = 1, and the
    left eigenvector p (A^T p = conj(lambda) p) with <p, q> = conj(p) . q = 1."""
    eig, vec = numpy.linalg.eig(A)
    upper = numpy.flatnonzero(eig.imag > 0)
    k = upper[numpy.argmin(numpy.abs(eig.real[upper]))]
    lam, q = eig[k], vec[:, k] / numpy.linalg.norm(vec[:, k])
    eig_t, vec_t = numpy.linalg.eig(A.T)
    p = vec_t[:, numpy.argmin(numpy.abs(eig_t - numpy.conj(lam)))]
    return lam.imag, q, p / numpy.conj(numpy.vdot(p, q)), lam.real


def coefficient(A: numpy.ndarray, B: Callable, C: Callable) -> Hopf:
    """Kuznetsov's l1 where A = df/du has the pair +- i omega nearest the
    axis (its small real part is ignored), B and C the forms there:

      l1 = 1/(2 omega) Re[<p, C(q,q,qbar)> - 2 <p, B(q, A^-1 B(q,qbar))>
                          + <p, B(qbar, (2 i omega I - A)^-1 B(q,q))>]   (3.20)

    with <a, b> = conj(a) . b."""
    omega, q, p, real_part = critical_pair(A)
    qbar = numpy.conj(q)
    resonant = numpy.linalg.solve(2j * omega * numpy.eye(len(q)) - A, B(q, q))
    bracket = (numpy.vdot(p, C(q, q, qbar))
               - 2 * numpy.vdot(p, B(q, numpy.linalg.solve(A, B(q, qbar))))
               + numpy.vdot(p, B(qbar, resonant)))
    return Hopf(bracket.real / (2 * omega), omega, q, p, real_part)


def state(u: Any) -> numpy.ndarray:
    """u as an array, from a sequence or {state name: value}."""
    if isinstance(u, dict):
        u = [u[name] for name in mlgmodel.UNAMES]
    return numpy.asarray(u, dtype=float)


def first_lyapunov(model: Any, u: Any) -> Hopf:
    """l1 at the equilibrium u (a sequence or {state name: value}) of a
    model with exact forms (an mlgmodel.Model)."""
    u = state(u)
    form = exact_form(model, u)
    return coefficient(model.jacobian(u), form, form)


def at_step(model: Any, u: Any, h: float) -> Hopf:
    """coefficient() with B and C by central differences of step h."""
    u = state(u)
    hopf = coefficient(model.jacobian(u), *difference_forms(model, u, h))
    return hopf._replace(h=h)


def by_differences(model: Any, u: Any, steps: ArrayLike = STEPS) -> Hopf:
    """l1 at the equilibrium u (at_step) for each of `steps` (decreasing by
    halves), kept at the step whose value and its two neighbours' differ
    least relative to their size: their spread is the error estimate.
    Relative, because a field whose cubic terms round away gives l1 = 0 at
    every step.  A step that takes the state out of the model's domain
    is passed over."""
    found = []
    for h in steps:
        try:
            found.append(at_step(model, u, h))
        except RuntimeError:
            continue
    if len(found) < 3:
        raise RuntimeError(f"lyapunov: only {len(found)} of the steps stay in the model's domain")
    triples = [numpy.array([hopf.l1 for hopf in found[k - 1:k + 2]])
               for k in range(1, len(found) - 1)]
    spread = [numpy.ptp(t) for t in triples]
    relative = [s / numpy.max(numpy.abs(t)) if numpy.any(t) else numpy.inf
                for s, t in zip(spread, triples)]
    k = int(numpy.argmin(relative))
    return found[k + 1]._replace(spread=spread[k])


# angles of the trapezoid rule in kink_coefficient: 64 and 256 agree to
# 2e-6 of a2 at the Hopf points of Fig. 12 at (-10, 20) deg
KINK_STEPS = 64


def kink_coefficient(model: Any, u: Any, hopf: Hopf, steps: int = KINK_STEPS) -> complex:
    """a2 of the normal form z' = (mu + i omega) z + a2 |z| z + c1 |z|^2 z
    where f has a kink on the critical plane (the oleo's |eta'| eta' at
    eta' = 0, when q moves eta'): the first harmonic of the one-sided
    second-order term (1/2) D^2 f[x] along x(theta) = 2 Re(q e^(i theta))
    (Model.taylor), a2 = mean over theta of <p, (1/2) D^2 f[x]> e^(-i theta).
    Zero where f is twice differentiable there: B(x, x) has harmonics 0 and
    2 only.  With r = |z|: r' = mu r + Re(a2) r^2 + omega l1 r^3, so for
    small r Re a2 < 0 stabilises (supercritical), whatever l1 says."""
    u = state(u)
    theta = 2 * numpy.pi * numpy.arange(steps) / steps
    planar = [2 * numpy.real(hopf.q * numpy.exp(1j * t)) for t in theta]
    terms = [numpy.vdot(hopf.p, 0.5 * model.taylor(u, x)[2]) * numpy.exp(-1j * t)
             for x, t in zip(planar, theta)]
    return complex(numpy.mean(terms))


def kink_amplitude(hopf: Hopf, a2: complex) -> float:
    """The psi amplitude up to which the kink's quadratic term Re(a2) r^2
    outweighs the cubic omega l1 r^3 (r' = mu r + Re(a2) r^2 + omega l1 r^3,
    psi = 2 |q_psi| r): 2 |q_psi| |Re a2| / (omega |l1|)."""
    return float(2 * abs(hopf.q[0]) * abs(a2.real) / (hopf.omega * abs(hopf.l1)))


def amplitude(hopf: Hopf, mu: float) -> numpy.ndarray:
    """Half the peak-to-peak swing of each state, to leading order, on the
    orbit where the pair's real part is mu: the normal form
    z' = (mu + i omega) z + c1 z|z|^2 with Re c1 = omega l1 has the circle
    |z|^2 = -mu / (omega l1), and u(t) = u + 2 Re(z q), so 2 |q_i| |z|;
    NaN where mu / l1 > 0 (no orbit on that side)."""
    rho2 = -mu / (hopf.omega * hopf.l1)
    return 2 * numpy.abs(hopf.q) * (numpy.sqrt(rho2) if rho2 >= 0 else numpy.nan)
