"""What a time simulation settled on: the classifier of the attractor atlas.

classify(t, psi) looks at the torsion angle psi over the last 2 W seconds of a
run (two windows of W seconds, the earlier one A, the later one B) and at the
trend of its modulation over the last half of the run, and returns a dict
with its `kind` and the measured numbers.  Amplitude = half peak-to-peak of
psi in B; peak spread = (largest - smallest psi peak) / largest, the size of
the modulation; psi_fp, the freeplay angle y_fp / r_tlk (the caller's), is
2.05-2.56e-3 rad at 1 mm.  The modulation's trend is the slope of log(peak spread) against
time, one spread per SPAN seconds (spread_trend, also used by torus.py to
check AUTO's Floquet rates), with its standard error sigma: growing if the
slope exceeds both RATE_MIN and SIGNIFICANT sigma, decaying if it is below
minus that, steady otherwise.  Kinds and criteria:

  straight   stationary (amplitude < STILL) within CENTRE of straight rolling:
             |mean psi - psi_straight| < CENTRE, psi_straight the caller's
             (shared.rolling: 0 at the paper's gear; with side-stay angles
             the load twists the gear and straight rolling sits off psi = 0)
  yaw        stationary off centre: |mean psi - psi_straight| >= CENTRE, or
             any stationary state where there is no straight rolling
             (psi_straight None); shared.yawed finds these states
  low        periodic shimmy that barely engages the torque link, and slow:
             amplitude below ENGAGED psi_fp and frequency below LOW_HZ
             (Fig. 11's low-frequency family, born at Hopf points below
             9.3 Hz; 1.7-14.1 Hz, at most 1.299 psi_fp on its stable part)
  high       any other periodic shimmy (the family born above 9.3 Hz and the
             large-amplitude family, 12-47 Hz).  Periodic:
             amplitude and mean settled (below), and the modulation is at
             the measurement floor (spread < SPREAD_NOISE), or decaying (a
             transient dying on a stable orbit, whatever its size), or
             steady, of at least MODULATED, with peaks at a few discrete
             values (period-k, `levels` > 1)
  quasi      a modulation that grows (spread >= SPREAD_NOISE): the orbit it
             surrounds is unstable (a Floquet pair outside the unit circle),
             so the attractor is the torus beyond it (`growing` true); or a
             steady modulation of at least MODULATED that fills its range
             without a gap (a saturated torus).  The modulation frequency is
             the envelope's strongest frequency
  unsettled  none of the above: amplitude or mean differ between A and B by
             more than SETTLED of the amplitude, or a modulation between
             SPREAD_NOISE and MODULATED with no trend (neither a clean orbit
             nor a torus yet); never guessed as anything else
The kind `domain` (the model left its domain, e.g. a wheel lifts off) comes
from the simulator's error, not from here.
"""
from __future__ import annotations

from typing import Any, Dict, Mapping, Optional, Tuple

import numpy

ENGAGED = 1.305       # low/high boundary of the amplitude / psi_fp: on the
                      # stable orbits of Fig. 11's 22 slices (F* 0.0625 -
                      # 3.375) and large family (13024 points) the low family
                      # reaches at most 1.299, the high family at least 1.309
                      # (but for 2 points at its Hopf point, 144.6 m/s); no
                      # frequency alone separates them (low up to 14.1 Hz,
                      # high from 12.2 Hz) ...
LOW_HZ = 15.0         # ... but below the slices, at F* = 0.02, the family
                      # born at the high Hopf point (10.7 Hz) shrinks to
                      # 1.11-1.28 psi_fp at V = 450-600 m/s, at 18-20 Hz
                      # (the atlas): the low family stays below 14.1 Hz
STILL = 1e-6          # psi amplitude of a stationary state [rad]
CENTRE = 1e-5         # |mean psi - psi_straight| of straight rolling [rad]
                      # (psi_fp ~ 2e-3)
MODULATED = 5e-3      # relative peak spread of a saturated torus
SETTLED = 0.01        # relative change A -> B of amplitude and mean (of the
                      # amplitude) allowed for a settled state
SPREAD_NOISE = 1e-5   # peak spread of a clean periodic orbit: stable orbits
                      # far from any bifurcation (V = 200, F* = 1) keep
                      # 2e-6 .. 5e-6 with no trend (integration and peak-fit
                      # error); below this a trend is not read
SPAN = 2.0            # s per spread sample of the trend fit (two periods of
                      # the slowest modulation, ~1 Hz, per sample)
FIT_PART = 0.5        # the trend is fitted over this last part of the run,
                      # after the other modes' transients
RATE_MIN = 1e-3       # |trend| [1/s] that counts: AUTO's Floquet rates
                      # ln|mu| f are 1e-3 .. 1e-1 /s within 1-25 m/s of the
                      # torus points; a slower trend changes the spread by
                      # < 6 % over 60 s and is not told from steady
