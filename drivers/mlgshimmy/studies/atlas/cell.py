"""One cell of the attractor atlas (mlgshimmy.studies.atlas): simulations of the
MLG model from each of STARTS at one (V, F*), y_fp = 1 mm, epsilon = 0.1 mm
(freeplay.NOMINAL), `figures` set, each end state classified by shared.attractor.
A start not settled after STAGES[0] seconds (or whose small modulation
grows: confirmed()) is run again for STAGES[1]; still unsettled, for
SETTLE; then it is reported as such.  A start that leaves the domain
keeps what it was doing until then (`before`), and a shimmy end keeps the
lateral and tyre motion relative to psi (end_state), so that a new rule
for a kind can be applied to stored cells.
"""
from __future__ import annotations

import functools
import os
import resource
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import attractor
from mlgshimmy.shared import freeplay, simulator, gear
from mlgshimmy.shared import yawed

FREEPLAY = freeplay.NOMINAL      # y_fp = 1 mm, eps = 0.1 mm (Fig. 11)

# The starts (simulator.STARTS).  One outside the model's domain at t = 0
# (at F* = 0.02 a wheel lifts off at psi = 0.05) is halved until it is
# inside; the psi0 used is recorded.
# At side-stay angles the gear is not mirror-symmetric and a yawed state on
# one side need not have a mirror image on the other: a start yawed the
# other way too.  (At rho = mu = 0 it would end on the mirror image of the
# "yawed" start's end, the same kind.)
STARTS = dict(simulator.STARTS, **({} if gear.current().symmetric
                                    else {"yawed_other": -simulator.STARTS["yawed"]}))
STAGES = (40.0, 120.0)           # time limits [s], the second only if needed
SETTLE = 360.0                   # s: the limit of a start still not settled after them:
                                 # at side-stay angles the psi = 0.05 start excites the
                                 # axial mode (0.6 Hz, decaying at 0.017 /s), still
                                 # 2e-6 rad in psi at 120 s at low speed (V <= 50)
WINDOW = 5.0                     # attractor.classify's window [s]
DT_OUT = 1e-3                    # sampling [s]: 25 samples per 40 Hz period


@functools.lru_cache(maxsize=None)
def straight_rolling(fstar: float) -> Optional[Dict[str, float]]:
    """Straight rolling at this load and the run's geometry (shared.yawed:
    continued from zero freeplay), {name: value}, or None where there is
    none (its branch ended in a fold of y_fp)."""
    return yawed.straight("figures", fstar, FREEPLAY, **gear.parameters())


def simulator_args(v: float, fstar: float, psi0: float, t_end: float) -> List[Any]:
    """The simulator's options for one start: straight rolling (given as
    --u0: at side-stay angles the simulator's own Newton from psi = 0 can
    fail or land on a yawed state; without straight rolling the simulator's
    equilibrium) with psi displaced by psi0, for the gear of the run
    (shared.gear; nothing at the paper's)."""
    return simulator.start_args(v, fstar, FREEPLAY, straight_rolling(fstar), psi0, t_end,
                                DT_OUT, gear.simulator_params())


def discard(path: str) -> None:
    if os.path.exists(path):
        os.remove(path)


def inside_start(v: float, fstar: float, psi0: float, csv: str) -> float:
    """psi0, halved until the initial state is inside the model's domain."""
    for _ in range(20):
        proc = simulator.run(csv, *simulator_args(v, fstar, psi0, DT_OUT))
        if proc.returncode == 0 or simulator.left_domain(proc) is None:
            discard(csv)
            return psi0
        psi0 *= 0.5
    discard(csv)
    raise RuntimeError(f"atlas: no start inside the domain at V = {v:g}, F* = {fstar:g}")


def read_run(csv: str) -> Optional[numpy.ndarray]:
    """t, psi, delta, lambda_L of the simulator's samples (of a run that left
    the domain: those up to then), or None if there are none."""
    try:
        data = numpy.loadtxt(csv, delimiter=",", skiprows=1, usecols=(0, 1, 2, 9), ndmin=2)
    except (OSError, ValueError):
        return None
    return data if len(data) else None


def reference(fstar: float) -> Tuple[float, Optional[float]]:
    """(psi_fp, psi_straight) [rad] at this load (yawed.reference)."""
    return yawed.reference("figures", fstar, FREEPLAY, straight_rolling(fstar),
                           **gear.parameters())


def end_state(data: numpy.ndarray, fstar: float) -> Dict[str, Any]:
    """attractor.classify of the samples at this load (reference), with the
    lateral (delta) and tyre (lambda_L) motion relative to psi at the orbit's
    frequency as [amplitude ratio, phase lead in degrees] for a shimmy end."""
    t, psi = data[:, 0], data[:, 1]
    result = attractor.classify(t, psi, WINDOW, *reference(fstar))
    if result["frequency_hz"] > 0:
        last = t >= t[-1] - WINDOW
        for name, col in (("delta_over_psi", 2), ("lambda_over_psi", 3)):
            ratio = attractor.mode_shape(t[last], psi[last], data[last, col],
                                         result["frequency_hz"])
            result[name] = [abs(ratio), float(numpy.degrees(numpy.angle(ratio)))]
    return result


