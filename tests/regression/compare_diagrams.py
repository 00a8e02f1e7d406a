"""Compare AUTO-07p bifurcation diagrams (b-files) with stored references.

    compare_diagrams.py REFERENCE_DIR RUN_DIR [--runs NAME ...] [--rtol R] [--atol A]
    compare_diagrams.py --figure FIG [RUN_DIR]

(run with /usr/bin/python3 or $PYTHON from the Makefile; AUTO_DIR as for the drivers)

The reference set is checked against its MANIFEST first (reference_set.py: a
file missing, extra or changed is an error naming it). Then every run of the
set, subdirectories included (b.<name>, zero/b.<name>, ...; or only the
--runs names), is read with AUTO's own reader (auto.parseB) and compared
with the same path under RUN_DIR, and every b-file under RUN_DIR must have a
reference (of those the set's runs.json selects, if it has one):
- the same number of branches, with the same branch numbers and columns;
- per branch, the same sequence of special-point types (EP, HB, LP, UZ, ...);
- at every labelled point, every column agrees: |ours - ref| <= rtol*|ref| + atol
  (where the sequences differ: at the points before the first changed type).
Point counts, step sizes and timings are never compared.

A column <x>_mean (psi_mean, ...) vanishes by symmetry on a symmetric gear:
its absolute tolerance is rtol times the largest <x>_amp of the reference
branch, the size of the motion it is the mean of (rounding noise of 1e-8 rad
is no change; an offset of a thousandth of the amplitude is).

The defaults rtol = 1e-5 and atol = 1e-10 can be set for one figure in
REFERENCE_DIR/tolerances.json ({"rtol": 1e-4, "atol": 1e-8}); command-line
options override both. REFERENCE_DIR/labels.json lists labelled points whose
position is numerically arbitrary, with the reason; they are left out of
both sides:
    {"ignore": [{"run": "hopf_down", "type": "LP", "reason": "..."},
                {"run": "po*", "type": "TR", "from": {"V": 560}, "reason": "..."}]}
("run" is a shell pattern; "from"/"to" bound a column's value).

The report opens with every special point (HB, LP, BP, PD, TR, ...):
reference -> ours in its first column (the continued parameter), the
relative change, and the column that changed most; then the table of values
outside the tolerance (run, branch, label, type, column, reference, ours,
relative error). --figure FIG compares tests/reference/FIG with RUN_DIR
(default build/regress/FIG, where `make regress` publishes its runs).
Exit status: 0 agree, 1 differences (a run of the reference the figure no
longer writes is one), 2 a reference file missing or unreadable, or one of
ours unreadable (named).
"""
import argparse
import fnmatch
import json
import os
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
from mlgshimmy.shared import autoglue  # noqa: E402  (PYTHONPATH=drivers; AUTO through init())
import reference_set  # noqa: E402  (this directory: run as a script, or pytest's pythonpath)

REFERENCE_ROOT = os.path.join(ROOT, "tests", "reference")
REGRESS_ROOT = os.path.join(ROOT, "build", "regress")
RTOL, ATOL = 1e-5, 1e-10
TOLERANCE_FILE = "tolerances.json"
LABEL_FILE = "labels.json"
# Types that are not bifurcations: start/end points, user stops, no convergence.
NOT_SPECIAL = {"EP", "UZ", "MX", "RG", "No Label"}


class DiagramFileError(Exception):
    """A b-file or reference directory that is missing or cannot be read."""


def read_branches(path):
    """The branches of one b-file, fully parsed by auto.parseB."""
    if not os.path.isfile(path):
        raise DiagramFileError(f"{path}: no such file")
    try:
        branches = autoglue.init().parseB.parseBR(path)
        for branch in branches:  # AUTO parses lazily: force it here
            branch.coordarray  # noqa: B018
    except Exception as exc:  # any parser failure means an unreadable file
        raise DiagramFileError(f"{path}: not a readable AUTO b-file "
                               f"({type(exc).__name__}: {exc})") from exc
    if len(branches) == 0:
        raise DiagramFileError(f"{path}: not a readable AUTO b-file (no branches)")
    return branches


def labelled_points(branch):
    """[(point index, label, type)] of a branch, in order."""
    points = []
    for index in branch.labels.getIndices():
        ty, info = branch._gettypelabel(index)
        if "LAB" in info:
            points.append((index, info["LAB"], ty))
    return points


def sequence(points):
    return " ".join(f"{ty}{label}" for _, label, ty in points)