SIGNIFICANT = 3.0     # ... and it must exceed this many standard errors
GAP = 0.2             # a gap in the sorted peaks wider than this share of their
                      # range means discrete levels (period-k), not a torus


# Quartic through five equally spaced samples at offsets -2..2: coefficients
# c0..c4 of x(s) = sum c_k s^k are QUARTIC @ samples.
QUARTIC = numpy.linalg.inv(numpy.vander(numpy.arange(-2.0, 3.0), 5, increasing=True))


def peaks(t: numpy.ndarray, x: numpy.ndarray) -> Tuple[numpy.ndarray, numpy.ndarray]:
    """Times and values of the local maxima of x (uniform samples), refined
    by the quartic through each maximum and two neighbours on either side:
    the peak error is then ~1e-7 of the amplitude at 25 samples per period
    (a parabola's, ~1e-4, would hide a slowly growing modulation)."""
    i = numpy.nonzero((x[1:-1] > x[:-2]) & (x[1:-1] >= x[2:]))[0] + 1
    i = i[(i >= 2) & (i < len(x) - 2)]
    if len(i) == 0:
        return t[:0], x[:0]
    c = numpy.stack([x[i + k] for k in range(-2, 3)]) .T @ QUARTIC.T
    s = numpy.zeros(len(i))
    for _ in range(8):                      # Newton on x'(s) = 0, from s = 0
        d1 = c[:, 1] + s * (2 * c[:, 2] + s * (3 * c[:, 3] + s * 4 * c[:, 4]))
        d2 = 2 * c[:, 2] + s * (6 * c[:, 3] + s * 12 * c[:, 4])
        s = numpy.clip(s - d1 / numpy.where(d2 < 0, d2, -1.0), -1.0, 1.0)
    value = c[:, 0] + s * (c[:, 1] + s * (c[:, 2] + s * (c[:, 3] + s * c[:, 4])))
    return t[i] + s * (t[1] - t[0]), value


def zero_crossings(t: numpy.ndarray, x: numpy.ndarray) -> Tuple[numpy.ndarray, numpy.ndarray]:
    """Indices and times of the upward crossings of x through its mean."""
    y = x - x.mean()
    k = numpy.nonzero((y[:-1] < 0) & (y[1:] >= 0))[0]
    return k, t[k] - y[k] * (t[k + 1] - t[k]) / (y[k + 1] - y[k])


def envelope_frequency(tp: numpy.ndarray, p: numpy.ndarray) -> float:
    """Strongest frequency [Hz] of the peak sequence (the modulation)."""
    grid = numpy.linspace(tp[0], tp[-1], 4 * len(tp))
    e = numpy.interp(grid, tp, p)
    spectrum = numpy.abs(numpy.fft.rfft((e - e.mean()) * numpy.hanning(len(e))))
    f = numpy.fft.rfftfreq(len(e), grid[1] - grid[0])
    return float(f[1 + numpy.argmax(spectrum[1:])])


def window_numbers(t: numpy.ndarray, psi: numpy.ndarray) -> Dict[str, Any]:
    """Mean, amplitude, frequency and peak statistics of one window.  The
    mean is taken over whole periods (first to last upward crossing), so
    that a part-period at the window's ends does not move it.  Not the
    simulator's own summary (c/simulate/mlg_simulate.c: raw extremes and
    the plain mean of its last second): the classifier compares two windows
    of its own width and needs peaks fitted between samples, which that
    one fixed window does not give."""
    tp, p = peaks(t, psi)
    top = float(numpy.max(numpy.abs(p))) if len(p) else 0.0
    spread = float(numpy.ptp(p)) / top if len(p) > 1 and top > 0 else 0.0
    k, tc = zero_crossings(t, psi)
    whole = psi[k[0]:k[-1]] if len(k) >= 2 else psi
    _, troughs = peaks(t, -psi)
    if len(p) and len(troughs):     # half peak-to-peak from the fitted extremes
        amplitude = 0.5 * float(numpy.max(p) + numpy.max(troughs))
    else:
        amplitude = 0.5 * float(numpy.ptp(psi))
    return {"mean": float(whole.mean()), "amplitude": amplitude,
            "frequency_hz": (len(tc) - 1) / (tc[-1] - tc[0]) if len(tc) >= 2 else 0.0,
            "peaks": (tp, p), "spread": spread}


def levels(p: numpy.ndarray) -> int:
    """Number of separate values the peaks take (1 + gaps wider than GAP of
    their range)."""
    s = numpy.sort(p)
    width = s[-1] - s[0]
    return 1 + int(numpy.sum(numpy.diff(s) > GAP * width)) if width > 0 else 1


