"""Grids of independent jobs (the side-stay sweep, the attractor atlas): the
axis values a user types, checked before any job runs.

An axis is "a,b,c" (values) or "start:stop:step" (start, start + step, ...
up to stop inclusive), or several of these joined by commas.  Every value
must be a finite number.  Two spellings of one value (10 and 1e1, 0 and
-0) are one point; two different values may not share a job (job names use
6 significant digits, f"{value:g}").  A grid has at most MAX_POINTS points
unless MLG_GRID_MAX_POINTS says otherwise, and a range is counted before
it is listed, so a tiny step is refused at once.
"""
import argparse
import math
import os
import sys

from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs.cli import job_line


MAX_POINTS = 2000       # points of one grid (about 4 h of sweep points on 2 cores)
MAX_POINTS_ENV = "MLG_GRID_MAX_POINTS"


def max_points():
    """The grid size limit: MLG_GRID_MAX_POINTS if set (checked), else MAX_POINTS."""
    text = os.environ.get(MAX_POINTS_ENV)
    if text is None:
        return MAX_POINTS
    if not (text.isdigit() and int(text) >= 1):
        raise GridError(f"{MAX_POINTS_ENV}={text!r} must be a whole number >= 1")
    return int(text)


class GridError(ValueError):
    """An axis that is not a list of distinct numbers (named by its variable)."""


def _number(item, text, variable, unit):
    try:
        value = float(item)
    except ValueError:
        raise GridError(f"{variable}={text!r}: {item.strip()!r} is not a number "
                        f"(give comma-separated {unit}, or start:stop:step)") from None
    if not math.isfinite(value):
        raise GridError(f"{variable}={text!r}: {item.strip()!r} is not finite")
    return value


def _range(item, text, variable, unit):
    start, stop, step = (_number(part, text, variable, unit) for part in item.split(":"))
    if not step > 0 or stop < start:
        raise GridError(f"{variable}={text!r}: {item.strip()!r} needs step > 0 and "
                        "stop >= start")
    count = math.floor((stop - start) / step + 1e-9) + 1
    if count > max_points():
        raise GridError(f"{variable}={text!r}: {item.strip()!r} has {count:.3g} values, more "
                        f"than the limit of {max_points()} points of a grid (raise it with "
                        f"{MAX_POINTS_ENV}=N)")
    return [round(start + k * step, 12) for k in range(int(count))]


def axis(text, variable, unit="numbers"):
    """The values of one axis; raises GridError naming `variable`."""
    values, names = [], {}
    for item in text.split(","):
        if item.count(":") == 2:
            items = [(value, f"{value:g}") for value in _range(item, text, variable, unit)]
        elif ":" in item:
            raise GridError(f"{variable}={text!r}: {item.strip()!r} is not start:stop:step")
        else:
            items = [(_number(item, text, variable, unit), item.strip())]
        for value, typed in items:
            value = value + 0.0          # -0 is 0
            name = f"{value:g}"
            if value in values:          # another spelling of a point listed already
                continue
            if name in names:
                raise GridError(f"{variable}={text!r}: {names[name]} and {typed} are the "
                                f"same grid point ({name}, one job); list each value once, "
                                "distinct to 6 significant digits")
            names[name] = typed
            values.append(value)
            if len(values) > max_points():
                raise GridError(f"{variable}={text!r}: more than the limit of {max_points()} "
                                f"points of a grid (raise it with {MAX_POINTS_ENV}=N)")
    return values


def plane(first, second):
    """The points of a grid over two axes (lists of values): every pair,
    refused if there are more than max_points()."""
    count = len(first) * len(second)
    if count > max_points():
        raise GridError(f"the grid has {len(first)} x {len(second)} = {count} points, more "
                        f"than the limit of {max_points()} (raise it with {MAX_POINTS_ENV}=N)")
    return [(a, b) for a in first for b in second]



class Plane:
    """The jobs of a grid over two axes: named <a><value>_<b><value> with the
    axes' prefixes a, b (values as f"{value:g}"), each writing
    $MLG_RUN_ROOT/<tool>/<name>/result.json."""

    def __init__(self, first, second, tool):
        self.first, self.second, self.tool = first, second, tool

    @property
    def directory(self):
        return paths.under_root(self.tool)

    def name(self, a, b):
        return f"{self.first}{a:g}_{self.second}{b:g}"

    def parse(self, name):
        """(a, b) of a job name; ValueError if it is not one."""
        a, b = name[len(self.first):].split(f"_{self.second}")
        return float(a), float(b)

    def result_path(self, a, b):
        return os.path.join(self.directory, self.name(a, b), "result.json")


def main(tool, description, job_command, plane, options, grid, *, run_job, check, summary):
    """The command line of a job-grid study mlgshimmy.studies.<tool>:
    `check|targets|jobs|summary|<job_command> [NAME] [--<axis> ...]`.
    options: (flag, default, help) per axis; grid(args): the points (a
    GridError ends the process naming the axis's variable)."""
    parser = argparse.ArgumentParser(prog=f"python3 -m mlgshimmy.studies.{tool}",
                                     description=description)
    parser.add_argument("command", choices=["check", "targets", "jobs", job_command, "summary"])
    parser.add_argument("name", nargs="?",
                        help=f"{plane.first}<value>_{plane.second}<value> ({job_command} only)")
    for flag, default, text in options:
        parser.add_argument(flag, default=default, help=text)
    args = parser.parse_args()
    try:
        points = grid(args)
    except GridError as exc:
        sys.exit(f"{tool}: grid rejected: {exc}")
    dispatch(tool, job_command, args, points, targets=plane.result_path, job_name=plane.name,
             run_job=run_job, check=check, summary=summary)


def dispatch(tool, job_command, args, points, *, targets, job_name, run_job, check, summary):
    """The commands every job-grid study has: check,
    targets, jobs (one shell line per job, for make, GNU parallel or Slurm),
    summary, and job_command NAME (one job).  A missing or rejected job name
    (ValueError from run_job) ends the process with a message naming it."""
    if args.command == "targets":
        print(" ".join(targets(*p) for p in points))
    elif args.command == "jobs":
        for point in points:
            print(job_line(f"mlgshimmy.studies.{tool}", job_command, job_name(*point)))
    elif args.command == "check":
        check(points)
    elif args.command == "summary":
        summary(points)
    elif args.name is None:
        sys.exit(f"{tool}: {job_command} needs a job name, e.g. {job_name(*points[0])}")
    else:
        try:
            run_job(args.name)
        except ValueError as exc:
            sys.exit(f"{tool}: {args.name} rejected: {exc}")