class Comparison:
    """Differences between two diagrams: structural problems (text), value
    rows (run, branch, label, type, column, reference, ours, rel. error) and
    the special points compared (run, label, type, column, reference, ours,
    rel. change, (column changed most, its rel. change))."""

    def __init__(self, rtol=RTOL, atol=ATOL, ignore=()):
        self.rtol, self.atol, self.ignore = rtol, atol, list(ignore)
        self.problems, self.rows, self.special = [], [], []
        self.points = self.values = 0

    def ok(self):
        return not self.problems and not self.rows

    def files(self, run, ref_path, our_path):
        ref = read_branches(ref_path)
        if not os.path.exists(our_path):
            self.problems.append(f"{run}: not written by the figure ({our_path} missing)")
            return
        ours = read_branches(our_path)
        if len(ref) != len(ours):
            self.problems.append(f"{run}: {len(ours)} branches, reference has {len(ref)}")
            return
        for number, (a, b) in enumerate(zip(ref, ours), 1):
            self.branches(f"{run} branch {number}", run, a, b)

    def ignored(self, run, branch, index, ty):
        """True if a labels.json rule leaves this labelled point out."""
        for rule in self.ignore:
            if not fnmatch.fnmatchcase(run, rule["run"]) or rule["type"] != ty:
                continue
            values = dict(zip(branch.coordnames, branch.coordarray[:, index]))
            if all(values[c] >= v for c, v in rule.get("from", {}).items()) and \
                    all(values[c] <= v for c, v in rule.get("to", {}).items()):
                return True
        return False

    def floors(self, branch):
        """Per column the absolute tolerance: atol, or for <x>_mean
        rtol * max |<x>_amp| of the reference branch (module docstring)."""
        out = []
        for column in branch.coordnames:
            amp = column[:-len("_mean")] + "_amp" if column.endswith("_mean") else None
            scale = (float(numpy.abs(numpy.asarray(branch[amp])).max())
                     if amp in branch.coordnames else 0.0)
            out.append(max(self.atol, self.rtol * scale))
        return out

    def branches(self, where, run, ref, ours):
        if ref.BR != ours.BR:
            self.problems.append(f"{where}: branch number BR {ours.BR}, reference {ref.BR}")
        if ref.coordnames != ours.coordnames:
            self.problems.append(f"{where}: columns {ours.coordnames}, "
                                 f"reference {ref.coordnames}")
            return
        ref_points = [p for p in labelled_points(ref) if not self.ignored(run, ref, p[0], p[2])]
        our_points = [p for p in labelled_points(ours)
                      if not self.ignored(run, ours, p[0], p[2])]
        if [p[2] for p in ref_points] != [p[2] for p in our_points]:
            self.problems.append(f"{where}: special points [{sequence(our_points)}], "
                                 f"reference [{sequence(ref_points)}]")
        floors = self.floors(ref)
        for (i, label, ty), (j, _, our_ty) in zip(ref_points, our_points):
            if our_ty != ty:  # values are compared up to the first changed type
                break
            self.points += 1
            changes = []
            for column, expected, value, floor in zip(ref.coordnames, ref.coordarray[:, i],
                                                      ours.coordarray[:, j], floors):
                self.values += 1
                rel = abs(value - expected) / abs(expected) if expected else \
                    (0.0 if value == expected else float("inf"))
                if not abs(value - expected) <= self.rtol * abs(expected) + floor:
                    self.rows.append((run, ref.BR, label, ty, column, expected, value, rel))
                    changes.append((rel, column))
            if ty not in NOT_SPECIAL:
                column = ref.coordnames[0]
                expected, value = ref.coordarray[0, i], ours.coordarray[0, j]
                first = (value - expected) / abs(expected) if expected else 0.0
                self.special.append((run, label, ty, column, expected, value, first,
                                     max(changes) if changes else None))

    def summary(self):
        """One line per special point: reference -> ours in the first column."""
        if not self.special:
            return []
        cells = [(run, f"{ty}{label}", column, f"{a:.6g}", "->", f"{b:.6g}", f"{rel:+.2e}",
                  "" if most is None or most[1] == column else
                  f"(most: {most[1]} {most[0]:.2e})")
                 for run, label, ty, column, a, b, rel, most in self.special]
        widths = [max(len(row[k]) for row in cells) for k in range(len(cells[0]))]
        lines = ["  special points (reference -> ours, relative change):"]
        for row in cells:
            lines.append("    " + "  ".join(c.rjust(w) if 3 <= k <= 6 else c.ljust(w)
                                            for k, (c, w) in enumerate(zip(row, widths)))
                         .rstrip())
        return lines

    def report(self):
        lines = self.summary() + [f"  {p}" for p in self.problems]
        if self.rows:
            header = ("run", "BR", "LAB", "TY", "column", "reference", "ours", "rel. error")
            cells = [header] + [(run, str(br), str(lab), ty, col, f"{a:.10e}", f"{b:.10e}",
                                 f"{rel:.2e}") for run, br, lab, ty, col, a, b, rel in self.rows]
            widths = [max(len(row[k]) for row in cells) for k in range(len(header))]
            lines.append("  values outside the tolerance:")
            for row in cells:
                lines.append("    " + "  ".join(c.rjust(w) if k >= 5 else c.ljust(w)
                                                for k, (c, w) in enumerate(zip(row, widths))))
        return "\n".join(lines)


