"""Benchmark of the figure suite: wall time of `make -j1 figures` and
`make -j2 figures`, each from scratch in its own run root (build/bench/j1,
build/bench/j2) of an otherwise built tree, in one session; then every run
directory of the two compared, every saved point of every b-file (the -j2
suite must produce the same diagrams, bit for bit).  About 25 min on 2 idle
cores: run it through `make bench-figures`, on a machine left otherwise
idle; `--compare-only` repeats the comparison of the last two suites, and
`--compare ROOT1 ROOT2` compares any two run roots (e.g. a suite before and
after a change).

The parallel work is the parts of Figs. 11, 13, 14 and 16 and the figures
themselves; with more cores the wall time is bounded by the longest single
part chain (Fig. 11's assembly after its slowest slice, Fig. 16's fold-seed
part), so it levels off at a few minutes beyond about 8 cores.
"""
import json
import math
import os
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
    serial, one = suite(1)
    print(f"bench_figures: make -j1 figures {serial / 60:.1f} min", flush=True)
    parallel, two = suite(2)
    print(f"bench_figures: make -j2 figures {parallel / 60:.1f} min; ratio -j2/-j1 "
          f"{parallel / serial:.2f} (goal <= 0.55)", flush=True)
    sys.exit(compare(one, two))


if __name__ == "__main__":
    main()
