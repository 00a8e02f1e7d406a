"""build/bin/mlg_simulate (CVODE time simulation of the c/ model) from
Python: the one place that runs it and reads its summary.

    proc = run(csv_path, "--V", "300", "--Fstar", "0.2", params={"yfp": 0})
    numbers = summary(proc.stdout)    # {"psi_amplitude_rad": ..., ...}
    numbers = simulate(csv_path, "--V", "300")   # the same, raising on failure
"""
import os
import subprocess

import paths

SIMULATOR = os.path.join(paths.BUILD, "bin", "mlg_simulate")


class SimulationError(RuntimeError):
    """mlg_simulate exited non-zero (its stderr is the message)."""


def run(csv, *args, params=None):
    """Run the simulator writing the samples to csv; the completed process.
    params: {name: value} passed as --param name=value."""
    command = [SIMULATOR, *map(str, args), "--out", csv]
    for name, value in (params or {}).items():
        command += ["--param", f"{name}={value}"]
    return subprocess.run(command, capture_output=True, text=True)


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