def b_file(directory, run):
    """Path of run "name" or "sub/name" of a directory: <dir>/sub/b.name."""
    return os.path.join(directory, os.path.dirname(run), f"b.{os.path.basename(run)}")


def run_names(reference_dir):
    """The runs of a reference set, after checking it against its MANIFEST."""
    try:
        return reference_set.verify(reference_dir)
    except reference_set.SetError as exc:
        raise DiagramFileError(str(exc)) from exc


def ignore_rules(reference_dir):
    """The labels.json rules of a reference set ([] without one)."""
    path = os.path.join(reference_dir, LABEL_FILE)
    if not os.path.exists(path):
        return []
    try:
        with open(path) as f:
            rules = json.load(f)["ignore"]
        for rule in rules:
            if not (rule["run"] and rule["type"] and rule["reason"]):
                raise ValueError("run, type and reason must be given")
        return rules
    except (ValueError, KeyError, TypeError) as exc:
        raise DiagramFileError(f"{path}: expected {{\"ignore\": [{{\"run\": ..., \"type\": ..., "
                               f"\"reason\": ...}}, ...]}} ({exc})") from exc


def tolerances(reference_dir):
    """(rtol, atol): the defaults, overridden by reference_dir/tolerances.json."""
    path = os.path.join(reference_dir, TOLERANCE_FILE)
    if not os.path.exists(path):
        return RTOL, ATOL
    try:
        with open(path) as f:
            values = json.load(f)
        return float(values.get("rtol", RTOL)), float(values.get("atol", ATOL))
    except (ValueError, AttributeError, TypeError) as exc:
        raise DiagramFileError(f"{path}: expected {{\"rtol\": R, \"atol\": A}} ({exc})") from exc


def compare_dirs(reference_dir, run_dir, runs=None, rtol=None, atol=None, raw=False):
    """Compare both directories run by run: the given runs, or (runs None)
    every run of the reference set (checked against its MANIFEST) and every
    b-file under run_dir that the set stores (runs.json), which must have a
    reference.  None tolerances come
    from tolerances(); raw compares every labelled point as stored (no
    labels.json rules)."""
    default_rtol, default_atol = tolerances(reference_dir)
    result = Comparison(default_rtol if rtol is None else rtol,
                        default_atol if atol is None else atol,
                        [] if raw else ignore_rules(reference_dir))
    if runs is None:
        runs = run_names(reference_dir)
        try:
            written = reference_set.stored(reference_dir, map(reference_set.run_name,
                                                              reference_set.run_files(run_dir)))
        except reference_set.SetError as exc:
            raise DiagramFileError(str(exc)) from exc
        for run in sorted(set(written) - set(runs)):
            result.problems.append(f"{run}: written by the figure, not in the reference set "
                                   "(a new run: `make refs-<fig>` adds it)")
    for run in runs:
        result.files(run, b_file(reference_dir, run), b_file(run_dir, run))
    return result


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dirs", nargs="*", metavar="DIR",
                        help="REFERENCE_DIR RUN_DIR, or with --figure only RUN_DIR")
    parser.add_argument("--figure", help="reference tests/reference/FIGURE; RUN_DIR "
                        "defaults to build/regress/FIGURE")
    parser.add_argument("--runs", nargs="+", help="compare only these runs (b.<name>)")
    parser.add_argument("--rtol", type=float, help=f"relative tolerance (default {RTOL})")
    parser.add_argument("--atol", type=float, help=f"absolute floor (default {ATOL})")
    args = parser.parse_args(argv)
    if args.figure:
        if len(args.dirs) > 1:
            parser.error("--figure takes at most one RUN_DIR")
        reference_dir = os.path.join(REFERENCE_ROOT, args.figure)
        run_dir = args.dirs[0] if args.dirs else os.path.join(REGRESS_ROOT, args.figure)
    elif len(args.dirs) == 2:
        reference_dir, run_dir = args.dirs
    else:
        parser.error("give REFERENCE_DIR RUN_DIR, or --figure FIG [RUN_DIR]")

    what = f"{os.path.relpath(run_dir)} vs {os.path.relpath(reference_dir)}"
    try:
        result = compare_dirs(reference_dir, run_dir, args.runs, args.rtol, args.atol)
    except DiagramFileError as exc:
        print(f"compare: {what}: error: {exc}", file=sys.stderr)
        return 2
    tol = f"rtol {result.rtol:g}, atol {result.atol:g}"
    if result.ok():
        print(f"compare: {what}: agree ({result.points} labelled points, "
              f"{result.values} values within {tol})")
        return 0
    print(f"compare: {what}: DIFFERENT ({len(result.problems)} structural, "
          f"{len(result.rows)} of {result.values} values outside {tol})")
    print(result.report())
    return 1


if __name__ == "__main__":
    sys.exit(main())
