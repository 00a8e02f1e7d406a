"""Benchmark of the figure suite: wall time of `make -j1 figures` and
`make -j2 figures`, each from scratch in its own run root (build/bench/j1,
build/bench/j2) of an otherwise built tree, in one session; then every run
directory of the two compared with the diagram comparator (the -j2 suite
must produce the same diagrams).  About 45 min on 2 cores: run it through
`make bench-figures`, on a machine left otherwise idle.

The parallel work is the parts of Figs. 11, 13, 14 and 16 and the figures
themselves; with more cores the wall time is bounded by the longest single
part chain (Fig. 11's assembly after its slowest slice, Fig. 16's fold-seed
part), so it levels off at a few minutes beyond about 8 cores.
"""
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COMPARE = os.path.join(ROOT, "tests", "regression", "compare_diagrams.py")
PYTHON = os.environ.get("PYTHON", sys.executable)


def suite(jobs):
    """(wall seconds, run root) of `make -j<jobs> figures` from scratch."""
    run_root = os.path.join(ROOT, "build", "bench", f"j{jobs}")
    shutil.rmtree(run_root, ignore_errors=True)
    started = time.monotonic()
    log = open(os.path.join(ROOT, "build", "bench", f"figures-j{jobs}.log"), "w")
    proc = subprocess.run(["make", f"-j{jobs}", "--no-print-directory", "figures"], cwd=ROOT,
                          env=dict(os.environ, MLG_RUN_ROOT=run_root), stdout=log,
                          stderr=subprocess.STDOUT)
    seconds = time.monotonic() - started
    if proc.returncode != 0:
        sys.exit(f"bench_figures: make -j{jobs} figures failed (log {log.name})")
    return seconds, run_root


def run_dirs(run_root):
    """Every directory under run_root holding b-files, relative to it."""
    return sorted(os.path.relpath(d, run_root) for d, _, files in os.walk(run_root)
                  if any(f.startswith("b.") for f in files))


def main():
    os.makedirs(os.path.join(ROOT, "build", "bench"), exist_ok=True)
    serial, one = suite(1)
    print(f"bench_figures: make -j1 figures {serial / 60:.1f} min", flush=True)
    parallel, two = suite(2)
    print(f"bench_figures: make -j2 figures {parallel / 60:.1f} min; ratio -j2/-j1 "
          f"{parallel / serial:.2f} (goal <= 0.55)", flush=True)
    dirs = run_dirs(one)
    differ = [d for d in dirs if subprocess.run(
        [PYTHON, COMPARE, os.path.join(one, d), os.path.join(two, d)],
        capture_output=True).returncode != 0]
    missing = sorted(set(run_dirs(two)) ^ set(dirs))
    print(f"bench_figures: {len(dirs)} run directories compared, -j2 vs -j1: "
          + ("all agree" if not differ and not missing else
             f"DIFFERENT {differ}, only in one {missing}"))
    sys.exit(1 if differ or missing else 0)


if __name__ == "__main__":
    main()
