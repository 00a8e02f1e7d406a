"""Grids of independent jobs (the side-stay sweep, the attractor atlas): the
axis values a user types, checked before any job runs.

An axis is "a,b,c" (values) or "start:stop:step" (start, start + step, ...
up to stop inclusive), or several of these joined by commas.  Every value
must be a finite number.  Two spellings of one value (10 and 1e1, 0 and
-0) are one point; two different values may not share a job (job names use
6 significant digits, f"{value:g}").  A grid has at most MAX_POINTS points
unless MLG_GRID_MAX_POINTS says otherwise, and a range is counted before
it is listed, so a tiny step is refused at once.

A point's result ($MLG_RUN_ROOT/<tool>/<name>/result.json, Plane.write)
records its provenance: git commit, AUTO version, parameter set and the
study's settings.  `jobs --missing` prints the jobs of the points without a
valid result (none, unreadable, or recorded with another provenance than a
job records now), so that resubmitting the same command redoes just those;
`status` lists every such point with its index; `summary` refuses while
one is missing or when the results' provenances differ (naming the points),
unless --mixed-provenance.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import shlex
import sys
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple

from mlgshimmy.shared import number_text, paths
from mlgshimmy.shared.jobs import cache
from mlgshimmy.shared.jobs.atomic import write_json
from mlgshimmy.shared.jobs.cli import job_line


MAX_POINTS = 2000       # points of one grid (about 4 h of sweep points on 2 cores)
MAX_POINTS_ENV = "MLG_GRID_MAX_POINTS"


def max_points() -> int:
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
    value = number_text.parse(item)
    if value is None:
        raise GridError(f"{variable}={text!r}: {item.strip()!r} is not a number "
                        f"(give comma-separated {unit}, or start:stop:step; each "
                        f"{number_text.SYNTAX})")
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


def axis(text: str, variable: str, unit: str = "numbers") -> List[float]:
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


def plane(first: Sequence[float], second: Sequence[float]) -> List[Tuple[float, float]]:
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
    $MLG_RUN_ROOT/<tool>/<name>/result.json (write(): atomically, with the
    provenance a job records now: git commit, AUTO version, parameter set
    and the study's settings())."""

    def __init__(self, first, second, tool, parameter_set="figures", settings=dict,
                 noun="points"):
        self.first, self.second, self.tool = first, second, tool
        self.parameter_set, self.settings, self.noun = parameter_set, settings, noun

    @property
    def directory(self) -> str:
        return paths.under_root(self.tool)

    def name(self, a: float, b: float) -> str:
        return f"{self.first}{a:g}_{self.second}{b:g}"

    def parse(self, name: str) -> Tuple[float, float]:
        """(a, b) of a job name; ValueError if it is not one."""
        a, b = name[len(self.first):].split(f"_{self.second}")
        return float(a), float(b)

    def result_path(self, a: float, b: float) -> str:
        return os.path.join(self.directory, self.name(a, b), "result.json")

    def provenance(self) -> Dict[str, Any]:
        """What a job records now (as JSON reads it back: tuples are lists)."""
        record = dict(cache.provenance(self.parameter_set), settings=self.settings())
        return json.loads(json.dumps(record))

    def write(self, a: float, b: float, result: Mapping[str, Any],
              provenance: Optional[Mapping[str, Any]] = None) -> str:
        """result.json of point (a, b): the result and its provenance,
        written whole or not at all (make and `status` see a result only
        when it is complete)."""
        record = dict(result, provenance=provenance or self.provenance())
        return write_json(self.result_path(a, b), record, indent=1)


# --- the state of a grid's results --------------------------------------------

DONE = "done"
MISSING = "missing"              # no result.json, never started
NO_RESULT = "no result"          # started (its directory exists), no result.json
UNREADABLE = "unreadable"        # result.json is not a JSON record
OTHER = "other provenance"       # a result, but not what a job writes now
NOT_COMPARED = ("written",)      # provenance fields that may differ between points


