"""The command lines of the figure and study drivers, and the one shell
line per job that make, GNU parallel and Slurm run."""
from __future__ import annotations

import argparse
import os
import shlex
import shutil
import sys
import time
from typing import Callable, List, Optional, Sequence, Tuple

from mlgshimmy.shared import gear, mlgmodel, paths
from mlgshimmy.shared.jobs import cache
from mlgshimmy.shared.jobs.atomic import write_text
from mlgshimmy.shared.jobs.parts import Parts, rules_path

PACKAGE_DIR = os.path.join(paths.ROOT, "drivers")


def job_line(module: str, *args: str) -> str:
    """One self-contained shell command that runs `python -m <module> args`
    from the repository, with the package on its path."""
    words = [sys.executable, "-m", module, *map(str, args)]
    return (f"cd {shlex.quote(paths.ROOT)} && PYTHONPATH={shlex.quote(PACKAGE_DIR)} "
            + " ".join(shlex.quote(w) for w in words))


def parts_status(jobs: Parts) -> int:
    """Print each stage's count of cached parts and every part not cached,
    with its index (its line in `jobs --stage K`: the array index of stage K
    submitted whole); the number of those."""
    missing = 0
    for stage in range(1, jobs.stages() + 1):
        names = jobs.of_stage(stage)
        absent = [(index, name) for index, name in enumerate(names, start=1)
                  if not os.path.exists(cache.path(jobs.figure, name))]
        print(f"{jobs.figure}: stage {stage}: {len(names) - len(absent)} of {len(names)} "
              "parts cached")
        for index, name in absent:
            print(f"  missing  stage {stage}, index {index:<3} {name}: no "
                  f"{cache.path(jobs.figure, name)}")
        missing += len(absent)
    return missing


def variant_option(figure: str, doc: str) -> Tuple[int, str, List[str]]:
    """A driver's --strut-variant option (0: the default strut, 1: the
    printed one) read from the command line: (variant, figure name: <figure>
    or <figure>_v<variant>, the other arguments for run_figure)."""
    parser = argparse.ArgumentParser(description=doc, add_help=False)
    parser.add_argument("--strut-variant", type=int, choices=(0, 1), default=0)
    args, rest = parser.parse_known_args()
    variant = args.strut_variant
    return variant, figure if variant == 0 else f"{figure}_v{variant}", rest


def run_variant_figure(figure: str, doc: str, compute: Callable, plot: Callable) -> None:
    """run_figure for a figure with a --strut-variant option (variant_option):
    compute(name, variant), the cached result named <figure> or
    <figure>_v<variant>."""
    variant, name, rest = variant_option(figure, doc)
    run_figure(name, lambda: compute(name, variant), plot, argv=rest,
               module=f"mlgshimmy.figures.{figure}")


def run_figure(figure: str, compute: Callable, plot: Callable, parts: Optional[Callable] = None,
               parameter_set: str = "figures", argv: Optional[Sequence[str]] = None,
               module: Optional[str] = None) -> None:
    """A figure driver's command line.  --compute: compute() (AUTO runs and
    the rest) and cache what it returns; --plot: plot(cached result) (the
    figure and its table); neither: both, from scratch.  A failure exits
    non-zero naming the figure (RunError and the model's errors are
    RuntimeError or ValueError).

    With parts (a function returning {name: function or Needs}, see
    Parts), compute gets the Parts and: `parts` lists their names, `rules`
    writes mk/parts.mk's rules to $MLG_RUN_ROOT/<fig>/parts.mk, `jobs
    [--stage K] [--missing]` prints one shell command per part of stage K
    (default 1; --missing: per part not cached, so that resubmitting the
    same command redoes just those; `stages` prints how many stages there
    are; a K outside them is an error), `status` lists every part not
    cached with its stage and index (exit 1 if any), `--part NAME` computes
    one, --compute uses those cached."""
    module = module or f"mlgshimmy.figures.{figure}"
    commands = ["parts", "stages", "rules", "jobs", "status"] if parts else []
    parser = argparse.ArgumentParser(prog=f"python3 -m {module}",
                                     description=f"{figure}: compute and cache, and/or plot")
    parser.add_argument("command", nargs="?", choices=commands,
                        help="list the parts, count their stages, write their make rules, "
                             "print one shell command per part of a stage, or list the parts "
                             "not cached")
    parser.add_argument("--compute", action="store_true", help="only compute and cache")
    parser.add_argument("--plot", action="store_true", help="only redraw from the cache")
    if parts:
        parser.add_argument("--part", help="compute and cache one part")
        parser.add_argument("--stage", type=int, default=1,
                            help="the stage whose parts `jobs` prints (default 1)")
        parser.add_argument("--missing", action="store_true",
                            help="jobs: only the parts not cached ($MLG_RUN_ROOT/<fig>/parts/"
                                 "<name>.json absent)")
    args = parser.parse_args(argv)
    both = not (args.compute or args.plot or getattr(args, "part", None))
    try:
        # before anything is written: a rejected gear (a SET out of range)
        # stops here naming it and leaves no directory of its tree.  `rules` in
        # a dry run before the library is built (make -n in a fresh clone) has
        # nothing to check with: --compute checks when it runs
        computes = args.command is None and (getattr(args, "part", None) or args.compute or both)
        if computes or (args.command == "rules" and os.path.exists(mlgmodel.LIBRARY)):
            gear.check()
        jobs = Parts(figure, parts(), parameter_set) if parts else None
        if args.command == "parts":
            print(" ".join(jobs.jobs))
            return
        if args.command == "stages":
            print(jobs.stages())
            return
        if args.command == "rules":
            write_text(rules_path(figure), jobs.make_rules())
            return
        if args.command == "jobs":
            names = jobs.of_stage(args.stage)
            if args.missing:
                names = [name for name in names if not os.path.exists(cache.path(figure, name))]
                print(f"{figure}: stage {args.stage}: {len(names)} of "
                      f"{len(jobs.of_stage(args.stage))} parts not cached", file=sys.stderr)
            for name in names:
                print(job_line(module, "--part", name))
            return
        if args.command == "status":
            missing = parts_status(jobs)
            if missing:
                sys.exit(f"{figure}: {missing} parts not cached; `python3 -m {module} jobs "
                         "--stage K --missing` prints the jobs of stage K's")
            print(f"{figure}: every part is cached")
            return
        if getattr(args, "part", None):
            jobs.compute(args.part, alone=True)
        if args.compute or both:
            if both and jobs:   # from scratch: no part of an earlier run is reused
                shutil.rmtree(os.path.dirname(cache.path(figure, "x")), ignore_errors=True)
            started = time.monotonic()
            if cache.compute_once(figure, lambda: compute(jobs) if jobs else compute(),
                                  parameter_set):
                print(f"{figure}: computed in {time.monotonic() - started:.0f} s")
        if args.plot or both:
            plot(cache.read(figure))
    except (RuntimeError, ValueError) as exc:   # GeometryError and OverlayError too
        message = str(exc)   # a MissingResult already names its figure
        sys.exit(message if message.startswith(f"{figure}:") else f"{figure}: {message}")
    except OSError as exc:   # a full disk, a directory that cannot be written
        sys.exit(f"{figure}: {exc.strerror}: {exc.filename or ''} (nothing half-written is "
                 "left: every result is written beside and renamed)")
