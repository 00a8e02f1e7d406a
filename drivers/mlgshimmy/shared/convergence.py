"""The order p of a convergence X(r) -> X(0), from |X(r) - X(0)| ~ C r^p:
a least-squares fit of log|error| against log r over the ratios r where
the error stands above a floor (below it: round-off, or the law is exact
there); and, where X(0) is not computed, X(0), C and p fitted together
(extrapolated).  No AUTO, no library."""
import math
from typing import Dict, Optional, Sequence

import numpy


def fitted_order(ratios: Sequence[float], errors: Sequence[float],
                 floor: float) -> Optional[Dict[str, float]]:
    """{"p": the fitted order, "C": the constant, "points": how many ratios
    were used} over the ratios whose |error| exceeds floor; None with fewer
    than two."""
    used = [(math.log(r), math.log(abs(e))) for r, e in zip(ratios, errors) if abs(e) > floor]
    if len(used) < 2:
        return None
    n = len(used)
    mx = sum(x for x, _ in used) / n
    my = sum(y for _, y in used) / n
    p = sum((x - mx) * (y - my) for x, y in used) / sum((x - mx) ** 2 for x, _ in used)
    return {"p": p, "C": math.exp(my - p * mx), "points": n}


def extrapolated(ratios: Sequence[float], values: Sequence[float],
                 spread: float) -> Optional[Dict[str, float]]:
    """X(0), p and C of X(r) = X(0) + C r^p fitted to values at the ratios
    (least squares, p searched on [0.25, 6]), where X(0) is not computed;
    None with fewer than four values, or if they spread by no more than
    `spread` (the resolution of X: nothing to fit)."""
    r, x = numpy.asarray(ratios, float), numpy.asarray(values, float)
    if len(r) < 4 or numpy.ptp(x) <= spread:
        return None

    def fit(p):
        A = numpy.column_stack([numpy.ones_like(r), numpy.sign(r) * r ** p])
        coef, *_ = numpy.linalg.lstsq(A, x, rcond=None)
        return float(numpy.sum((A @ coef - x) ** 2)), coef
    orders = numpy.linspace(0.25, 6.0, 2301)
    p = orders[int(numpy.argmin([fit(q)[0] for q in orders]))]
    (x0, C) = fit(p)[1]
    return {"p": float(p), "C": float(C), "limit": float(x0), "points": len(r)}
