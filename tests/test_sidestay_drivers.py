"""The side-stay drivers: bad angles are rejected before any AUTO run, with a
message naming the parameter; one sweep job gives the critical speed, and
the mirror image (-rho, -mu) gives the same (docs/model.md 8.5, 8.7).  A
sweep grid with a repeated point or a non-number is rejected naming
SWEEP_RHO/SWEEP_MU, and `make clean` never reads the grid; a bad EOM stops
`make sidestay` naming it.  Two side-stay
runs that both need the rho = mu = 0 runs, the second started while the
first holds them: the second waits for the first and then reuses its cached runs, with the same numbers;
the numbers are in a plain-text table and the eom_terms level is printed."""
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from check import check, wait_until_claimed  # noqa: E402


def driver(*args):
    return subprocess.run([sys.executable, *args], cwd=ROOT, capture_output=True, text=True)


def main():
    proc = driver("drivers/sidestay.py", "--rho", "87", "--mu", "0")
    check("sidestay: rho = 87 deg rejected before AUTO (degenerate side-stay)",
          proc.returncode != 0 and "parameters rho = 1.51844" in proc.stderr
          and "degenerate" in proc.stderr
          and not os.path.exists(os.path.join(ROOT, "build", "sidestay_rho87_mu0")),
          proc.stderr.strip())
    proc = driver("drivers/sweep.py", "check", "--rho=0,95", "--mu=0")
    check("sweep: grid with rho = 95 deg rejected, naming rho",
          proc.returncode != 0 and "parameter rho = 1.65806 rad" in proc.stderr,
          proc.stderr.strip())

    for eom in ("7", "x"):
        proc = subprocess.run(["make", "-n", "sidestay", "RHO=10", "MU=10", f"EOM={eom}"],
                              cwd=ROOT, capture_output=True, text=True)
        check(f"make sidestay EOM={eom}: stops before any run, naming EOM",
              proc.returncode != 0 and f"EOM={eom} must be 0" in proc.stderr
              and "sidestay.py" not in proc.stdout, (proc.stdout + proc.stderr).strip()[-300:])

    sweep_grids()
    shared_reference()

    speeds = {}
    for name in ("rho10_mu10", "rho-10_mu-10"):
        proc = driver("drivers/sweep.py", "point", name)
        path = os.path.join(ROOT, "build", "sweep", name, "result.json")
        if check(f"sweep point {name} runs", proc.returncode == 0, proc.stderr.strip()[-300:]):
            with open(path) as f:
                speeds[name] = json.load(f)["critical_V"]
    if len(speeds) == 2:
        a, b = speeds["rho10_mu10"], speeds["rho-10_mu-10"]
        # eigenvalue bisection at rho = mu = 10 deg, eom_terms = 2: 350.664 m/s
        check("sweep: critical speed at rho = mu = 10 deg is 350.66 +- 0.05 m/s",
              abs(a - 350.664) <= 0.05, f"{a:.4f} m/s")
        check("sweep: mirror geometry (-rho, -mu) has the same critical speed (1e-6)",
              abs(a - b) <= 1e-6 * a, f"{a:.6f} vs {b:.6f} m/s")


# drivers/sidestay.py with equilibria only (no Hopf points, so no orbit or
# curve runs: seconds, not minutes) and a pause after each geometry, in which
# the process still owns that geometry's run directory.
QUICK_SIDESTAY = """
import os, sys, time
sys.path.insert(0, os.path.join(sys.argv[1], "drivers"))
from mlgshimmy.studies import sidestay
sidestay.hopf_points = lambda rundir, tag, values: []
computed = sidestay.compute
def paused(*args, **kw):
    out = computed(*args, **kw)
    time.sleep(2.0)
    return out
sidestay.compute = paused
sys.argv = ["sidestay.py", "--rho", sys.argv[2], "--mu", sys.argv[2]]
sidestay.main()
"""