def spread_trend(t: numpy.ndarray, psi: numpy.ndarray, t0: float, t1: float,
                 span: float = SPAN) -> Optional[Dict[str, float]]:
    """The modulation's trend over [t0, t1): the least-squares slope of
    log(peak spread) against time, one spread per `span` seconds, as
    {"rate" [1/s], "rate_error" (its standard error), "first", "last"
    (the first and last spread)}; None if fewer than 4 spreads fit in."""
    starts = numpy.arange(t0, t1 - span + 1e-9, span)
    if len(starts) < 4:
        return None
    times, spreads = [], []
    for a in starts:
        part = (t >= a) & (t < a + span)
        times.append(a + span / 2)
        spreads.append(window_numbers(t[part], psi[part])["spread"])
    # a spread of exactly 0 (all peaks equal to the fit's precision) is
    # floored so that the logarithm exists
    (rate, _), cov = numpy.polyfit(times, numpy.log(numpy.maximum(spreads, 1e-12)), 1,
                                   cov=True)
    return {"rate": float(rate), "rate_error": float(numpy.sqrt(cov[0, 0])),
            "first": float(spreads[0]), "last": float(spreads[-1])}


def trend_kind(fit: Optional[Mapping[str, float]]) -> Optional[str]:
    """"growing", "decaying" or "steady" (see the module's docstring);
    None without a fit."""
    if fit is None:
        return None
    bound = max(RATE_MIN, SIGNIFICANT * fit["rate_error"])
    return "growing" if fit["rate"] > bound else "decaying" if fit["rate"] < -bound else "steady"


def mode_shape(t: numpy.ndarray, psi: numpy.ndarray, other: numpy.ndarray,
               frequency: float) -> complex:
    """other's fundamental at `frequency` relative to psi's (complex: the
    amplitude ratio and the phase lead of `other`), over whole periods."""
    k, _ = zero_crossings(t, psi)
    part = slice(k[0], k[-1]) if len(k) >= 2 else slice(None)
    e = numpy.exp(-2j * numpy.pi * frequency * t[part])
    c_psi = numpy.sum((psi[part] - psi[part].mean()) * e)
    c_other = numpy.sum((other[part] - other[part].mean()) * e)
    return complex(c_other / c_psi) if c_psi != 0 else complex("nan")


def off_centre(mean: float, psi_straight: Optional[float]) -> bool:
    """Whether a stationary state of mean psi `mean` is not straight rolling
    (psi_straight, or None where there is none)."""
    return psi_straight is None or abs(mean - psi_straight) >= CENTRE


def classify(t: numpy.ndarray, psi: numpy.ndarray, window: float, psi_fp: float,
             psi_straight: Optional[float]) -> Dict[str, Any]:
    """The kind of state reached over the last 2 * window seconds, with its
    numbers (amplitude, mean [rad], frequency, modulation [Hz]); psi_fp [rad]
    is the freeplay angle (low/high), psi_straight [rad] straight rolling's
    psi at this load (straight/yaw; None: there is no straight rolling)."""
    t_end = t[-1]
    if t_end - t[0] < 2 * window - 1e-9:
        raise ValueError(f"attractor.classify: {t_end - t[0]:g} s of samples, need "
                         f"2 x window = {2 * window:g} s")
    a_part = (t >= t_end - 2 * window) & (t < t_end - window)
    b_part = t >= t_end - window
    A, B = window_numbers(t[a_part], psi[a_part]), window_numbers(t[b_part], psi[b_part])
    result = {"amplitude_rad": B["amplitude"], "mean_rad": B["mean"],
              "frequency_hz": B["frequency_hz"], "modulation_hz": None,
              "peak_spread": B["spread"], "levels": 1,
              "change": None, "trend": None, "growing": False}
    scale = max(B["amplitude"], STILL)
    change = max(abs(B["amplitude"] - A["amplitude"]) / scale,
                 abs(B["mean"] - A["mean"]) / scale)
    result["change"] = change
    if B["amplitude"] < STILL and A["amplitude"] < 10 * STILL:
        result["frequency_hz"] = 0.0
        result["kind"] = "yaw" if off_centre(B["mean"], psi_straight) else "straight"
        return result
    fit = spread_trend(t, psi, t_end - FIT_PART * (t_end - t[0]), t_end)
    trend = trend_kind(fit)
    result["trend"] = trend
    result["spread_rate"] = fit and fit["rate"]
    result["spread_rate_error"] = fit and fit["rate_error"]
    if change > SETTLED:
        result["kind"] = "unsettled"
        return result
    tp, p = B["peaks"]
    periodic = ("low" if B["amplitude"] < ENGAGED * psi_fp and B["frequency_hz"] < LOW_HZ
                else "high")
    noise = B["spread"] < SPREAD_NOISE
    if trend == "growing" and not noise:
        result.update(kind="quasi", growing=True, modulation_hz=envelope_frequency(tp, p))
    elif noise or trend == "decaying":
        result["kind"] = periodic
    elif B["spread"] >= MODULATED and trend == "steady":
        result["levels"] = levels(p)
        if result["levels"] > 1:
            result["kind"] = periodic
        else:
            result.update(kind="quasi", modulation_hz=envelope_frequency(tp, p))
    else:                           # a small steady modulation, or no fit
        result["kind"] = "unsettled"
    return result
