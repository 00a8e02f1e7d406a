"""The cached result of a figure's compute step: one JSON file per figure,
$MLG_RUN_ROOT/<fig>/result.json (beside its runs, so `make regress`
starting a figure afresh starts its result afresh too), holding its numbers, the curve arrays its
plot needs and where they came from (parameter set, git commit, AUTO
version).  The plot step, the tables and the reproduction numbers read it;
no AUTO import, so a redraw needs none.

    results.write("fig10", {"numbers": {...}, "eq": stored(eq, COLUMNS)}, "figures")
    result = results.read("fig10")      # raises MissingResult naming `make fig10`

Writes are atomic (written beside, then renamed): a reader sees the old
result or the new one, never a part.
"""
import argparse
import datetime
import json
import os
import shlex
import shutil
import subprocess
import sys
import time

import numpy

import branches
import paths


class MissingResult(RuntimeError):
    """No cached result for a figure (its compute step has not run)."""


def path(figure, part=None):
    """$MLG_RUN_ROOT/<fig>/result.json, or parts/<part>.json there."""
    if part is None:
        return os.path.join(paths.RUN_ROOT, figure, "result.json")
    return os.path.join(paths.RUN_ROOT, figure, "parts", f"{part}.json")


def _auto_version():
    auto_dir = os.environ.get("AUTO_DIR", os.path.join(paths.BUILD, "auto", "07p"))
    try:
        with open(os.path.join(auto_dir, "CHANGELOG")) as log:
            return log.readline().strip().rstrip(":")
    except OSError:
        return None


def _git_commit():
    """HEAD, with "+dirty" if the drivers, constants, C sources or models
    differ from it."""
    def git(*args):
        return subprocess.run(["git", "-C", paths.ROOT, *args], capture_output=True,
                              text=True).stdout.strip()
    head = git("rev-parse", "HEAD")
    dirty = git("status", "--porcelain", "--", "drivers", "constants", "c", "models")
    return (head + ("+dirty" if dirty else "")) or None


