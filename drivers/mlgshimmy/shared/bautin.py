"""The second Lyapunov coefficient l2 at a generalised Hopf (Bautin) point,
where l1 = 0: its sign says on which side of the point the fold of limit
cycles leaves, beside the Hopf curve where l1 l2 < 0 (Kuznetsov, Elements of
Applied Bifurcation Theory, 3rd ed., section 8.3).

    gh = second_lyapunov(model, u)     # u: straight rolling at the GH point
    gh.l1, gh.l2, gh.omega

The centre manifold u = u0 + H(z, zbar), H = sum c_jk z^j zbar^k (c_10 = q,
c_01 = conj q), carries the normal form z' = i omega z + g_21 z|z|^2 + g_32
z|z|^4; f(u0 + H) = H_z z' + H_zbar zbar' is solved order by order for c_jk
and the resonant g_(k+1)k (Kuznetsov, chapter 8, the critical normal forms; SIAM J. Numer.
Anal. 36 (1999) 1104, the Bautin point: g_21 = G21 / 2, g_32 = G32 / 12):

  (i omega (j - k) I - A) c_jk = R_jk - L_jk - g_jk q,

R_jk the coefficient of z^j zbar^k in sum_m F_m(H, ..., H) / m! (F_m the
m-th form: B, C, D, E) from the known c's, L_jk that of H_z z' + H_zbar
zbar' from the known c's and g's, g_jk = <p, R_jk - L_jk> where the
operator is singular (j = k + 1), c_jk then with <p, c_jk> = 0.  Then

  l1 = Re g_21 / omega  (= lyapunov.coefficient's, eq. (3.20)),
  l2 = Re g_32 / omega  (MatCont and BifurcationKit print Re G32 / 12 = omega l2).

Like l1 its value depends on the normalisation <q, q> = 1 (z scaled by s:
l2 by s^-4); its sign does not.
"""
import itertools
import math
from typing import Any, Callable, Dict, NamedTuple, Tuple

import numpy

from mlgshimmy.shared import lyapunov

# the terms of H the coefficient of z^3 zbar^2 needs (j <= 3, k <= 2), solved in
# order of degree; the others follow by conjugation (c_kj = conj c_jk)
SOLVED = ((2, 0), (1, 1), (3, 0), (2, 1), (3, 1), (2, 2), (3, 2))


class Bautin(NamedTuple):
    l1: float            # Re g_21 / omega: 0 at an exact GH point
    l2: float            # Re g_32 / omega
    omega: float         # the critical pair +- i omega [rad/s]
    g21: complex         # Kuznetsov's c1 = G21 / 2
    g32: complex         # Kuznetsov's c2 = G32 / 12


def _products(c: Dict[Tuple[int, int], numpy.ndarray], j: int, k: int, form: Callable):
    """The coefficient of z^j zbar^k in sum over m >= 2 of F_m(H, ..., H) / m!
    from the known terms c of H: each multiset of m terms whose degrees add
    to (j, k) once, weighted by its orderings / m! (the forms are symmetric)."""
    keys = [key for key in c if key[0] <= j and key[1] <= k]
    out = numpy.zeros(len(c[(1, 0)]), dtype=complex)
    for m in range(2, j + k + 1):
        for terms in itertools.combinations_with_replacement(keys, m):
            if tuple(map(sum, zip(*terms))) != (j, k):
                continue
            orderings = math.factorial(m)
            for key in set(terms):
                orderings //= math.factorial(terms.count(key))
            out += orderings / math.factorial(m) * form(*[c[key] for key in terms])
    return out


def _chain(c, g, j: int, k: int):
    """The coefficient of z^j zbar^k in H_z z' + H_zbar zbar' from the known
    terms c of H and g of the normal form but g_10 = i omega (its terms hold
    the unknown c_jk; g_jk, unknown, is not yet in g)."""
    out = numpy.zeros(len(c[(1, 0)]), dtype=complex)
    for (a, b), term in c.items():
        for (m, n), coefficient in g.items():
            if (m, n) == (1, 0):
                continue
            if (a - 1 + m, b + n) == (j, k):          # H_z z'
                out += a * coefficient * term
            if (a + n, b - 1 + m) == (j, k):          # H_zbar zbar'
                out += b * numpy.conj(coefficient) * term
    return out


def coefficients(A: numpy.ndarray, form: Callable) -> Bautin:
    """l1 and l2 where A = df/du has the pair +- i omega nearest the axis
    (lyapunov.critical_pair), form(*vectors) the multilinear forms there for
    complex arguments (B, C, D, E by the number of arguments)."""
    omega, q, p, _ = lyapunov.critical_pair(A)
    n = len(q)
    c = {(1, 0): q, (0, 1): numpy.conj(q)}
    g = {(1, 0): 1j * omega}
    for j, k in SOLVED:
        rhs = _products(c, j, k, form) - _chain(c, g, j, k)
        operator = 1j * omega * (j - k) * numpy.eye(n) - A
        if j == k + 1:     # resonant: g_jk from the solvability, c_jk with <p, c_jk> = 0
            g[(j, k)] = numpy.vdot(p, rhs)
            bordered = numpy.block([[operator, q[:, None]], [numpy.conj(p)[None, :], 0]])
            c[(j, k)] = numpy.linalg.solve(bordered, numpy.r_[rhs - g[(j, k)] * q, 0])[:n]
        else:
            c[(j, k)] = numpy.linalg.solve(operator, rhs)
        if j != k:
            c[(k, j)] = numpy.conj(c[(j, k)])
    return Bautin(g[(2, 1)].real / omega, g[(3, 2)].real / omega, omega, g[(2, 1)], g[(3, 2)])


def second_lyapunov(model: Any, u: Any) -> Bautin:
    """l1 and l2 at the equilibrium u of an mlgmodel.Model, its forms exact
    (lyapunov.exact_form: Taylor arithmetic of the c/ library)."""
    u = lyapunov.state(u)
    return coefficients(model.jacobian(u), lyapunov.exact_form(model, u))


def fold_of_cycles(l1: float, l2: float, omega: float, mu_slope: float) -> Tuple[float, float]:
    """(distance, r2): the fold of limit cycles of the truncated normal form
    r' = r (mu + omega l1 r^2 + omega l2 r^4) near a GH point, where l1 l2
    < 0: at mu = omega l1^2 / (4 l2) and r^2 = -l1 / (2 l2); distance = mu
    / mu_slope, from the Hopf point in the parameter whose d Re lambda / d
    parameter is mu_slope.  (NaN, NaN) where l1 l2 >= 0: no fold."""
    if l1 * l2 >= 0:
        return numpy.nan, numpy.nan
    return omega * l1 ** 2 / (4 * l2 * mu_slope), -l1 / (2 * l2)
