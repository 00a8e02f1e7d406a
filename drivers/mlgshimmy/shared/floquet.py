"""Floquet multipliers of AUTO's periodic-orbit runs, read from the d-file,
and the torus (Neimark-Sacker) crossings found from them.

AUTO 0.9.2 labels a TR point only when its count of multipliers inside the
unit circle (tolerance 1e-5 on |z|) changes at the same step as the sign of
its test function |mu_2| - 1 (periodic.f90, FNSPBV: otherwise the type gets
a trailing 0 and is dropped).  On the MLG orbits the critical pair moves
through |z| = 1 by only ~1e-5 per m/s, so most crossings go unlabelled (at
F* = 0.2 the count changes 1.2 m/s after the sign).  The crossings are
therefore found here, from the multipliers of every step.
"""
import math
import re
from typing import Dict, List, Sequence, Tuple

import numpy

_ITERATION = re.compile(r"^\s*-?\d+\s+-?\d+\s+\d+\s+(\S+)\s+\S+\s*$")
_MULTIPLIER = re.compile(r"^\s*-?\d+\s+(-?\d+)\s+Multiplier\s+\d+\s+(\S+)\s+(\S+)\s+Abs")

COMPLEX = 3e-3    # |Im mu| above this: a complex pair (AUTO: sqrt(EPSS))
HUGE = 1.79769e308  # Fortran's HUGE(1.0D0) as AUTO prints it (6 digits)


def fortran_number(text: str) -> float:
    """A number as AUTO's Fortran writes it: 1.5D+02, and 1.5+288 where a
    three-digit exponent leaves no room for the E."""
    return float(re.sub(r"(?<=[0-9.])([+-]\d+)$", r"E\1", text.replace("D", "E"))
                 if "E" not in text.upper().replace("D", "E") else text.replace("D", "E"))


def multiplier(re_text: str, im_text: str) -> complex:
    """A multiplier of a d-file; AUTO writes an infinite one (where the
    monodromy's solve breaks down, FLOWKM) as CMPLX(HUGE, HUGE),
    1.79769+308 twice: it is read as a real infinity, not a complex pair."""
    re_part, im_part = fortran_number(re_text), fortran_number(im_text)
    if abs(re_part) >= HUGE and abs(im_part) >= HUGE:
        return complex(math.inf, 0.0)
    return complex(re_part, im_part)


def read(path: str) -> List[Tuple[float, numpy.ndarray]]:
    """[(parameter value, multipliers as complex array)] per point of the
    branch in the d-file at path, in branch order (read_points)."""
    points = read_points(path)
    return [points[k] for k in sorted(points)]


def read_points(path: str) -> Dict[int, Tuple[float, numpy.ndarray]]:
    """{point number: (parameter value, multipliers)} of the d-file at path,
    the point numbers as the b-file's PT.  AUTO writes a block for each
    Newton solve; while it locates a special point it solves several times
    for one point number, and the last block is the point kept.  A block
    of placeholders (every multiplier exactly 1) is no point: AUTO writes
    one for the MX point of a run whose last Newton solve diverged, with
    that solve's iterate as the parameter value."""
    points, value, last_value, current, point = {}, None, None, [], None

    def keep():
        if current and any(mu != 1.0 for mu in current):
            points[point] = (last_value, numpy.array(current))

    with open(path) as f:
        for line in f:
            m = _MULTIPLIER.match(line)
            if m:
                point = abs(int(m.group(1)))
                current.append(multiplier(m.group(2), m.group(3)))
                continue
            m = _ITERATION.match(line)
            if m:
                keep()
                current = []
                value = fortran_number(m.group(1))
            last_value = value
    keep()
    return points


def critical(mults: numpy.ndarray) -> Tuple[float, float]:
    """The complex multiplier of largest modulus, the trivial one (nearest 1)
    left out: (|mu| - 1, angle in rad)."""
    rest = numpy.delete(mults, numpy.argmin(numpy.abs(mults - 1.0)))
    pairs = rest[numpy.abs(rest.imag) > COMPLEX]
    if len(pairs) == 0:
        return -1.0, 0.0
    mu = pairs[numpy.argmax(numpy.abs(pairs))]
    return abs(mu) - 1.0, abs(numpy.angle(mu))


def torus_crossings(steps: Sequence[Tuple[float, numpy.ndarray]]) -> List[Dict[str, object]]:
    """Where a complex pair crosses the unit circle between two steps:
    [{"value", "angle", "direction", "slope_per_unit", "between"}], the
    value and angle interpolated linearly in |mu| - 1 between the two
    steps' values `between`; direction +1 = leaves (the orbit loses
    stability), -1 = enters."""
    out = []
    previous = None
    for value, mults in steps:
        g, angle = critical(mults)
        if previous is not None and (previous[1] < 0) != (g < 0) and previous[0] != value:
            v0, g0, a0 = previous
            s = g0 / (g0 - g)
            out.append({"value": v0 + s * (value - v0), "angle": a0 + s * (angle - a0),
                        "direction": 1 if g > g0 else -1,
                        "slope_per_unit": (g - g0) / (value - v0), "between": (v0, value)})
        previous = (value, g, angle)
    return out
