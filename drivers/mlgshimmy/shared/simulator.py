"""build/bin/mlg_simulate (CVODE time simulation of the c/ model) from
Python: the one place that runs it and reads its summary.

    proc = run(csv_path, "--V", "300", "--Fstar", "0.2", params={"yfp": 0})
    numbers = summary(proc.stdout)    # {"psi_amplitude_rad": ..., ...}
    numbers = simulate(csv_path, "--V", "300")   # the same, raising on failure
"""
import os
import subprocess

from mlgshimmy.shared import children, mlgmodel
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


def run(csv, *args, params=None):
    """Run the simulator writing the samples to csv (None: none, only the
    summary); the completed process.  params: {name: value} passed as
    --param name=value."""
    command = [SIMULATOR, *map(str, args)] + (["--out", csv] if csv else [])
    for name, value in (params or {}).items():
        command += ["--param", f"{name}={value}"]
    children.stop_with_this_process()   # a make interrupted leaves no simulator running
    return subprocess.run(command, capture_output=True, text=True)


def freeplay_args(freeplay):
    """--yfp/--eps-abs/--eps-rel of a freeplay case {yfp, eps_abs, eps_rel}."""
    return ["--yfp", freeplay["yfp"], "--eps-abs", freeplay["eps_abs"],
            "--eps-rel", freeplay["eps_rel"]]


def state_args(u):
    """--u0 of a state {name: value} (the simulator then starts there, not at
    its own straight-rolling Newton solve); [] for None."""
    return [] if u is None else ["--u0", ",".join(repr(u[n]) for n in mlgmodel.UNAMES)]


def left_domain(proc):
    """The simulator's reason if the model left its domain, else None."""
    for line in proc.stderr.splitlines():
        if line.startswith("mlg_simulate: model evaluation failed"):
            return line[len("mlg_simulate: "):]
    return None


def summary(stdout):
    """The simulator's summary, one `key value` per line, as {key: float}."""
    return {key: float(value) for key, value in
            (line.split(None, 1) for line in stdout.splitlines() if line.strip())}


def simulate(csv, *args, params=None):
    """run() and summary(); raises SimulationError if the simulator fails."""
    proc = run(csv, *args, params=params)
    if proc.returncode != 0:
        raise SimulationError(f"mlg_simulate failed (exit status {proc.returncode}): "
                              f"{proc.stderr.strip()}")
    return summary(proc.stdout)