def comparable(provenance: Optional[Mapping[str, Any]]) -> Optional[Dict[str, Any]]:
    """The provenance fields two points must share (all but when written);
    None for a record without one."""
    if not isinstance(provenance, dict):
        return None
    return {k: v for k, v in provenance.items() if k not in NOT_COMPARED}


def differences(ours: Optional[Mapping[str, Any]], theirs: Optional[Mapping[str, Any]]) -> str:
    """The fields in which two comparable provenances differ, as text:
    'git_commit 1a2b3c4d5e6f (not 5d6e7f8a9b0c)'."""
    if ours is None:
        return "no provenance recorded"
    if theirs is None:
        return described(ours)
    return ", ".join(f"{k} {_short(ours.get(k))} (not {_short(theirs.get(k))})"
                     for k in _fields(ours, theirs) if ours.get(k) != theirs.get(k))


def described(provenance: Optional[Mapping[str, Any]],
              fields: Optional[Sequence[str]] = None) -> str:
    """'git_commit ..., auto_version ...' of the given fields (default all)."""
    if provenance is None:
        return "no provenance"
    return ", ".join(f"{k} {_short(provenance.get(k))}"
                     for k in _fields(provenance, {}) if fields is None or k in fields)


def _fields(ours, theirs):
    return sorted(set(ours) | set(theirs),
                  key=lambda k: (k not in ("git_commit", "auto_version"), k))


def _short(value):
    text = json.dumps(value) if isinstance(value, (dict, list)) else str(value)
    if len(text) == 40 or (len(text) == 46 and text.endswith("+dirty")):
        text = text[:12] + text[40:]             # a commit
    return text if len(text) <= 60 else text[:57] + "..."


class Point:
    """One grid point's result: its index (its line in `jobs`: the array
    index of a submission of the whole grid, one line per task), name,
    path, state, what is wrong (detail) and the record (if readable)."""

    def __init__(self, index, point, name, path, state, detail="", record=None):
        self.index, self.point, self.name, self.path = index, point, name, path
        self.state, self.detail, self.record = state, detail, record

    def line(self) -> str:
        return f"  {self.state:<16} index {self.index:<4} {self.name}: {self.detail}"


def survey(plane: Plane, points: Sequence[Tuple[float, float]],
           expected: Optional[Mapping[str, Any]] = None) -> List[Point]:
    """Every point's Point, in the order of `jobs`.  With expected (a
    comparable provenance), a readable result recorded otherwise is OTHER."""
    found = []
    for index, (a, b) in enumerate(points, start=1):
        path = plane.result_path(a, b)
        name = plane.name(a, b)
        try:
            with open(path) as source:
                record = json.load(source)
            if not isinstance(record, dict):
                raise ValueError(f"a JSON {type(record).__name__}, not a record")
        except FileNotFoundError:
            if os.path.isdir(os.path.dirname(path)):
                found.append(Point(index, (a, b), name, path, NO_RESULT,
                                   f"{os.path.dirname(path)} exists but holds no result.json "
                                   "(the job failed, was killed, or is running)"))
            else:
                found.append(Point(index, (a, b), name, path, MISSING,
                                   f"no {path} (never run)"))
            continue
        except (OSError, ValueError) as exc:
            found.append(Point(index, (a, b), name, path, UNREADABLE,
                               f"{path} unreadable ({type(exc).__name__}: {exc})"))
            continue
        ours = comparable(record.get("provenance"))
        if expected is not None and ours != expected:
            found.append(Point(index, (a, b), name, path, OTHER,
                               f"recorded with {differences(ours, expected)}; a job now "
                               "records the latter", record))
        else:
            found.append(Point(index, (a, b), name, path, DONE, "", record))
    return found


def report(tool: str, found: Sequence[Point], what: str = "points") -> int:
    """Counts by state, then every point without a valid result; the number
    of those."""
    counts = {}
    for point in found:
        counts[point.state] = counts.get(point.state, 0) + 1
    print(f"{tool}: {len(found)} {what}: "
          + ", ".join(f"{n} {state}" for state, n in counts.items()))
    bad = [point for point in found if point.state != DONE]
    for point in bad:
        print(point.line())
    return len(bad)


