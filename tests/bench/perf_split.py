"""Where the CPU time of a benchmark goes: run a command under `perf record`
and sort the samples into the model library, libm, string handling, AUTO,
libgomp (OpenMP), Python and the rest, over all processes and for each AUTO
process (mlg.exe) in start order.  Used by bench_auto_jacobian.py."""
import os
import re
import shutil
import subprocess
import sys

# perf report --sort pid,dso,sym:  "  8.60%  14942:mlg.exe  mlg.exe  [.] conpar"
SAMPLE = re.compile(r"^\s*([\d.]+)%\s+(\d+):(\S+)\s+(\S+)\s+\[(.)\]\s+(\S+)")
STRING_FUNCTIONS = re.compile(r"^__?(strcmp|strncmp|strlen|strcasecmp|memcmp|strchr)")
CATEGORIES = ("model library (c/, models/mlg.c)", "libm", "string handling (strcmp ...)",
              "AUTO (Fortran and C, libgfortran)", "libgomp (OpenMP runtime)", "Python",
              "kernel and other")


def available():
    """None if `perf record` works here, else why not."""
    if shutil.which("perf") is None:
        return "perf is not installed"
    probe = subprocess.run(["perf", "record", "-q", "-o", os.devnull, "--", "true"],
                           capture_output=True, text=True)
    if probe.returncode != 0:
        return "perf record is not permitted: " + probe.stderr.strip().splitlines()[-1]
    return None


def own_symbols(objects):
    """Function names defined in our object files (nm), clone suffixes dropped."""
    names = set()
    for path in objects:
        out = subprocess.run(["nm", "--defined-only", path], capture_output=True, text=True,
                             check=True).stdout
        for line in out.splitlines():
            parts = line.split()
            if len(parts) == 3 and parts[1] in "tTW":
                names.add(parts[2].split(".")[0])
    return names


def category(comm, dso, kind, sym, ours):
    if kind == "k":
        return CATEGORIES[6]
    if comm.startswith("python"):
        return CATEGORIES[5]
    if dso.startswith("libm.") or dso.startswith("libm-"):
        return CATEGORIES[1]
    if dso.startswith("libgomp"):
        return CATEGORIES[4]
    if STRING_FUNCTIONS.match(sym):
        return CATEGORIES[2]
    if dso.startswith("libgfortran") or (dso == comm and sym.split(".")[0] not in ours):
        return CATEGORIES[3]
    if dso == comm:
        return CATEGORIES[0]
    return CATEGORIES[6]


def record(command, data, env=None):
    """Run command under perf record (samples to data); its exit status."""
    return subprocess.run(["perf", "record", "-q", "-o", data, "--"] + command, env=env).returncode


def split(data, objects):
    """{'all': {category: %}, pid: {category: %}, ...} from perf's report of data."""
    report = subprocess.run(["perf", "report", "-i", data, "--stdio", "--no-children", "-q",
                             "--sort", "pid,dso,sym"],
                            capture_output=True, text=True, check=True).stdout
    ours = own_symbols(objects)
    shares = {"all": dict.fromkeys(CATEGORIES, 0.0)}
    for line in report.splitlines():
        m = SAMPLE.match(line)
        if not m:
            continue
        pct, pid, comm, dso, kind, sym = float(m[1]), int(m[2]), m[3], m[4], m[5], m[6]
        where = category(comm, dso, kind, sym, ours)
        shares["all"][where] += pct
        if comm == "mlg.exe":
            shares.setdefault(pid, dict.fromkeys(CATEGORIES, 0.0))[where] += pct
    return shares


def print_split(shares, run_names):
    """The table: one column for all samples, one per AUTO process (named in start order)."""
    pids = sorted(k for k in shares if k != "all")
    names = [run_names[i] if i < len(run_names) else str(pid) for i, pid in enumerate(pids)]
    print("  profile (perf record, share of all samples in %):")
    print("    " + f"{'where':36s}" + f"{'all':>7s}" + "".join(f"{n:>9s}" for n in names))
    for c in CATEGORIES:
        print("    " + f"{c:36s}" + f"{shares['all'][c]:7.1f}"
              + "".join(f"{shares[p][c]:9.1f}" for p in pids))


if __name__ == "__main__":
    sys.exit("perf_split.py is a module of tests/bench/bench_auto_jacobian.py")