def shared_reference():
    root = os.path.join(ROOT, "build", "tests", "sidestay")
    env = dict(os.environ, MLG_RUN_ROOT=root)
    cache = os.path.join(root, "sidestay_rho0_mu0", "cache.json")
    if os.path.exists(cache):
        os.remove(cache)

    def start(angle):
        return subprocess.Popen([sys.executable, "-c", QUICK_SIDESTAY, ROOT, angle], cwd=ROOT,
                                env=env, text=True, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE)
    first = start("5")
    wait_until_claimed(os.path.join(root, "sidestay_rho0_mu0"), first)
    second = start("10")
    (out1, err1), (out2, err2) = first.communicate(timeout=300), second.communicate(timeout=300)
    if not check("sidestay at 5 and 10 deg, the second started while the first holds rho = mu = 0: "
                 "both succeed", first.returncode == 0 and second.returncode == 0,
                 (err1 + err2)[-800:]):
        return
    check("... the second waits for the first, naming sidestay_rho0_mu0",
          "sidestay_rho0_mu0 is in use by process" in err2 and "waiting" in err2, err2[-400:])
    check("... then reuses its cached rho = mu = 0 runs instead of recomputing them",
          "reusing the runs" in out2 and "reusing the runs" not in out1
          and "sidestay_rho0_mu0: eq_fp0 done" not in out2, out2[-600:])

    def reference(out):
        return [line for line in out.splitlines() if "rho = mu = 0, " in line]
    check("... with the same rho = mu = 0 numbers",
          reference(out1) == reference(out2) and len(reference(out1)) == 2,
          f"{reference(out1)} vs {reference(out2)}")
    check("the eom_terms level is printed first", "eom_terms = 2" in out1.splitlines()[0],
          out1[:200])
    table = os.path.join(root, "tables", "sidestay_rho5_mu5.txt")
    text = open(table).read() if os.path.exists(table) else ""
    check("the numbers are in build/.../tables/sidestay_rho5_mu5.txt, without LaTeX",
          "Hopf points at V" in text and "$" not in text and "\\" not in text, text[:300])


def sweep_grids():
    for rho, mu, variable, what in (("10,10.0000001", "0", "SWEEP_RHO", "10 and 10.0000001"),
                                    ("0", "5,-5,5", "SWEEP_MU", "5 and 5"),
                                    ("0,,10", "0", "SWEEP_RHO", "'' is not a number"),
                                    ("0", "1,x", "SWEEP_MU", "'x' is not a number")):
        for command in ("jobs", "targets"):
            proc = driver("drivers/sweep.py", command, f"--rho={rho}", f"--mu={mu}")
            check(f"sweep {command} --rho={rho} --mu={mu}: rejected naming {variable} ({what})",
                  proc.returncode != 0 and not proc.stdout and variable in proc.stderr
                  and what in proc.stderr, (proc.stdout + proc.stderr).strip())
    proc = subprocess.run(["make", "-n", "sweep", "SWEEP_RHO=10,10.0000001"], cwd=ROOT,
                          capture_output=True, text=True)
    check("make sweep SWEEP_RHO=10,10.0000001 stops before any job, naming SWEEP_RHO",
          proc.returncode != 0 and "SWEEP_RHO" in proc.stderr and "sweep.py point" not in
          proc.stdout, (proc.stdout + proc.stderr).strip()[-400:])
    # A PYTHON that leaves a mark shows whether make ran it to read the grid.
    with tempfile.TemporaryDirectory() as scratch:
        mark = os.path.join(scratch, "called")
        fake = os.path.join(scratch, "python")
        with open(fake, "w") as f:
            f.write(f"#!/bin/sh\ntouch {mark}\n")
        os.chmod(fake, 0o755)
        proc = subprocess.run(["make", "-n", "clean", f"PYTHON={fake}", "SWEEP_RHO=x"],
                              cwd=ROOT, capture_output=True, text=True)
        check("make clean does not evaluate the sweep grid (not even a bad one)",
              proc.returncode == 0 and not os.path.exists(mark), proc.stderr.strip())


if __name__ == "__main__":
    main()
