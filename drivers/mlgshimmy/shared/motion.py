"""The gear's settled motion at one (V, F*), from the time simulator: what
the animations (studies.animate) draw.

    m = settle(300.0, 1.0, freeplay.NOMINAL, "shimmy", 40.0, rundir)
    m["kind"], m["frequency_hz"], m["frames"]["psi"]   # "high", 38.5, [...]

A start (STARTS: straight rolling at this load and gear with psi displaced,
or the yawed stationary state) is simulated for t_end seconds; shared.attractor.classify names what it
settled on (a run that leaves the model's domain, a wheel lifting off, is
kind "domain", even before the classifier's windows are filled: its last
LIFTOFF_SPAN gives its numbers), and the frames are the last few periods of it, with what the
drawing needs at each (the torque-link deflection y_tlk = r_tlk psi_s, the
tyre patch lengths h_i: shared.domain.diagnose).
"""
import os
from typing import Dict, Mapping, Optional, Tuple

import numpy

from mlgshimmy.shared import attractor, domain, gear, mlgmodel, simulator, yawed

WINDOW = 5.0            # s: attractor.classify's window (as the atlas's)
TRACE_PERIODS = 12      # periods of a periodic psi(t) shown beside the frames (at
                        # least 0.5 s); of any other motion, the last WINDOW
DT_OUT = 2e-4           # s: 125 samples per period at 40 Hz
FRAMES_PER_PERIOD = 30
PERIODS = 2             # periodic shimmy: this many periods, looped
STILL_FRAMES = 12       # a stationary state: frames of it (nothing moves)
QUASI_SPAN = 0.25       # s of a quasi-periodic or unsettled motion shown
MAX_FRAMES = 120
STILL_DEFLECTION = 1e-7  # m: a tyre deflection swing below this does not move
LIFTOFF_SPAN = 0.5      # s before a wheel lifts off whose numbers are given (and
                        # the least run that is drawn) when that is before 2 WINDOW
# start: (psi displacement [rad], from the yawed state instead of straight rolling)
STARTS = {"rolling": (simulator.STARTS["rolling"], False),
          "shimmy": (simulator.STARTS["shimmy"], False),
          "yawed": (1e-5, True)}
KINDS = {"straight": "straight rolling", "yaw": "yawed (off-centre) rolling",
         "low": "low-frequency shimmy", "high": "high-frequency shimmy",
         "quasi": "quasi-periodic shimmy (a torus)", "unsettled": "not settled",
         "domain": "a wheel lifts off (the model's domain ends)"}


def _frame_times(t_end: float, kind: str, frequency_hz: float) -> numpy.ndarray:
    """The times of the frames: PERIODS periods (a loop) of a periodic
    shimmy, QUASI_SPAN seconds of any other motion, a still state's end."""
    if kind in ("straight", "yaw"):
        return numpy.full(STILL_FRAMES, t_end)
    if kind in ("low", "high") and frequency_hz > 0:
        count = PERIODS * FRAMES_PER_PERIOD
        span = PERIODS / frequency_hz
    else:
        span = QUASI_SPAN
        count = min(MAX_FRAMES, int(FRAMES_PER_PERIOD * span * max(frequency_hz, 1.0)))
    return t_end - span + span * numpy.arange(count) / count


def start_state(V: float, Fstar: float, freeplay: Mapping[str, float],
                start: str) -> Tuple[Optional[Dict[str, float]], float, Optional[Dict[str, float]]]:
    """(the state a start begins at, its psi displacement, straight rolling):
    straight rolling (None where its branch has ended: the simulator's own
    equilibrium), or the yawed stationary state of largest psi (shared.yawed);
    ValueError naming START where there is none or the name is unknown."""
    if start not in STARTS:
        raise ValueError(f"START={start!r} is not one of {', '.join(STARTS)}")
    psi0, yawed_start = STARTS[start]
    values = gear.parameters()
    straight = yawed.straight("figures", Fstar, dict(freeplay), **values)
    if not yawed_start:
        return straight, psi0, straight
    found = yawed.states("figures", Fstar, dict(freeplay), **values)["yawed"]
    if not found:
        raise ValueError(f"START=yawed: no yawed stationary state at F* = {Fstar:g} "
                         f"(V = {V:g} m/s; Fig. 12 has them between its two pitchforks)")
    return dict(zip(mlgmodel.UNAMES, map(float, found[-1]))), psi0, straight


YAWED_LOADS = numpy.round(numpy.arange(0.02, 3.5 + 1e-9, 0.01), 2)   # where yawed_load looks


def yawed_load(Fstar: float, freeplay: Mapping[str, float]) -> Optional[float]:
    """The load of YAWED_LOADS nearest Fstar at which this gear has a yawed
    stationary state (shared.yawed.states; Fstar itself if it has one),
    None if it has none at any (about 2 s at the most)."""
    values = gear.parameters()
    for load in sorted({float(Fstar), *map(float, YAWED_LOADS)},
                       key=lambda F: (abs(F - Fstar), F)):   # Fstar first, once
        if yawed.states("figures", float(load), dict(freeplay), **values)["yawed"]:
            return float(load)
    return None