def provenance_groups(found: Sequence[Point]
                      ) -> List[Tuple[Optional[Dict[str, Any]], List[Point]]]:
    """[(comparable provenance, [Point ...])] of readable points, the
    largest group first."""
    groups = []
    for point in found:
        key = comparable(point.record.get("provenance"))
        for value, members in groups:
            if value == key:
                members.append(point)
                break
        else:
            groups.append((key, [point]))
    return sorted(groups, key=lambda group: -len(group[1]))


def mixed_provenance(tool: str, groups: Sequence[Tuple[Optional[Dict[str, Any]], List[Point]]],
                     noun: str = "points") -> str:
    """The text that names the points whose provenance differs from the
    largest group's."""
    base, largest = groups[0]
    fields = {k for value, _ in groups[1:] for k in _fields(value or {}, base or {})
              if (value or {}).get(k) != (base or {}).get(k)}
    lines = [f"{tool}: the results have {len(groups)} different provenances: {len(largest)} "
             f"{noun} (e.g. {', '.join(p.name for p in largest[:3])}) with "
             f"{described(base, fields)}, and"]
    for value, members in groups[1:]:
        lines.append(f"  {len(members)} with {differences(value, base)}: "
                     + ", ".join(f"{p.name} (index {p.index})" for p in members))
    return "\n".join(lines)


# --- the command line ----------------------------------------------------------

def main(tool: str, description: str, job_command: str, plane: Plane,
         options: Sequence[Tuple[str, str, str]], grid: Callable[[Any], List[Tuple[float, float]]],
         *, run_job: Callable[[str], None],
         problem: Callable[[Tuple[float, float]], Optional[str]], summary: Callable[..., None],
         argv: Optional[Sequence[str]] = None) -> None:
    """The command line of a job-grid study mlgshimmy.studies.<tool>:
    `check|targets|jobs [--missing]|status|summary [--mixed-provenance]|
    <job_command> NAME [--<axis> ...]`.  options: (flag, default, help) per
    axis; grid(args): the points (a GridError ends the process naming the
    axis's variable); summary(points, records, provenance): the points'
    records (without their provenance) and the one provenance they share
    (None if mixed and allowed)."""
    parser = argparse.ArgumentParser(
        prog=f"python3 -m mlgshimmy.studies.{tool}", description=description,
        epilog="A point's index is its line in `jobs` (the array index when the whole "
               "grid is submitted one line per task).")
    parser.add_argument("command",
                        choices=["check", "targets", "jobs", "status", job_command, "summary"])
    parser.add_argument("name", nargs="?",
                        help=f"{plane.first}<value>_{plane.second}<value> ({job_command} only)")
    for flag, default, text in options:
        parser.add_argument(flag, default=default, help=text)
    parser.add_argument("--missing", action="store_true",
                        help="jobs: only the points without a valid result (none, unreadable, "
                             "or another provenance than a job records now)")
    parser.add_argument("--mixed-provenance", action="store_true",
                        help="summary: accept results of different provenances (git commit, "
                             "AUTO version, settings), naming them, instead of refusing")
    args = parser.parse_args(argv)
    try:
        points = grid(args)
    except GridError as exc:
        sys.exit(f"{tool}: grid rejected: {exc}")
    axes = " ".join(f"{flag}={shlex.quote(getattr(args, flag.lstrip('-')))}"
                    for flag, _, _ in options)
    dispatch(tool, job_command, args, points, plane, axes, run_job=run_job, problem=problem,
             summary=summary)


