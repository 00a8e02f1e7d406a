"""Benchmark of the figure suite: wall time of `make -j1 figures` and
`make -j2 figures`, each from scratch in its own run root (build/bench/j1,
build/bench/j2) of an otherwise built tree, in one session; then every run
directory of the two compared, every saved point of every b-file (the -j2
suite must produce the same diagrams, bit for bit).  About 25 min on 2 idle
cores: run it through `make bench-figures`, on a machine left otherwise
idle; `--compare-only` repeats the comparison of the last two suites, and
`--compare ROOT1 ROOT2` compares any two run roots (e.g. a suite before and
after a change).

Then the rows of a gear against the paper's, measured in the same session
(`--gear-rows` makes only these): `make -j2 fig11` from scratch, wall and
CPU seconds, at the paper's gear and at GEAR; and one design-map point's
CPU seconds (studies.design_map.compute, by stage) at both.

The parallel work is the parts of Figs. 11, 13, 14 and 16 and the figures
themselves; with more cores the wall time is bounded by the longest single
part chain (Fig. 11's assembly after its slowest slice, Fig. 16's fold-seed
part), so it levels off at a few minutes beyond about 8 cores.
"""
import json
import math
import os
import resource
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


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


GEAR = {"RHO": "15", "MU": "-5"}   # a side-stay geometry no driver was tuned at
DESIGN_POINT = """
import json, sys, tempfile
from mlgshimmy.studies import design_map
out = design_map.compute(float(sys.argv[1]), float(sys.argv[2]), tempfile.mkdtemp(dir=sys.argv[3]))
print(json.dumps(out["cpu_seconds"]))
"""


def timed(argv, env):
    """(wall seconds, CPU seconds of it and its children, exit status) of a command."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.monotonic()
    proc = subprocess.run(argv, cwd=ROOT, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return time.monotonic() - started, cpu, proc


def gear_rows():
    """Fig. 11 (make -j2, from scratch) and one design-map point at the
    paper's gear and at GEAR: printed rows, exit status 1 if a run failed."""
    bench = os.path.join(ROOT, "build", "bench")
    status = 0
    for label, gear in (("the paper's gear", {}), (", ".join(f"{k}={v}" for k, v in GEAR.items()),
                                                   GEAR)):
        tag = "-".join(f"{k.lower()}{v}" for k, v in gear.items()) or "paper"
        run_root = os.path.join(bench, f"fig11-{tag}")
        shutil.rmtree(run_root, ignore_errors=True)
        wall, cpu, proc = timed(["make", "-j2", "--no-print-directory", "fig11"]
                                + [f"{k}={v}" for k, v in gear.items()],
                                dict(os.environ, MLG_RUN_ROOT=run_root))
        with open(os.path.join(bench, f"fig11-{tag}.log"), "w") as log:
            log.write(proc.stdout)
        print(f"bench_figures: fig11 at {label}: make -j2 {wall / 60:.1f} min wall, "
              f"{cpu / 60:.1f} CPU-min" + ("" if proc.returncode == 0 else
                                           f" FAILED (log build/bench/fig11-{tag}.log)"),
              flush=True)
        status |= proc.returncode != 0
        rho, mu = float(gear.get("RHO", 0)), float(gear.get("MU", 0))
        _, _, proc = timed([sys.executable, "-c", DESIGN_POINT, str(rho), str(mu), bench],
                           dict(os.environ, PYTHONPATH=os.path.join(ROOT, "drivers")))
        if proc.returncode != 0:
            print(f"bench_figures: design-map point at {label} FAILED:\n{proc.stdout[-2000:]}")
            status = 1
            continue
        seconds = json.loads(proc.stdout.splitlines()[-1])
        print(f"bench_figures: design-map point at {label}: {sum(seconds.values()):.1f} s of "
              "CPU (" + ", ".join(f"{k} {v:.1f}" for k, v in seconds.items()) + ")", flush=True)
    return status


def run_dirs(run_root):
    """Every directory under run_root holding b-files, relative to it."""
    return sorted(os.path.relpath(d, run_root) for d, _, files in os.walk(run_root)
                  if any(f.startswith("b.") for f in files))


