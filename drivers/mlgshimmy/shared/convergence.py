"""The order p of a convergence X(r) -> X(0), from |X(r) - X(0)| ~ C r^p:
a least-squares fit of log|error| against log r over the ratios r where
the error stands above a floor (below it: round-off, or the law is exact
there).  No AUTO, no library."""
import math
from typing import Dict, Optional, Sequence


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
