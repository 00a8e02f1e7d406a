"""Benchmark (not a test): one periodic-orbit continuation with the analytic
Jacobian (JAC=1) and with AUTO's finite differences (JAC=0), the same run,
one after the other.  Printed: wall time, and the CPU time of AUTO's process
alone (children's user + system time), which load from other processes and
Python's reading of the output do not enter; the ratio of each.  Where perf
works, the run is recorded with it and the profile split follows
(perf_split.py: model library, libm, AUTO, OpenMP runtime, Python)."""
import os
import resource
import sys
import time

import perf_split   # beside this script (tests/bench/)
from mlgshimmy.shared import continuation as ct   # PYTHONPATH=drivers (make bench sets it)
from mlgshimmy.shared import paths

RUNDIR = os.path.join(paths.BUILD, "bench", "auto-jacobian")
UNDER_PERF = "MLG_BENCH_UNDER_PERF"    # set in the recorded child


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def main():
    start = ct.Start("figures", Fstar=1.0, V=0.0)
    eq = ct.equilibria(RUNDIR, "eq", start, stop={"V": 400.0}, expect=["HB"])
    seconds, cpu, points = {}, {}, {}
    for jac in (1, 0):
        begin, cpu_begin = time.perf_counter(), children_cpu()
        po = ct.periodic_from(RUNDIR, f"po_jac{jac}", eq("HB1"), stop={"V": 500.0},
                              expect=["UZ"], JAC=jac)
        seconds[jac] = time.perf_counter() - begin
        cpu[jac] = children_cpu() - cpu_begin
        points[jac] = len(po[0])
    print("bench_auto_jacobian: periodic orbits from the Hopf point at F* = 1 to V = 500 m/s "
          "(NTST = 80, NCOL = 4)")
    for jac in (1, 0):
        print(f"  JAC={jac}: {seconds[jac]:7.2f} s wall, {cpu[jac]:7.2f} s CPU in AUTO, "
              f"{points[jac]} points")
    print(f"  ratio JAC=0 / JAC=1: {seconds[0] / seconds[1]:.2f} wall, "
          f"{cpu[0] / cpu[1]:.2f} CPU in AUTO")


def profiled():
    """main() under perf record, then the split; main() alone where perf does not work."""
    why_not = perf_split.available()
    if why_not is not None:
        print(f"bench_auto_jacobian: no profile ({why_not})")
        main()
        return
    data = RUNDIR + ".perf.data"       # beside the run directory, which each run replaces
    os.makedirs(os.path.dirname(data), exist_ok=True)
    status = perf_split.record([sys.executable, os.path.abspath(__file__)], data,
                               env=dict(os.environ, **{UNDER_PERF: "1"}))
    if status != 0:
        sys.exit(f"bench_auto_jacobian: the recorded run failed (exit {status})")
    objects = [os.path.join(paths.BUILD, "lib", "libmlg.a"),
               os.path.join(paths.BUILD, "models", "mlg.o")]
    perf_split.print_split(perf_split.split(data, objects), ["eq", "JAC=1", "JAC=0"])


if __name__ == "__main__":
    main() if os.environ.get(UNDER_PERF) else profiled()