def settle(V: float, Fstar: float, freeplay: Mapping[str, float], start: str, t_end: float,
           rundir: str) -> Dict[str, object]:
    """Simulate from the start (start_state) and keep the frames of what it
    settled on: {"kind", "about", "frequency_hz",
    "amplitude_rad", "psi_fp", "frames": {"t", states..., "y_tlk", "h_L",
    "h_R"}, "trace": {"t", "psi"} (TRACE_PERIODS periods, or WINDOW), "start"}."""
    values = gear.parameters()
    u0, psi0, straight = start_state(V, Fstar, freeplay, start)
    csv = os.path.join(rundir, "motion.csv")
    proc = simulator.run(csv, *simulator.start_args(V, Fstar, freeplay, u0, psi0, t_end, DT_OUT,
                                                    gear.simulator_params()))
    data = numpy.genfromtxt(csv, delimiter=",", names=True) if os.path.exists(csv) else None
    left = simulator.left_domain(proc) if proc.returncode != 0 else None
    if proc.returncode != 0 and left is None:
        raise simulator.SimulationError(f"mlg_simulate failed: {proc.stderr.strip()}")
    span = 0.0 if data is None or data.size < 2 else float(data["t"][-1] - data["t"][0])
    if span < 2 * WINDOW and (left is None or span < LIFTOFF_SPAN):
        raise RuntimeError(f"motion: the run at V = {V:g} m/s, F* = {Fstar:g} stopped at "
                           f"t = {span:g} s, before {2 * WINDOW:g} s to classify ({left})")
    psi_fp, psi_straight = yawed.reference("figures", Fstar, dict(freeplay), straight, **values)
    if span >= 2 * WINDOW:
        found = attractor.classify(data["t"], data["psi"], WINDOW, psi_fp, psi_straight)
    else:   # a wheel lifted off before the classifier's windows were filled
        near_end = data["t"] >= data["t"][-1] - LIFTOFF_SPAN
        numbers = attractor.window_numbers(data["t"][near_end], data["psi"][near_end])
        found = {"kind": "domain", "frequency_hz": numbers["frequency_hz"],
                 "amplitude_rad": numbers["amplitude"]}
    kind = "domain" if proc.returncode != 0 else found["kind"]
    t_end = float(data["t"][-1])
    times = _frame_times(t_end, kind, found["frequency_hz"])
    frames = {"t": times.tolist()}
    for name in mlgmodel.UNAMES:
        frames[name] = numpy.interp(times, data["t"], data[name]).tolist()
    model = mlgmodel.Model("figures", V=V, Fstar=Fstar, **freeplay, **values)
    extra = {"y_tlk": [], "h_L": [], "h_R": []}
    for k in range(len(times)):
        d = domain.diagnose(model, {n: frames[n][k] for n in mlgmodel.UNAMES})
        psi_s = frames["psi"][k] + frames["beta"][k] * numpy.sin(d["p"])
        extra["y_tlk"].append(d["r_tlk"] * psi_s)
        extra["h_L"].append(d["h"][0])
        extra["h_R"].append(d["h"][1])
    frames.update(extra)
    periodic = kind in ("low", "high") and found["frequency_hz"] > 0
    shown = max(0.5, TRACE_PERIODS / found["frequency_hz"]) if periodic else WINDOW
    last = data["t"] >= t_end - min(shown, WINDOW)
    step = max(1, int(round(1e-3 / DT_OUT)) if shown > 1.0 else 1)
    return {"kind": kind, "about": KINDS[kind], "frequency_hz": found["frequency_hz"],
            "modulation_hz": found.get("modulation_hz"), "amplitude_rad": found["amplitude_rad"],
            "psi_fp": psi_fp, "yfp_m": freeplay["yfp"] * 1e-3, "frames": frames,
            "trace": {"t": data["t"][last][::step].tolist(),
                      "psi": data["psi"][last][::step].tolist()},
            "start": {"name": start, "psi0": psi0, "t_end": t_end}}


def scales(frames: Mapping[str, list], angle_deg: float = 20.0,
           deflection_m: float = 0.12) -> Dict[str, float]:
    """The factors that make the motion visible, stated on every frame:
    "angle" multiplies psi, delta and beta so that the largest angle drawn
    (a swing, or psi's and delta's offset: a yawed state's) is about
    angle_deg; "deflection" the tyres' lateral deflections so that the
    largest is about deflection_m (1 where nothing moves or is offset; a
    round number, at least 1).  beta is drawn about its mean."""
    def factor(largest: float, target: float) -> float:
        if largest <= 0:
            return 1.0
        raw = max(1.0, target / largest)
        magnitude = 10 ** numpy.floor(numpy.log10(raw))
        return float(max(1.0, max(m for m in (1, 2, 5, 10) if m * magnitude <= raw) * magnitude))

    def drawn(name: str, still: float, offset: bool = True) -> float:
        values = numpy.asarray(frames[name])
        mean = float(numpy.mean(values))
        largest = max(float(numpy.max(numpy.abs(values - mean))), abs(mean) if offset else 0.0)
        return largest if largest > still else 0.0    # a stationary state's rounding
    angle = max(drawn("psi", attractor.STILL), drawn("delta", attractor.STILL),
                drawn("beta", attractor.STILL, offset=False))
    deflection = max(drawn(name, STILL_DEFLECTION) for name in ("lambda_L", "lambda_R"))
    return {"angle": factor(angle, numpy.radians(angle_deg)),
            "deflection": factor(deflection, deflection_m)}