def validate(tool: str, points: Sequence[Tuple[float, float]],
             problem: Callable[[Tuple[float, float]], Optional[str]], noun: str) -> None:
    """Every point checked before any job runs: problem(point) says why one
    is rejected (None: valid); any rejected point ends the process, each
    listed."""
    bad = [why for why in map(problem, points) if why]
    if bad:
        sys.exit(f"{tool}: grid rejected before any run:\n  " + "\n  ".join(bad))
    print(f"{tool}: {len(points)} {noun} valid")


def dispatch(tool: str, job_command: str, args: Any, points: Sequence[Tuple[float, float]],
             plane: Plane, axes: Sequence[Any], *, run_job: Callable[[str], None],
             problem: Callable[[Tuple[float, float]], Optional[str]],
             summary: Callable[..., None]) -> None:
    """The commands every job-grid study has: check, targets, jobs (one
    shell line per job, for make, GNU parallel or Slurm; --missing: only
    those without a valid result), status (every point without one, with
    its index; exit 1 if any), summary (refused, listing them, while a point
    has no result or the results' provenances differ), and job_command NAME
    (one job).  A missing or rejected job name (ValueError from run_job), or
    a job that fails (RuntimeError: AUTO's, the model's), ends the process
    with a message naming it."""
    module = f"mlgshimmy.studies.{tool}"
    missing_jobs = f"python3 -m {module} jobs --missing {axes}"
    if args.command == "targets":
        print(" ".join(plane.result_path(*p) for p in points))
    elif args.command == "jobs":
        chosen = points
        if args.missing:
            chosen = [p.point for p in survey(plane, points, comparable(plane.provenance()))
                      if p.state != DONE]
            print(f"{tool}: {len(chosen)} of {len(points)} {plane.noun} without a valid "
                  "result",
                  file=sys.stderr)
        for point in chosen:
            print(job_line(module, job_command, plane.name(*point)))
    elif args.command == "status":
        found = survey(plane, points, comparable(plane.provenance()))
        bad = report(tool, found, plane.noun)
        if bad:
            sys.exit(f"{tool}: {bad} of {len(found)} {plane.noun} without a valid result; "
                     f"`{missing_jobs}` prints their jobs")
        print(f"{tool}: all {len(found)} {plane.noun} have a valid result")
    elif args.command == "check":
        validate(tool, points, problem, plane.noun)
    elif args.command == "summary":
        found = survey(plane, points)
        bad = [point for point in found if point.state != DONE]
        if bad:
            report(tool, found, plane.noun)
            sys.exit(f"{tool}: summary refused: {len(bad)} of {len(found)} {plane.noun} have no "
                     f"result (listed above); `{missing_jobs}` prints their jobs")
        groups = provenance_groups(found)
        if len(groups) > 1:
            text = mixed_provenance(tool, groups, plane.noun)
            if not args.mixed_provenance:
                sys.exit(f"{text}\n{tool}: summary refused: it would mix them; recompute the "
                         f"others (`{missing_jobs}` prints the jobs of those a job now "
                         "records otherwise) or pass --mixed-provenance")
            print(f"{text}\n{tool}: mixing them, as --mixed-provenance asks", file=sys.stderr)
        shared = groups[0][0] if len(groups) == 1 else None
        current = comparable(plane.provenance())
        if shared is not None and shared != current:
            changed = {k for k in _fields(shared, current or {})
                       if shared.get(k) != (current or {}).get(k)}
            print(f"{tool}: note: the results were recorded with {described(shared, changed)}; "
                  f"a job now records {described(current, changed)}")
        records = [{k: v for k, v in p.record.items() if k != "provenance"} for p in found]
        summary(points, records, groups[0][1][0].record.get("provenance")
                if shared is not None else None)
    elif args.name is None:
        sys.exit(f"{tool}: {job_command} needs a job name, e.g. {plane.name(*points[0])}")
    else:
        try:
            run_job(args.name)
        except ValueError as exc:
            sys.exit(f"{tool}: {args.name} rejected: {exc}")
        except RuntimeError as exc:     # runerror.RunError (a failed run, mlg.exe out of date)
            sys.exit(f"{tool}: {args.name}: {exc}")