def run_stage(v: float, fstar: float, psi0: float, t_end: float, rundir: str) -> Dict[str, Any]:
    """Simulate t_end seconds from psi0 and classify the end state
    (end_state; `domain` if the model leaves its domain, with `before`: the
    state classified over the samples up to then, if there are 2 WINDOW
    seconds of them)."""
    csv = os.path.join(rundir, "run.csv")
    proc = simulator.run(csv, *simulator_args(v, fstar, psi0, t_end))
    data = read_run(csv)
    discard(csv)
    if proc.returncode != 0:
        reason = simulator.left_domain(proc)
        if reason is None:
            raise RuntimeError(f"atlas: mlg_simulate failed at V = {v:g}, F* = {fstar:g}, "
                               f"psi0 = {psi0:g}: {proc.stderr.strip()}")
        result = {"kind": "domain", "t_end": t_end, "psi0": psi0, "reason": reason,
                  "before": None}
        if data is not None and data[-1, 0] - data[0, 0] >= 2 * WINDOW:
            result["before"] = end_state(data, fstar)
            result["before"]["t_end"] = float(data[-1, 0])
        return result
    if data is None or data[-1, 0] < t_end - 1e-9:
        raise RuntimeError(f"atlas: the run stopped at t = "
                           f"{0 if data is None else data[-1, 0]:g} s of {t_end:g}")
    result = end_state(data, fstar)
    result.update(t_end=t_end, psi0=psi0)
    return result


def confirmed(result: Mapping[str, Any]) -> bool:
    """Whether a stage's end state stands.  Not when unsettled; nor when a
    modulation still below attractor.MODULATED grows: over the first stage
    that can be a transient (at V = 250, F* = 0.02 a start's spread grew at
    0.013 /s over 20-40 s at 1e-4, while the same orbit's decays at
    -0.017 /s over 60-120 s), so the growth must last to the last stage."""
    if result["kind"] == "unsettled":
        return False
    return not (result.get("growing") and result["peak_spread"] < attractor.MODULATED)


def simulate_start(v: float, fstar: float, psi0: float, rundir: str) -> Dict[str, Any]:
    """Classify one start: the first stage whose end state is confirmed,
    else what the last stage shows, run for SETTLE if that is unsettled."""
    psi0 = inside_start(v, fstar, psi0, os.path.join(rundir, "probe.csv"))
    for t_end in STAGES:
        result = run_stage(v, fstar, psi0, t_end, rundir)
        if confirmed(result):
            break
    if result["kind"] == "unsettled":
        result = run_stage(v, fstar, psi0, SETTLE, rundir)
    return result


def cell(v: float, fstar: float, rundir: str) -> Dict[str, Any]:
    """The cell's result: every start's end state, the cell's label and the
    CPU time its simulations took."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    starts = {start: simulate_start(v, fstar, psi0, rundir) for start, psi0 in STARTS.items()}
    # An orbit next to a torus attractor may be weakly unstable, its
    # modulation growing too slowly to show within the first limit: when a
    # start ends quasi-periodic, every periodic end is checked over the last.
    if any(s["kind"] == "quasi" for s in starts.values()):
        for start, s in starts.items():
            if s["kind"] in ("low", "high") and s["t_end"] < STAGES[-1]:
                starts[start] = run_stage(v, fstar, s["psi0"], STAGES[-1], rundir)
    unstable_orbits(starts)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    return {"V": v, "Fstar": fstar, "starts": starts, "label": label(starts),
            "cpu_seconds": round(cpu, 2)}


def unstable_orbits(starts: Dict[str, Dict[str, Any]]) -> None:
    """A start that sits on a periodic orbit with its modulation at the
    measurement floor (attractor.SPREAD_NOISE: no trend can be read) is on
    an unstable orbit, not an attractor, when another start of the cell
    grows a modulation around the same orbit (amplitude and frequency
    within SAME): it ends on that start's torus, only later (a start near
    rest excites the unstable Floquet pair little; it grows at ~1e-2 /s
    from ~1e-5 and needs ~10 min).  Its kind becomes quasi, with the start
    that showed the growth in `unstable_by`."""
    growing = {k: s for k, s in starts.items() if s["kind"] == "quasi" and s.get("growing")}
    for start, s in starts.items():
        if s["kind"] not in ("low", "high") or s["peak_spread"] >= attractor.SPREAD_NOISE:
            continue
        for other, g in growing.items():
            if distinct([g, s]) == [g]:
                s.update(kind="quasi", unstable_by=other, growing=True)
                break


# cell labels: the distinct kinds its starts reached, in this order
KINDS = ("straight", "yaw", "low", "high", "quasi", "domain", "unsettled")
NAMES = {"straight": "straight rolling", "yaw": "off-centre yaw",
         "low": "low-frequency shimmy", "high": "high-frequency shimmy",
         "quasi": "quasi-periodic shimmy", "domain": "left the domain",
         "unsettled": "not settled"}


SAME = 0.02    # orbits of one kind are one attractor if amplitude and
               # frequency agree to this relative tolerance


def distinct(states: Sequence[Mapping[str, Any]]) -> List[Mapping[str, Any]]:
    """The states that are different attractors (by amplitude, frequency)."""
    kept = []
    for s in states:
        if not any(abs(s["amplitude_rad"] - k["amplitude_rad"]) <= SAME * k["amplitude_rad"]
                   and abs(s["frequency_hz"] - k["frequency_hz"]) <= SAME * k["frequency_hz"]
                   for k in kept):
            kept.append(s)
    return kept


def label(starts: Mapping[str, Mapping[str, Any]]) -> str:
    """The kinds the starts reached, in KINDS order; "high x2": two
    different high-frequency orbits."""
    parts = []
    for kind in KINDS:
        states = [s for s in starts.values() if s["kind"] == kind]
        if not states:
            continue
        count = len(distinct(states)) if kind in ("low", "high", "quasi") else 1
        parts.append(kind if count == 1 else f"{kind} x{count}")
    return " + ".join(parts)
