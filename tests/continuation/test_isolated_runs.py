"""Isolated runs and a quiet console (shared/rundirs.py: claim; shared/autoglue.py: run).

Two processes that want the same run directory, the second started once
the first holds it: the second waits for the first and says so, and both
read back the same, whole branch.  A cut-short b-file is an error.  AUTO's
output goes to a log file in the run directory; the console gets one
progress line per run; a failed run's error carries the tail of its log
and its path.  A run's time limit counts the AUTO executable's CPU time,
not the wall clock, so a loaded machine does not cut short a run an idle
one finishes."""
import os
import re
import subprocess
import sys
import time

import pytest

import helpers
from mlgshimmy.shared import diagrams, guards, rundirs, runerror
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import paths

DRIVERS = os.path.join(paths.ROOT, "drivers")
HOPF_V = 346.1  # m/s, zero freeplay, F* = 1 (Fig. 7, reference fig07/b.eq_F1)

# One short equilibrium branch, then a pause standing for a driver's plotting
# (it still reads its run directory), then the branch read back from disk.
JOB = """
import os, time
from mlgshimmy.shared import autosession, paths
from mlgshimmy.shared import continuation as ct
rundir = paths.rundir("shared")
start = ct.Start("figures", Fstar=1.0, V=0.0)
ct.equilibria(rundir, "eq", start, stop={"V": 600.0}, expect=["HB"])
time.sleep(2.0)
branch = autosession.init().parseB.parseBR(os.path.join(rundir, "b.eq"))[0]
hb = [i for i in branch.labels.getIndices() if "HB" in branch.labels[i]][0]
print(f"RESULT {len(branch)} {branch['V'][hb]:.10f} {branch['V'][-1]:.6f}")
"""


@pytest.fixture(scope="module")
def run_root(tmp_path_factory):
    """The runs' MLG_RUN_ROOT, set for this module; the directories this
    process claims are not passed on to later tests' child processes."""
    root = tmp_path_factory.mktemp("isolated")
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("MLG_RUN_ROOT", str(root))
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        yield str(root)


def job(root):
    env = {k: v for k, v in os.environ.items() if k != rundirs.CLAIMED_ENV}
    return subprocess.Popen([sys.executable, "-c", JOB], cwd=paths.ROOT, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env=dict(env, MLG_RUN_ROOT=root, PYTHONPATH=DRIVERS))


@pytest.fixture(scope="module")
def concurrent(run_root):
    """Two processes on one run directory, the second started once the
    first holds it: {"first": pid, "outputs": [(stdout, stderr)],
    "status": [exit status], "results": [RESULT fields of each]}."""
    first = job(run_root)
    helpers.wait_until_claimed(os.path.join(run_root, "shared"), first)
    second = job(run_root)
    outputs = [p.communicate(timeout=300) for p in (first, second)]
    results = [[line.split()[1:] for line in out.splitlines() if line.startswith("RESULT ")]
               for out, _ in outputs]
    return {"first": first.pid, "outputs": outputs, "status": [first.returncode,
                                                               second.returncode],
            "results": results}


@pytest.mark.parametrize("n", (1, 2))
def test_concurrent_process_on_one_run_directory_succeeds(concurrent, n):
    out, err = concurrent["outputs"][n - 1]
    assert concurrent["status"][n - 1] == 0 and concurrent["results"][n - 1], \
        f"process {n} of 2: {(out + err)[-600:]}"


def test_concurrent_second_process_waits_naming_the_directory_and_the_first(concurrent):
    err = concurrent["outputs"][1][1]
    assert f"in use by process {concurrent['first']}" in err and "waiting" in err \
        and "shared" in err, err[-400:]


def test_concurrent_processes_read_back_the_same_whole_branch(concurrent):
    """Both read back the same branch (points, Hopf speed, end): the whole
    branch, its Hopf point at 346.1 m/s (0.01), ending at V = 600."""
    results = [r[0] for r in concurrent["results"] if r]
    assert len(results) == 2, f"{len(results)} of 2 processes read a branch back"
    assert results[0] == results[1], f"{results}"
    points, hopf, end = results[0]
    assert abs(float(hopf) - HOPF_V) <= 0.01 and float(end) == 600.0, f"{results[0]}"


def test_quiet_console_auto_output_in_the_runs_log(concurrent, run_root):
    stdout = concurrent["outputs"][0][0]
    log = os.path.join(run_root, "shared", "eq.log")
    assert os.path.isfile(log) and "BR    PT  TY" in open(log).read() \
        and "BR    PT  TY" not in stdout, stdout[-400:]


def test_quiet_console_one_progress_line_per_run(concurrent):
    """One progress line per run: figure, run, its number (of the total of
    last time, once there is one), time."""
    stdout = concurrent["outputs"][0][0]
    assert any(re.match(r"shared: eq done \((1/\d+|run 1)\) in [\d.]+ s, \d+ s elapsed$", line)
               for line in stdout.splitlines()), stdout[-400:]


@pytest.fixture(scope="module")
def failed(run_root):
    """A run that misses the special point it expects: (rundir, its error)."""
    rundir = os.path.join(run_root, "failure")
    start = ct.Start("figures", Fstar=1.0, V=0.0)
    try:
        ct.equilibria(rundir, "eq", start, stop={"V": 10.0}, expect=["HB"])
        message = "no error"
    except runerror.RunError as exc:
        message = str(exc)
    return rundir, message


def test_failed_run_error_names_its_log_and_shows_its_last_lines(failed):
    rundir, message = failed
    log = os.path.join(rundir, "eq.log")
    assert "expected special points ['HB'] missing" in message and log in message \
        and "    | " in message, message


def test_cut_short_b_file_is_an_error_naming_it(failed):
    rundir, _ = failed
    path = os.path.join(rundir, "b.eq")
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text[:len(text) * 2 // 3])
    with pytest.raises(runerror.RunError) as error:
        diagrams.read_diagram([os.path.join(rundir, f"{k}.eq") for k in "bsd"], "cut")
    assert "cut short" in str(error.value) and path in str(error.value), str(error.value)


@pytest.mark.parametrize("program, killed", (("import time; time.sleep(2.5)", False),
                                             ("while True: pass", True)),
                         ids=("waiting child", "busy child"))
def test_cpu_limit_kills_a_busy_child_only(program, killed):
    """autoglue's stall guard on a child that waits (no CPU) and on one that
    computes: only the second is killed (after 1 s of CPU; the waiting one
    outlives the limit by 2.5 s of wall time)."""
    started = time.monotonic()
    with guards.CPULimit(1.0) as limit:
        status = subprocess.run([sys.executable, "-c", program], timeout=60).returncode
    seconds = time.monotonic() - started
    assert limit.fired == killed and (status != 0) == killed \
        and (seconds < 10 if killed else seconds >= 2.5), \
        f"fired {limit.fired}, status {status}, {seconds:.1f} s"