def provenance(parameter_set):
    return {"parameter_set": parameter_set, "git_commit": _git_commit(),
            "auto_version": _auto_version(),
            "written": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")}


def _plain(value):
    """value with numpy arrays and numbers as lists and floats (JSON)."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, numpy.ndarray):
        return _plain(value.tolist())
    if isinstance(value, numpy.floating):
        return float(value)
    if isinstance(value, (numpy.integer, numpy.bool_)):
        return value.item()
    return value


def write(figure, data, parameter_set="figures", part=None):
    """Store data (dicts, lists, arrays, numbers, strings; NaN and inf as
    Python's json writes and reads them) with its provenance, as the
    figure's result or one part of it; returns the path."""
    target = path(figure, part)
    os.makedirs(os.path.dirname(target), exist_ok=True)
    partial = f"{target}.{os.getpid()}.part"
    with open(partial, "w") as out:
        json.dump({"figure": figure, "part": part, "provenance": provenance(parameter_set),
                   "data": _plain(data)}, out)
    os.replace(partial, target)
    print(f"{figure}: {'part ' + part if part else 'result'} cached in "
          f"{os.path.relpath(target, paths.ROOT)}", flush=True)
    return target


def read(figure, part=None):
    """The data of a figure's cached result (or of one part of it)."""
    try:
        with open(path(figure, part)) as source:
            return json.load(source)["data"]
    except FileNotFoundError:
        raise MissingResult(f"{figure}: no cached result {path(figure, part)} "
                            f"(run `make {figure}`)") from None


class Branch:
    """A stored AUTO branch read back: columns by name (numpy arrays), and
    stability() and labels as a parseB branch has them, so the helpers of
    `branches` and `plotting` take either."""

    def __init__(self, record):
        self.columns = {k: numpy.asarray(v, dtype=float) for k, v in record["columns"].items()}
        self.coordnames = list(self.columns)
        self._stable = numpy.asarray(record["stable"], dtype=bool)
        self.labels = _Labels(record["labels"])

    def __getitem__(self, name):
        return self.columns[name]

    def __len__(self):
        return len(self._stable)

    def stability(self):
        """AUTO's encoding: the end index of each run of equal stability,
        negative for stable runs."""
        return [(-s.stop if self._stable[s.start] else s.stop)
                for s in branches.runs_of(self._stable, overlap=False)]


class _Labels:
    """branch.labels of parseB, as far as branches.labelled_points reads it."""

    def __init__(self, points):
        self._at = {}
        for index, label, kind in points:
            self._at.setdefault(index, {})[kind] = {"LAB": label}

    def getIndices(self):
        return sorted(self._at)

    def __getitem__(self, index):
        return self._at[index]


def stored(diagram, columns):
    """The branches of an AUTO diagram (a bifDiag or a list of branches) as
    records of the given columns (those a branch lacks are left out)."""
    return [{"columns": {c: numpy.asarray(b[c]) for c in columns if c in b.coordnames},
             "stable": branches.stable_mask(b),
             "labels": [list(p) for p in branches.labelled_points(b)]}
            for b in diagram]


def loaded(records):
    """Stored branches (stored()) back as Branch objects."""
    return [Branch(r) for r in records]


class Needs:
    """A part that reads other parts: function(parts), run once the parts
    named in `names` are cached (make runs it after them)."""

    def __init__(self, names, function):
        self.names, self.function = tuple(names), function


class Parts:
    """The jobs of a figure's compute step, {name: function or Needs}, each
    cached as a part (path(figure, name)) by `<fig>.py --part <name>`, so
    that make (drivers/parts.mk), GNU parallel or a Slurm array can run
    them side by side: a part of stage 1 needs no other, one of stage k + 1
    needs parts of stage k at most.  parts[name] is the cached part,
    computed here if it is missing, except in a single part's run
    (`--part`): that one refuses to compute another part, which a parallel
    job may be writing."""

    def __init__(self, figure, jobs, parameter_set):
        self.figure, self.jobs, self.parameter_set = figure, jobs, parameter_set
        self.alone = False   # in compute(name, alone=True): no other part is computed
        for name in jobs:
            self.stage(name)   # every needed part exists, no cycle

    def stage(self, name, seen=()):
        if name not in self.jobs:
            raise ValueError(f"{self.figure}: no part named {name!r} "
                             f"(parts: {' '.join(self.jobs)})")
        if name in seen:
            raise ValueError(f"{self.figure}: part {name} needs itself")
        job = self.jobs[name]
        if not isinstance(job, Needs):
            return 1
        return 1 + max(self.stage(n, seen + (name,)) for n in job.names)

    def of_stage(self, stage):
        return [name for name in self.jobs if self.stage(name) == stage]

    def compute(self, name, alone=False):
        """Compute and cache one part; alone: a missing part it needs is an
        error (a parallel job may be writing it), not computed here."""
        self.stage(name)   # a part of this figure (the error names the parts)
        job = self.jobs[name]
        started = time.monotonic()
        self.alone = alone
        try:
            data = job.function(self) if isinstance(job, Needs) else job()
        finally:
            self.alone = False
        write(self.figure, data, self.parameter_set, part=name)
        print(f"{self.figure}: part {name} computed in {time.monotonic() - started:.0f} s",
              flush=True)

    def __getitem__(self, name):
        if not os.path.exists(path(self.figure, name)):
            if self.alone:
                raise MissingResult(f"{self.figure}: part {name} is not cached yet; run the "
                                    f"parts of stage {self.stage(name)} first")
            self.compute(name)
        return read(self.figure, name)

    def all(self):
        """{name: data} of every part, in order."""
        return {name: self[name] for name in self.jobs}

    def make_rules(self):
        """drivers/parts.mk's rules: PARTS, and each part's needs as the
        prerequisites of its file."""
        def file(name):
            return path(self.figure, name)
        lines = [f"PARTS := {' '.join(self.jobs)}"]
        lines += [f"{file(name)}: {' '.join(file(n) for n in job.names)}"
                  for name, job in self.jobs.items() if isinstance(job, Needs)]
        return "\n".join(lines) + "\n"


def variant_option(figure, doc):
    """A driver's --strut-variant option (0: the default strut, 1: the
    printed one) read from the command line: (variant, figure name: <figure>
    or <figure>_v<variant>, the other arguments for run_figure)."""
    parser = argparse.ArgumentParser(description=doc, add_help=False)
    parser.add_argument("--strut-variant", type=int, choices=(0, 1), default=0)
    args, rest = parser.parse_known_args()
    variant = args.strut_variant
    return variant, figure if variant == 0 else f"{figure}_v{variant}", rest


def run_figure(figure, compute, plot, parts=None, parameter_set="figures", argv=None):
    """A figure driver's command line.  --compute: compute() (AUTO runs and
    the rest) and cache what it returns; --plot: plot(cached result) (the
    figure and its table); neither: both, from scratch.  A failure exits
    non-zero naming the figure (RunError and the model's errors are
    RuntimeError or ValueError).

    With parts (a function returning {name: function or Needs}, see
    Parts), compute gets the Parts and: `parts` lists their names, `rules`
    writes drivers/parts.mk's rules to $MLG_RUN_ROOT/<fig>/parts.mk, `jobs
    [--stage K]` prints one shell command per part of stage K (default 1;
    for GNU parallel or a Slurm array, one stage after the other; then
    --compute assembles), `--part NAME` computes one, --compute uses those
    cached."""
    parser = argparse.ArgumentParser(description=f"{figure}: compute and cache, and/or plot")
    parser.add_argument("command", nargs="?", choices=["parts", "rules", "jobs"] if parts else [],
                        help="list the parts, write their make rules, or print one shell "
                             "command per part of a stage")
    parser.add_argument("--compute", action="store_true", help="only compute and cache")
    parser.add_argument("--plot", action="store_true", help="only redraw from the cache")
    if parts:
        parser.add_argument("--part", help="compute and cache one part")
        parser.add_argument("--stage", type=int, default=1,
                            help="the stage whose parts `jobs` prints (default 1)")
    args = parser.parse_args(argv)
    both = not (args.compute or args.plot or getattr(args, "part", None))
    try:
        jobs = Parts(figure, parts(), parameter_set) if parts else None
        if args.command == "parts":
            print(" ".join(jobs.jobs))
            return
        if args.command == "rules":
            target = os.path.join(paths.RUN_ROOT, figure, "parts.mk")
            os.makedirs(os.path.dirname(target), exist_ok=True)
            with open(f"{target}.{os.getpid()}.part", "w") as out:
                out.write(jobs.make_rules())
            os.replace(f"{target}.{os.getpid()}.part", target)
            return
        if args.command == "jobs":
            if args.stage < 1:
                raise ValueError(f"--stage {args.stage}: stages count from 1")
            for name in jobs.of_stage(args.stage):
                print(f"cd {shlex.quote(paths.ROOT)} && {shlex.quote(sys.executable)} "
                      f"drivers/{figure}.py --part {name}")
            return
        if getattr(args, "part", None):
            jobs.compute(args.part, alone=True)
        if args.compute or both:
            if both and jobs:   # from scratch: no part of an earlier run is reused
                shutil.rmtree(os.path.dirname(path(figure, "x")), ignore_errors=True)
            started = time.monotonic()
            data = compute(jobs) if jobs else compute()
            write(figure, data, parameter_set)
            print(f"{figure}: computed in {time.monotonic() - started:.0f} s")
        if args.plot or both:
            plot(read(figure))
    except (RuntimeError, ValueError) as exc:
        message = str(exc)   # a MissingResult already names its figure
        sys.exit(message if message.startswith(f"{figure}:") else f"{figure}: {message}")
