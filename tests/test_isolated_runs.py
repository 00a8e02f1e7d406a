"""Isolated runs and a quiet console (drivers/autoglue.py: claim, run).

Two processes that want the same run directory, the second started once
the first holds it: the second waits for the first and says so, and both
read back the same, whole branch.  A cut-short b-file is an error.  AUTO's output goes to a log file in
the run directory; the console gets one progress line per run; a failed run's
error carries the tail of its log and its path.  A run's time limit counts
the AUTO executable's CPU time, not the wall clock, so a loaded machine does
not cut short a run an idle one finishes."""
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "drivers"))
from mlgshimmy.shared import autoglue  # noqa: E402
from mlgshimmy.shared import continuation as ct  # noqa: E402
from check import check, wait_until_claimed  # noqa: E402

RUN_ROOT = os.path.join(ROOT, "build", "tests", "isolated")
HOPF_V = 346.1  # m/s, zero freeplay, F* = 1 (Fig. 7, reference fig07/b.eq_F1)

# One short equilibrium branch, then a pause standing for a driver's plotting
# (it still reads its run directory), then the branch read back from disk.
JOB = """
import os, sys, time
sys.path.insert(0, os.path.join(sys.argv[1], "drivers"))
import autoglue, continuation as ct, paths
rundir = paths.rundir("shared")
start = ct.Start("figures", Fstar=1.0, V=0.0)
ct.equilibria(rundir, "eq", start, stop={"V": 600.0}, expect=["HB"])
time.sleep(2.0)
branch = autoglue.init().parseB.parseBR(os.path.join(rundir, "b.eq"))[0]
hb = [i for i in branch.labels.getIndices() if "HB" in branch.labels[i]][0]
print(f"RESULT {len(branch)} {branch['V'][hb]:.10f} {branch['V'][-1]:.6f}")
"""


def job():
    return subprocess.Popen([sys.executable, "-c", JOB, ROOT], cwd=ROOT, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env=dict(os.environ, MLG_RUN_ROOT=RUN_ROOT))


def concurrent():
    first = job()
    wait_until_claimed(os.path.join(RUN_ROOT, "shared"), first)
    second = job()
    outputs = [p.communicate(timeout=300) for p in (first, second)]
    results = []
    for n, ((out, err), proc) in enumerate(zip(outputs, (first, second)), 1):
        lines = [line.split()[1:] for line in out.splitlines() if line.startswith("RESULT ")]
        if check(f"process {n} of 2 on one run directory succeeds",
                 proc.returncode == 0 and lines, (out + err)[-600:]):
            jobs.append(lines[0])
    err = outputs[1][1]
    check("the second process waits, naming the directory and the first process",
          f"in use by process {first.pid}" in err and "waiting" in err
          and "shared" in err, err[-400:])
    if len(results) == 2:
        check("both read back the same branch (points, Hopf speed, end)",
              results[0] == results[1], f"{results}")
        points, hopf, end = results[0]
        check(f"... the whole branch: Hopf point at {HOPF_V} m/s (0.01), ends at V = 600",
              abs(float(hopf) - HOPF_V) <= 0.01 and float(end) == 600.0, f"{results[0]}")
    return outputs[0][0]


def quiet_console(stdout):
    log = os.path.join(RUN_ROOT, "shared", "eq.log")
    check("AUTO's output is in the run's log file, not on the console",
          os.path.isfile(log) and "BR    PT  TY" in open(log).read()
          and "BR    PT  TY" not in stdout, stdout[-400:])
    check("one progress line per run: figure, run, done/total, time",
          any(line.startswith("shared: eq done (1/") and " s elapsed" in line
              for line in stdout.splitlines()), stdout[-400:])


def failures():
    rundir = os.path.join(RUN_ROOT, "failure")
    start = ct.Start("figures", Fstar=1.0, V=0.0)
    try:
        ct.equilibria(rundir, "eq", start, stop={"V": 10.0}, expect=["HB"])
        message = "no error"
    except autoglue.RunError as exc:
        message = str(exc)
    log = os.path.join(rundir, "eq.log")
    check("a failed run's error names its log and shows its last lines",
          "expected special points ['HB'] missing" in message and log in message
          and "    | " in message, message)

    path = os.path.join(rundir, "b.eq")
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text[:len(text) * 2 // 3])
    try:
        autoglue.read_diagram([os.path.join(rundir, f"{k}.eq") for k in "bsd"], "cut")
        message = "no error"
    except autoglue.RunError as exc:
        message = str(exc)
    check("a b-file cut short is an error naming it",
          "cut short" in message and path in message, message)


def cpu_limit():
    """autoglue's stall guard on a child that waits (no CPU) and on one that
    computes: only the second is killed."""
    for program, killed in (("import time; time.sleep(2.5)", False),
                            ("while True: pass", True)):
        started = time.monotonic()
        with autoglue._CPULimit(1.0) as limit:
            status = subprocess.run([sys.executable, "-c", program], timeout=60).returncode
        seconds = time.monotonic() - started
        what = "a busy child is killed after 1 s of CPU" if killed else \
            "a waiting child outlives a 1 s CPU limit (2.5 s of wall time)"
        check(what, limit.fired == killed and (status != 0) == killed
              and (seconds < 10 if killed else seconds >= 2.5),
              f"fired {limit.fired}, status {status}, {seconds:.1f} s")


def main():
    os.environ["MLG_RUN_ROOT"] = RUN_ROOT
    autoglue.RUN_ROOT = RUN_ROOT
    stdout = concurrent()
    quiet_console(stdout)
    failures()
    cpu_limit()


if __name__ == "__main__":
    main()