def data_lines(path):
    """The solution lines of a b-file (header lines, which name files and
    constants, start with 0)."""
    with open(path) as f:
        return [line for line in f if line.split()[:1] not in ([], ["0"])]


def differences(one, two):
    """What differs between the b-files of directory `one` and their twins in
    `two`, every saved point and digit ('' if nothing).  The two suites run
    the same AUTO runs with one thread each, so the job order must not change
    a bit."""
    out = []
    for name in sorted(f for f in os.listdir(one) if f.startswith("b.")):
        theirs = os.path.join(two, name)
        if not os.path.exists(theirs):
            out.append(f"{name}: missing in {two}")
            continue
        a, b = data_lines(os.path.join(one, name)), data_lines(theirs)
        first = next((k for k, (x, y) in enumerate(zip(a, b)) if x != y), None)
        if first is not None or len(a) != len(b):
            out.append(f"{name}: {len(a)} vs {len(b)} lines" + (
                "" if first is None else f", first difference:\n  {a[first].rstrip()}\n"
                f"  {b[first].rstrip()}"))
    return "\n".join(out)


def comparable(value):
    """value with NaN as None: a NaN never equals itself, and the cache
    stores no NaN since it refuses them (older results held some)."""
    if isinstance(value, float) and math.isnan(value):
        return None
    if isinstance(value, dict):
        return {k: comparable(v) for k, v in value.items()}
    if isinstance(value, list):
        return [comparable(v) for v in value]
    return value


def results(run_root):
    """{relative path: data} of every cached result and part (result.json,
    parts/*.json) under run_root; their provenance is left out."""
    out = {}
    for d, _, files in os.walk(run_root):
        for name in files:
            path = os.path.join(d, name)
            if name == "result.json" or os.path.basename(d) == "parts" and name.endswith(".json"):
                with open(path) as f:
                    stored = json.load(f)
                if isinstance(stored, dict) and "data" in stored:
                    out[os.path.relpath(path, run_root)] = comparable(stored["data"])
    return out


def compare(one, two, what="-j2 vs -j1"):
    """Exit status of comparing the run roots of two suites: every b-file's
    points bitwise, and every cached result's data."""
    dirs = run_dirs(one)
    differ = {d: differences(os.path.join(one, d), os.path.join(two, d)) for d in dirs}
    differ = {d: report for d, report in differ.items() if report}
    missing = sorted(set(run_dirs(two)) ^ set(dirs))
    print(f"bench_figures: {len(dirs)} run directories compared, {what} (bitwise): "
          + ("all agree" if not differ and not missing else
             f"DIFFERENT {sorted(differ)}, only in one {missing}"))
    for d, report in differ.items():
        print(f"--- {d}\n{report[:2000]}")
    ours, theirs = results(one), results(two)
    data_differ = sorted(k for k in set(ours) & set(theirs) if ours[k] != theirs[k])
    data_missing = sorted(set(ours) ^ set(theirs))
    print(f"bench_figures: {len(set(ours) & set(theirs))} cached results and parts compared, "
          f"{what}: " + ("all agree" if not data_differ and not data_missing else
                        f"DIFFERENT {data_differ}, only in one {data_missing}"))
    return 1 if differ or missing or data_differ or data_missing else 0


def main():
    os.makedirs(os.path.join(ROOT, "build", "bench"), exist_ok=True)
    if sys.argv[1:] == ["--compare-only"]:
        sys.exit(compare(os.path.join(ROOT, "build", "bench", "j1"),
                         os.path.join(ROOT, "build", "bench", "j2")))
    if sys.argv[1:2] == ["--compare"] and len(sys.argv) == 4:   # two suites of your own
        sys.exit(compare(sys.argv[2], sys.argv[3], f"{sys.argv[2]} vs {sys.argv[3]}"))
    if sys.argv[1:] == ["--gear-rows"]:
        sys.exit(gear_rows())
    serial, one = suite(1)
    print(f"bench_figures: make -j1 figures {serial / 60:.1f} min", flush=True)
    parallel, two = suite(2)
    print(f"bench_figures: make -j2 figures {parallel / 60:.1f} min; ratio -j2/-j1 "
          f"{parallel / serial:.2f} (goal <= 0.55)", flush=True)
    status = compare(one, two)
    sys.exit(gear_rows() or status)


if __name__ == "__main__":
    main()
