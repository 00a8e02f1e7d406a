"""The spectrum of straight rolling from the exact Jacobian of the c/
library (ctypes and numpy only, no AUTO): eigenvalue scans along a
parameter, stability changes located by bisection, growth rates by mode.

    changes = stability_changes("figures", "V", grid, Fstar=1.0)
    hopf = hopf_scan("figures", "V", grid, Fstar=1.0)     # [(V, Hz)]

AUTO's Hopf test function follows the eigenvalue nearest the imaginary
axis; on this model that is usually the lightly damped axial pair
(Re ~ -0.016), so AUTO misses a torsional crossing unless a step lands
within |Re| < 0.016 of it.  These scans find every crossing;
continuation.hopf_point then has AUTO locate it.
"""
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import mlgmodel


def eigenvalues(model: mlgmodel.Model, u: Optional[dict] = None) -> numpy.ndarray:
    """Eigenvalues of the Jacobian at the state u (default: the model's
    straight-rolling equilibrium)."""
    u = model.equilibrium() if u is None else u
    return numpy.linalg.eigvals(numpy.array(model.jacobian(u)))


def bisect(same_as_lo: Callable[[float], bool], lo: float, hi: float, tol: float = 0.0,
           steps: int = 60, split: float = 0.5) -> float:
    """Midpoint of [lo, hi] after cutting it `steps` times (or until it is no
    wider than tol), keeping lo where same_as_lo() holds; each cut at
    `split` of the bracket from lo (0.5: halving)."""
    if not 0.0 < split < 1.0:
        raise ValueError(f"bisect: split = {split} must lie between 0 and 1")
    for _ in range(steps):
        if hi - lo <= tol:
            break
        mid = lo + split * (hi - lo)
        if same_as_lo(mid):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def root(f: Callable[[float], float], lo: float, hi: float, f_lo: float, f_hi: float,
         tol: float = 0.0, steps: int = 200) -> float:
    """Where the continuous f changes sign (f > 0 against f <= 0) in
    [lo, hi], f_lo and f_hi its values there: the bracket narrowed to tol
    by regula falsi with the Illinois rule (the end that stays has its
    value halved), with a halving step wherever a value is not finite or
    three steps did not halve the bracket; its midpoint, as bisect gives
    it, in far fewer evaluations of f."""
    side, checkpoint = 0, hi - lo
    for k in range(steps):
        if hi - lo <= tol:
            break
        # every third step: a halving if the last three did not halve the bracket
        slow = k % 3 == 2 and hi - lo > 0.5 * checkpoint
        if k % 3 == 2:
            checkpoint = hi - lo
        secant = not slow and numpy.isfinite(f_lo) and numpy.isfinite(f_hi) and f_hi != f_lo
        x = hi - f_hi * (hi - lo) / (f_hi - f_lo) if secant else 0.5 * (lo + hi)
        x = min(max(x, lo + 0.25 * tol), hi - 0.25 * tol)
        f_x = f(x)
        if (f_x > 0) == (f_lo > 0):
            lo, f_lo = x, f_x
            f_hi, side = (0.5 * f_hi if side == -1 else f_hi), -1
        else:
            hi, f_hi = x, f_x
            f_lo, side = (0.5 * f_lo if side == 1 else f_lo), 1
    return 0.5 * (lo + hi)


def _unstable(parameter_set, values, u=None):
    """(number of real, number of complex eigenvalues with Re > 0, eigenvalues)
    at the state u (default: the model's straight-rolling equilibrium)."""
    eig = eigenvalues(mlgmodel.Model(parameter_set, **values), u)
    real = numpy.abs(eig.imag) <= 1e-9 * numpy.maximum(1.0, numpy.abs(eig.real))
    return int(numpy.sum(real & (eig.real > 0))), int(numpy.sum(~real & (eig.real > 0))), eig


def stability_changes(parameter_set: str, parameter: str, grid: Sequence[float],
                      state: Optional[Callable[[float], dict]] = None,
                      **values: float) -> List[Tuple[float, str, float]]:
    """Where straight rolling changes stability along `grid` of `parameter`,
    refined by bisection (60 halvings of a grid step): [(value, kind, freq_hz)],
    kind "HB" (complex pair, freq_hz its frequency |Im|/2pi in Hz) or "BP"
    (real eigenvalue, 0 Hz).  state(value): the state of straight rolling there,
    where Newton from psi = 0 may miss it (shared.stationary)."""
    def counts(value):
        return _unstable(parameter_set, {**values, parameter: value},
                         state(value) if state else None)

    changes = []
    previous, before = grid[0], counts(grid[0])[:2]
    for value in grid[1:]:
        now = counts(value)[:2]
        for kind, k in (("BP", 0), ("HB", 1)):
            if now[k] == before[k]:
                continue
            at = bisect(lambda v: counts(v)[k] == before[k], previous, value)
            eig = counts(at)[2]
            critical = eig[numpy.argmin(numpy.abs(eig.real))]
            hz = abs(critical.imag) / (2 * numpy.pi) if kind == "HB" else 0.0
            changes.append((at, kind, hz))
        previous, before = value, now
    return sorted(changes)


