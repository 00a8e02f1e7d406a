"""build/bin/mlg_simulate (CVODE time simulation of the c/ model) from
Python: the one place that runs it and reads its summary.

    proc = run(csv_path, "--V", "300", "--Fstar", "0.2", params={"yfp": 0})
    numbers = summary(proc.stdout)    # {"psi_amplitude_rad": ..., ...}
    numbers = simulate(csv_path, "--V", "300")   # the same, raising on failure
"""
from __future__ import annotations

import os
import subprocess
import tempfile
from typing import Any, Dict, List, Mapping, Optional

import numpy

from mlgshimmy.shared import children, mlgmodel, spectrum
from mlgshimmy.shared import paths

SIMULATOR = os.path.join(paths.BUILD, "bin", "mlg_simulate")

# Initial states of the atlas and the lift-off edge: the straight-rolling
# equilibrium with psi displaced [rad].  The freeplay angle y_fp / r_tlk is
# about 2.1e-3 rad; the stable shimmy orbits of Fig. 11 reach 0.005-0.27 rad.
STARTS = {"rolling": 1e-4,       # straight rolling, slightly perturbed
          "yawed": 4e-3,         # yawed twice the freeplay angle, at rest
          "shimmy": 0.05}        # a large-amplitude torsional swing


class SimulationError(RuntimeError):
    """mlg_simulate exited non-zero (its stderr is the message)."""


def run(csv: Optional[str], *args: Any,
        params: Optional[Mapping[str, float]] = None) -> subprocess.CompletedProcess:
    """Run the simulator writing the samples to csv (None: none, only the
    summary); the completed process.  params: {name: value} passed as
    --param name=value."""
    command = [SIMULATOR, *map(str, args)] + (["--out", csv] if csv else [])
    for name, value in (params or {}).items():
        command += ["--param", f"{name}={value}"]
    children.stop_with_this_process()   # a make interrupted leaves no simulator running
    return subprocess.run(command, capture_output=True, text=True)


def freeplay_args(freeplay: Mapping[str, float]) -> List[Any]:
    """--yfp/--eps-abs/--eps-rel of a freeplay case {yfp, eps_abs, eps_rel}."""
    return ["--yfp", freeplay["yfp"], "--eps-abs", freeplay["eps_abs"],
            "--eps-rel", freeplay["eps_rel"]]


def state_args(u: Optional[Mapping[str, float]]) -> List[str]:
    """--u0 of a state {name: value} (the simulator then starts there, not at
    its own straight-rolling Newton solve); [] for None."""
    return [] if u is None else ["--u0", ",".join(repr(u[n]) for n in mlgmodel.UNAMES)]


def start_args(V: float, Fstar: float, freeplay: Mapping[str, float],
               u0: Optional[Mapping[str, float]], psi0: float, t_end: float, dt_out: float,
               params: Optional[Mapping[str, float]]) -> List[Any]:
    """The options of a run of the `figures` set from the state u0 (None: the
    simulator's own straight rolling) with psi displaced by psi0, at a
    freeplay case {yfp, eps_abs, eps_rel} and the gear's --param values
    (shared.gear.simulator_params)."""
    at = [word for name, value in params.items() for word in ("--param", f"{name}={value}")]
    return ["--set", "figures", "--V", V, "--Fstar", Fstar, *freeplay_args(freeplay),
            "--t-end", t_end, "--dt-out", dt_out, "--psi0", psi0, *state_args(u0), *at]


def left_domain(proc: subprocess.CompletedProcess) -> Optional[str]:
    """The simulator's reason if the model left its domain, else None."""
    for line in proc.stderr.splitlines():
        if line.startswith("mlg_simulate: model evaluation failed"):
            return line[len("mlg_simulate: "):]
    return None


def summary(stdout: str) -> Dict[str, float]:
    """The simulator's summary, one `key value` per line, as {key: float}."""
    return {key: float(value) for key, value in
            (line.split(None, 1) for line in stdout.splitlines() if line.strip())}


def simulate(csv: Optional[str], *args: Any,
             params: Optional[Mapping[str, float]] = None) -> Dict[str, float]:
    """run() and summary(); raises SimulationError if the simulator fails."""
    proc = run(csv, *args, params=params)
    if proc.returncode != 0:
        raise SimulationError(f"mlg_simulate failed (exit status {proc.returncode}): "
                              f"{proc.stderr.strip()}")
    return summary(proc.stdout)


# fold_speed: the orbit settles for FOLD_SETTLE s at the upper speed, then each
# trial runs FOLD_TRIAL s from its last state; an orbit whose psi amplitude
# falls below FOLD_GONE of the settled one has ceased
FOLD_SETTLE, FOLD_TRIAL, FOLD_GONE = 20.0, 80.0, 0.1


def fold_speed(lo: float, hi: float, tol: float,
               params: Optional[Mapping[str, float]]) -> Optional[float]:
    """The speed S in (lo, hi) below which the stable orbit reached at hi
    (from psi = 0.01 rad) ceases to exist: bisected (spectrum.bisect) on
    whether it survives FOLD_TRIAL s started from its state at hi, to tol.
    A run just below S lingers on the ghost of the orbit for a time ~ (S -
    V)^-1/2, so S comes out low by about what FOLD_TRIAL resolves (1e-3 m/s
    at Fig. 10's S).  None if the orbit survives at lo or is absent at hi."""
    base = ["--Fstar", params.get("Fstar", 1.0), "--dt-out", 1e-3]
    extra = {k: v for k, v in params.items() if k != "Fstar"}
    with tempfile.TemporaryDirectory() as tmp:
        csv = os.path.join(tmp, "orbit.csv")
        settled = simulate(csv, "--V", hi, "--t-end", FOLD_SETTLE, "--psi0", 0.01, *base,
                           params=extra)["psi_amplitude_rad"]
        start = numpy.loadtxt(csv, delimiter=",", skiprows=1)[-1, 1:]
    u0 = ",".join(repr(x) for x in start)

    def gone(V):
        amp = simulate(None, "--V", V, "--t-end", FOLD_TRIAL, "--u0", u0, *base,
                       params=extra)["psi_amplitude_rad"]
        return amp < FOLD_GONE * settled
    if settled < 1e-4 or not gone(lo):
        return None
    return spectrum.bisect(gone, lo, hi, tol=tol)
