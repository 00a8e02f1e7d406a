"""build/bin/mlg_simulate refuses, before it starts, a run whose memory or
output would exceed its stated budget (c/simulate/mlg_simulate.c: the last
second's samples, 88 bytes each, at most 1024 MB unless --max-memory /
MLG_SIMULATE_MAX_MEMORY_MB raise it; the --out CSV, at most 280 bytes a
sample, at most 1024 MB unless --max-output / MLG_SIMULATE_MAX_OUTPUT_MB):

- `--t-end 1 --dt-out 1e-8` (within the 1e8-sample limit, 8.4 GB of samples)
  and `--t-end 0.05 --dt-out 1e-9` fail in under 2 s, exit status 2, naming
  the options and the budget, under a 2 GB address-space limit as well;
- a CSV over the output budget is refused the same way, and not created;
- the budgets can be lowered and raised by option and environment variable;
- Fig. 8's run (mlgshimmy.figures.fig08's options) is unaffected: its summary is
  the one the simulator printed before the budgets (same numbers to 1e-9
  relative, same sample counts) and its CSV has every sample.

Run with: python3 -m pytest -q tests/model/test_simulate_budget.py
(after `make build/bin/mlg_simulate`)
"""
import os
import resource
import subprocess
import time

import pytest

import helpers

ROOT = helpers.ROOT
SIMULATOR = os.path.join(ROOT, "build", "bin", "mlg_simulate")
LIMIT = 2 * 1024 ** 3  # the 2 GB ulimit of the report

pytestmark = pytest.mark.skipif(not os.access(SIMULATOR, os.X_OK),
                                reason="build/bin/mlg_simulate not built")


def run(*args, env=None, limit=None, timeout=60):
    """(exit status, stdout, stderr, seconds) of the simulator."""
    def restrict():
        if limit is not None:
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    environment = {k: v for k, v in os.environ.items() if not k.startswith("MLG_SIMULATE_")}
    environment.update(env or {})
    start = time.monotonic()
    proc = subprocess.run([SIMULATOR, *map(str, args)], capture_output=True, text=True,
                          env=environment, preexec_fn=restrict, timeout=timeout)
    return proc.returncode, proc.stdout, proc.stderr, time.monotonic() - start


@pytest.mark.parametrize("args", [("--t-end", "1", "--dt-out", "1e-8"),
                                  ("--t-end", "0.05", "--dt-out", "1e-9")])
@pytest.mark.parametrize("limit", [None, LIMIT])
def test_memory_over_budget_is_refused_up_front(args, limit):
    status, _, err, seconds = run(*args, limit=limit)
    assert status == 2, err
    assert seconds < 2.0, f"took {seconds:.1f} s: {err}"
    assert "--t-end" in err and "--dt-out" in err, err
    assert "memory budget of 1024 MB" in err and "--max-memory" in err, err
    assert "out of memory" not in err
    assert len(err.strip().splitlines()) == 1, err


def test_output_over_budget_is_refused_and_not_written(tmp_path):
    csv = tmp_path / "big.csv"
    status, _, err, seconds = run("--t-end", "60", "--dt-out", "1e-6", "--out", csv)
    assert status == 2, err
    assert seconds < 2.0, f"took {seconds:.1f} s"
    assert "--out" in err and "output budget of 1024 MB" in err and "--max-output" in err, err
    assert not csv.exists()


def test_budgets_follow_option_and_environment(tmp_path):
    small = ("--t-end", "0.1", "--dt-out", "1e-3")  # 102 samples kept: 9 KB
    status, _, err, _ = run(*small, "--max-memory", "0.001")
    assert status == 2 and "memory budget of 0.001 MB" in err, err
    status, _, err, _ = run(*small, env={"MLG_SIMULATE_MAX_MEMORY_MB": "0.001"})
    assert status == 2 and "memory budget of 0.001 MB" in err, err
    status, out, err, _ = run(*small, "--max-memory", "0.1",
                              env={"MLG_SIMULATE_MAX_MEMORY_MB": "0.001"})
    assert status == 0, err  # the option wins over the environment
    assert "window_samples 101" in out, out
    csv = tmp_path / "small.csv"
    status, _, err, _ = run(*small, "--out", csv, "--max-output", "0.01")
    assert status == 2 and "--max-output" in err and not csv.exists(), err
    status, _, err, _ = run(*small, "--out", csv, env={"MLG_SIMULATE_MAX_OUTPUT_MB": "0.1"})
    assert status == 0 and csv.exists(), err
    for bad in ("0", "-1", "inf", "nan", "lots"):
        status, _, err, _ = run(*small, "--max-memory", bad)
        assert status == 2 and "--max-memory" in err, err
        status, _, err, _ = run(*small, env={"MLG_SIMULATE_MAX_OUTPUT_MB": bad})
        assert status == 2 and "MLG_SIMULATE_MAX_OUTPUT_MB" in err, err


# The summary of Fig. 8's run (mlgshimmy.figures.fig08: --set figures --V 300.0
# --Fstar 0.2 --yfp 0 --t-end 15.0 --dt-out 0.001 --psi0 0.001) printed by the
# simulator before the budgets existed (commit d0647f9).
FIG08 = {"window_samples": 1001, "window_start_s": 14, "t_end": 15,
         "equilibrium_beta_rad": -1.9268214951e-03, "equilibrium_eta_m": 2.7013064104e-01,
         "psi_mean_rad": -1.0600219025e-05, "psi_amplitude_rad": 3.7063203702e-02,
         "delta_mean_rad": -2.0605262274e-06, "delta_amplitude_rad": 5.0417634470e-03,
         "beta_mean_rad": -2.1313639075e-03, "beta_amplitude_rad": 4.6718574516e-06,
         "eta_mean_m": 2.6970081709e-01, "eta_amplitude_m": 4.9209301644e-06,
         "frequency_hz": 37.98394005}


def test_fig08_run_unaffected(tmp_path):
    csv = tmp_path / "fig08.csv"
    status, out, err, _ = run("--set", "figures", "--V", "300.0", "--Fstar", "0.2", "--yfp", "0",
                              "--t-end", "15.0", "--dt-out", "0.001", "--psi0", "0.001",
                              "--out", csv)
    assert status == 0, err
    summary = {k: float(v) for k, v in (line.split(None, 1) for line in out.splitlines())}
    for key, expected in FIG08.items():
        assert summary[key] == pytest.approx(expected, rel=1e-9, abs=1e-15), key
    with open(csv) as f:
        lines = f.readlines()
    assert lines[0].startswith("t,psi,delta,beta,eta,")
    assert len(lines) == 1 + 15001  # the header, t = 0 and 15000 samples
    assert float(lines[-1].split(",")[0]) == 15.0
