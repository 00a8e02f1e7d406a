"""What a time simulation settled on: the classifier of the attractor atlas.

classify(t, psi) looks at the torsion angle psi over the last 2 W seconds of a
run (two windows of W seconds, the earlier one A, the later one B) and
returns a dict with its `kind` and the measured numbers.  Kinds and criteria
(amplitude = half peak-to-peak of psi in B; thresholds are the constants
below; PSI_FP is the freeplay angle y_fp / r_tlk, about 2.1e-3 rad at 1 mm):

  straight   stationary (amplitude < STILL) at |mean psi| < CENTRE
  yaw        stationary off centre: |mean psi| >= CENTRE (the pitchfork band)
  low        periodic shimmy, dominant frequency < SPLIT_HZ (Fig. 11's
             low-frequency orbits, 1.7-4.7 Hz at F* = 1)
  high       periodic shimmy, dominant frequency >= SPLIT_HZ
  quasi      a stationary amplitude modulation: the psi peaks of B spread by
             >= MODULATED of their largest value, fill that range without a
             gap (no period-k orbit), and the spread in A and B agree; the
             modulation frequency is the envelope's strongest frequency
  unsettled  none of the above within the time limit: amplitude or mean
             differ between A and B by more than SETTLED of the amplitude, or
             the peak spread by more than SPREAD_SETTLED of itself (at least
             SPREAD_FLOOR); never guessed as anything else.  A modulation
             growing by less than SPREAD_SETTLED per window (about 2 %/s) is
             not seen: such an orbit counts as periodic
The kind `domain` (the model left its domain, e.g. a wheel lifts off) comes
from the simulator's error, not from here.  Periodic orbits whose peaks take
a few discrete values (period-k) count as low/high, with `levels` > 1.
"""
import numpy

SPLIT_HZ = 8.0        # low/high frequency boundary [Hz] (as drivers/fig11.py)
STILL = 1e-6          # psi amplitude of a stationary state [rad]
CENTRE = 1e-5         # |mean psi| of straight rolling [rad] (psi_fp ~ 2e-3)
MODULATED = 5e-3      # relative peak spread of a modulated oscillation
SETTLED = 0.01        # relative change A -> B of amplitude and mean (of the
                      # amplitude) allowed for a settled state
SPREAD_SETTLED = 0.1  # relative change A -> B of the peak spread allowed ...
SPREAD_FLOOR = 1e-5   # ... or this much absolute (the peak fit's error is
                      # < 1e-6; orbits of Fig. 11 that settle keep ~2e-5 from
                      # the axial mode, damped at only 0.016 /s)
GAP = 0.2             # a gap in the sorted peaks wider than this share of their
                      # range means discrete levels (period-k), not a torus


# Quartic through five equally spaced samples at offsets -2..2: coefficients
# c0..c4 of x(s) = sum c_k s^k are QUARTIC @ samples.
QUARTIC = numpy.linalg.inv(numpy.vander(numpy.arange(-2.0, 3.0), 5, increasing=True))


def peaks(t, x):
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


def crossings(t, x):
    """Indices and times of the upward crossings of x through its mean."""
    y = x - x.mean()
    k = numpy.nonzero((y[:-1] < 0) & (y[1:] >= 0))[0]
    return k, t[k] - y[k] * (t[k + 1] - t[k]) / (y[k + 1] - y[k])


def envelope_frequency(tp, p):
    """Strongest frequency [Hz] of the peak sequence (the modulation)."""
    grid = numpy.linspace(tp[0], tp[-1], 4 * len(tp))
    e = numpy.interp(grid, tp, p)
    spectrum = numpy.abs(numpy.fft.rfft((e - e.mean()) * numpy.hanning(len(e))))
    f = numpy.fft.rfftfreq(len(e), grid[1] - grid[0])
    return float(f[1 + numpy.argmax(spectrum[1:])])


def window_numbers(t, psi):
    """Mean, amplitude, frequency and peak statistics of one window.  The
    mean is taken over whole periods (first to last upward crossing), so
    that a part-period at the window's ends does not move it."""
    tp, p = peaks(t, psi)
    top = float(numpy.max(numpy.abs(p))) if len(p) else 0.0
    spread = float(numpy.ptp(p)) / top if len(p) > 1 and top > 0 else 0.0
    k, tc = crossings(t, psi)
    whole = psi[k[0]:k[-1]] if len(k) >= 2 else psi
    _, troughs = peaks(t, -psi)
    if len(p) and len(troughs):     # half peak-to-peak from the fitted extremes
        amplitude = 0.5 * float(numpy.max(p) + numpy.max(troughs))
    else:
        amplitude = 0.5 * float(numpy.ptp(psi))
    return {"mean": float(whole.mean()), "amplitude": amplitude,
            "frequency_hz": (len(tc) - 1) / (tc[-1] - tc[0]) if len(tc) >= 2 else 0.0,
            "peaks": (tp, p), "spread": spread}


def levels(p):
    """Number of separate values the peaks take (1 + gaps wider than GAP of
    their range)."""
    s = numpy.sort(p)
    width = s[-1] - s[0]
    return 1 + int(numpy.sum(numpy.diff(s) > GAP * width)) if width > 0 else 1


def classify(t, psi, window):
    """The kind of state reached over the last 2 * window seconds, with its
    numbers (amplitude, mean [rad], frequency, modulation [Hz])."""
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
              "change": None}
    scale = max(B["amplitude"], STILL)
    change = max(abs(B["amplitude"] - A["amplitude"]) / scale,
                 abs(B["mean"] - A["mean"]) / scale)
    result["change"] = change
    if B["amplitude"] < STILL and A["amplitude"] < 10 * STILL:
        result["frequency_hz"] = 0.0
        result["kind"] = "straight" if abs(B["mean"]) < CENTRE else "yaw"
        return result
    spread_change = abs(B["spread"] - A["spread"])
    if change > SETTLED or spread_change > max(SPREAD_SETTLED * max(A["spread"], B["spread"]),
                                               SPREAD_FLOOR):
        result["kind"] = "unsettled"
        return result
    tp, p = B["peaks"]
    result["levels"] = levels(p) if B["spread"] >= MODULATED else 1
    if B["spread"] >= MODULATED and result["levels"] == 1:
        result["kind"] = "quasi"
        result["modulation_hz"] = envelope_frequency(tp, p)
        return result
    result["kind"] = "low" if B["frequency_hz"] < SPLIT_HZ else "high"
    return result
