"""The side-stay drivers: bad angles are rejected before any AUTO run, with a
message naming the parameter; one sweep job gives the critical speed, and
the mirror image (-rho, -mu) gives the same (docs/model.md 8.5, 8.7)."""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from check import check  # noqa: E402


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


if __name__ == "__main__":
    main()