def stable_intervals(parameter_set: str, parameter: str, changes: Sequence[float], lo: float,
                     hi: float, **values: float) -> List[Tuple[float, float]]:
    """[(start, end)]: the parts of [lo, hi] where straight rolling is
    stable, between its stability changes `changes` (stability_changes'
    values along the same parameter): one eigenvalue solve inside each."""
    edges = [lo] + sorted(changes) + [hi]
    out: List[Tuple[float, float]] = []
    for a, b in zip(edges, edges[1:]):
        model = mlgmodel.Model(parameter_set, **{**values, parameter: 0.5 * (a + b)})
        if eigenvalues(model).real.max() < 0:
            out.append((a, b))
    return out


def stable_before_hopf(parameter_set: str, parameter: str, grid: Sequence[float],
                       state: Optional[Callable[[float], dict]] = None,
                       **values: float) -> Optional[Tuple[float, float]]:
    """(start, end): the stretch of `grid` over which straight rolling is
    stable up to its first Hopf point (end), from its last stability change
    below it (or grid[0]); None if there is no Hopf point or straight
    rolling is unstable just below it.  Fig. 12's (a_12, b_12) where a
    stable orbit coexists over the whole stretch, as at V = 50 m/s with
    the paper's gear (fig12.bistable_interval)."""
    changes = stability_changes(parameter_set, parameter, grid, state, **values)
    hopf = [v for v, kind, _ in changes if kind == "HB"]
    if not hopf:
        return None
    start = max([v for v, _, _ in changes if v < hopf[0]], default=grid[0])
    middle = {**values, parameter: 0.5 * (start + hopf[0])}
    u = state(middle[parameter]) if state else None
    if eigenvalues(mlgmodel.Model(parameter_set, **middle), u).real.max() >= 0:
        return None
    return start, hopf[0]


def hopf_scan(parameter_set: str, parameter: str, grid: Sequence[float],
              **values: float) -> List[Tuple[float, float]]:
    """[(value, frequency in Hz)] of the Hopf points of straight rolling
    along `grid` (stability_changes, complex pairs only)."""
    return [(v, hz) for v, kind, hz
            in stability_changes(parameter_set, parameter, grid, **values) if kind == "HB"]


def growth(model: mlgmodel.Model, bands: Dict[str, Tuple[float, float]],
           u: Optional[dict] = None) -> Dict[str, float]:
    """{band: largest real part of the eigenvalues of straight rolling (or
    of the state u) whose frequency |Im|/2pi lies in (lo, hi]} for bands
    {name: (lo, hi)} (-inf if none), and "any": the largest of all."""
    u = model.equilibrium() if u is None else u
    return growths(numpy.array(model.jacobian(u))[None], bands)[0]


def growths(jacobians: numpy.ndarray, bands: Dict[str, Tuple[float, float]]) -> List[dict]:
    """growth of each of a stack of Jacobians (k x NX x NX), their
    eigenvalues in one call."""
    eig = numpy.linalg.eigvals(jacobians)
    freq = numpy.abs(eig.imag) / (2 * numpy.pi)
    out = [{"any": float(e.real.max())} for e in eig]
    for band, (lo, hi) in bands.items():
        inside = (freq > lo) & (freq <= hi)
        rates = numpy.where(inside, eig.real, -numpy.inf).max(axis=1)
        for row, rate in zip(out, rates):
            row[band] = float(rate)
    return out


def sign_changes(f: Callable[[float], float], grid: Sequence[float], tol: float = 1e-10,
                 first_only: bool = False) -> List[float]:
    """The values where f changes sign along `grid`, bisected to tol (with
    first_only, only the first)."""
    found, previous, f_prev = [], grid[0], f(grid[0])
    for x in grid[1:]:
        f_x = f(x)
        if (f_x > 0) != (f_prev > 0):
            found.append(bisect(lambda v, s=f_prev > 0: (f(v) > 0) == s, previous, x,
                                tol=tol, steps=200))
            if first_only:
                break
        previous, f_prev = x, f_x
    return found


def stable_on_grid(parameter_set: str, outer: str, outer_grid: Sequence[float], inner: str,
                   inner_grid: Sequence[float], state: Optional[Callable[[float], dict]] = None,
                   **values: float) -> numpy.ndarray:
    """[outer, inner]: True where every eigenvalue of straight rolling has a
    negative real part.  The equilibrium must not depend on the inner
    parameter (checked at both ends of its grid); it is solved once per
    outer value.  state(outer value): the state of straight rolling there
    instead (as in stability_changes; not checked)."""
    model = mlgmodel.Model(parameter_set, **values)
    stable = numpy.zeros((len(outer_grid), len(inner_grid)), dtype=bool)
    for i, x in enumerate(outer_grid):
        model.set(**{outer: x, inner: inner_grid[-1]})
        if state:
            u = state(x)
        else:
            u = model.equilibrium()
            model.set(**{inner: inner_grid[0]})
            if max(abs(a - b) for a, b in zip(u.values(), model.equilibrium().values())) > 1e-9:
                raise RuntimeError(f"straight rolling at {outer} = {x:g} depends on {inner}")
        for j, y in enumerate(inner_grid):
            model.set(**{inner: y})
            stable[i, j] = eigenvalues(model, u).real.max() < 0
    return stable
