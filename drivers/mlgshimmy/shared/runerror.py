"""The error of an AUTO run that failed, did not converge or missed a special
point, with the tail of its log."""
from __future__ import annotations

from typing import List, Optional


MX, NON_FINITE = "MX", "non-finite"   # RunError.kind of a run that did not converge


class RunError(RuntimeError):
    """An AUTO run that failed, did not converge or missed a special point.
    str() ends with the tail of the run's log; .brief is the first line;
    .kind is MX (a branch ends with no convergence), NON_FINITE (the model
    stopped the run at a non-finite solution, models/mlg.c) or None."""

    def __init__(self, message, log=None, kind=None):
        self.brief = message
        self.kind = kind
        if log:
            message += f"\n  log {log}, last lines:\n" + "".join(
                f"    | {line}" for line in tail(log))
        super().__init__(message)

    @property
    def unconverged(self) -> bool:
        """Whether AUTO's iteration failed (a smaller step or a finer mesh
        may succeed: continuation.with_ladder)."""
        return self.kind in (MX, NON_FINITE)


# the line models/mlg.c writes before it stops a run at a non-finite solution
NON_FINITE_LINE = "mlg: non-finite solution"


def non_finite_stop(log: str) -> Optional[str]:
    """The model's line saying it stopped the run at a non-finite solution
    (stripped), or None."""
    return next((line.strip() for line in tail(log, 40) if NON_FINITE_LINE in line), None)


def tail(path: str, lines: int = 15) -> List[str]:
    """The last `lines` lines of a text file ([] if it cannot be read)."""
    try:
        with open(path, errors="replace") as f:
            return f.readlines()[-lines:]
    except OSError:
        return []
