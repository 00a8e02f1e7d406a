"""Compare AUTO-07p bifurcation diagrams (b-files) with stored references.

    compare_diagrams.py REFERENCE_DIR RUN_DIR [--runs NAME ...] [--rtol R] [--atol A]
    compare_diagrams.py --figure FIG [RUN_DIR]

(run with /usr/bin/python3 or $PYTHON from the Makefile; AUTO_DIR as for the drivers)

The reference set is checked against its MANIFEST first (reference_set.py: a
file missing, extra or changed is an error naming it); a REFERENCE_DIR outside
tests/reference/ without a MANIFEST (a run of one's own) has its b-files
compared, and RUN_DIR's other b-files are not. Then every run of the
set, subdirectories included (b.<name>, zero/b.<name>, ...; or only the
--runs names), is read with AUTO's own reader (auto.parseB) and compared
with the same path under RUN_DIR, and every b-file under RUN_DIR must have a
reference (of those the set's runs.json selects, if it has one):
- the same number of branches, with the same branch numbers and columns;
- per branch, the same sequence of special-point types (EP, HB, LP, UZ, ...);
- at every labelled point, every column agrees: |ours - ref| <= rtol*|ref| + atol
  (where the sequences differ: at the points before the first changed type);
- per branch, the same stability: AUTO marks each point stable or unstable by
  the sign of PT (negative = stable); the branch's stable and unstable
  segments come in the same order, and each change of stability lies at the
  same place: the first column (the continued parameter) at the first point
  of the new segment agrees within the local step (the larger of the two
  steps into that point, ours and the reference's) plus rtol*|ref| + atol,
  since AUTO locates a change between two computed points only to within
  the step.  A change next to a labelled point that labels.json leaves out
  (or between the first and last such point of one rule on the branch) is
  not compared: the segment goes on as before it;
- no value anywhere (labelled or not, either side) is NaN or infinite.
Point counts, step sizes and timings are never compared.

A column <x>_mean (psi_mean, ...) vanishes by symmetry on a symmetric gear:
its absolute tolerance is rtol times the largest <x>_amp of the reference
branch, the size of the motion it is the mean of (rounding noise of 1e-8 rad
is no change; an offset of a thousandth of the amplitude is).

The defaults rtol = 1e-5 and atol = 1e-10 can be set for one figure in
REFERENCE_DIR/tolerances.json ({"rtol": 1e-4, "atol": 1e-8, "reason": "why"}); command-line
options override both. REFERENCE_DIR/labels.json lists labelled points whose
position is numerically arbitrary, with the reason; they are left out of
both sides:
    {"ignore": [{"run": "hopf_down", "type": "LP", "reason": "..."},
                {"run": "po*", "type": "TR", "from": {"V": 560}, "reason": "..."}]}
("run" is a shell pattern; "from"/"to" bound a column's value; the keys
run, type and reason are required, type is an AUTO point type, and a column
that a run's branch does not have is an error).

The report opens with every special point (HB, LP, BP, PD, TR, ...):
reference -> ours in its first column (the continued parameter), the
relative change, and the column that changed most; then the table of values
outside the tolerance (run, branch, label, type, column, reference, ours,
relative error). --figure FIG compares tests/reference/FIG with RUN_DIR
(default build/regress/FIG, where `make regress` publishes its runs).
Exit status: 0 agree; 1 differences (a run of the reference that the figure
no longer writes is one); 2 nothing to compare, named on stderr: a reference
file or RUN_DIR missing or unreadable, one of ours unreadable, no AUTO-07p at
AUTO_DIR (auto.parseB reads the b-files), or a usage error: a malformed
labels.json or tolerances.json (a rule naming a column the run does not
have, an unknown key, a negative tolerance).
"""
import argparse
import fnmatch
import json
import math
import os
import re
import sys

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
try:   # the drivers' one way to AUTO (autosession.init); make sets PYTHONPATH=drivers
    from mlgshimmy.shared import autosession
except ImportError:   # exit status 2: nothing compared (1 would read "differ")
    print(f"compare_diagrams: the package mlgshimmy is not on the path: run it as "
          f"PYTHONPATH={os.path.join(ROOT, 'drivers')} {sys.executable} {sys.argv[0]} ... "
          "(make does)", file=sys.stderr)
    sys.exit(2)
import causes  # noqa: E402  (this directory: run as a script, or pytest's pythonpath)
import named_points  # noqa: E402
import reference_set  # noqa: E402

REFERENCE_ROOT = os.path.join(ROOT, "tests", "reference")
REGRESS_ROOT = os.path.join(ROOT, "build", "regress")
RTOL, ATOL = 1e-5, 1e-10
TOLERANCE_FILE = "tolerances.json"
LABEL_FILE = "labels.json"
# Types that are not bifurcations: start/end points, user stops, no convergence.
NOT_SPECIAL = {"EP", "UZ", "MX", "RG", "No Label"}


class DiagramFileError(Exception):
    """A b-file or reference directory that is missing or cannot be read."""


class SettingsError(DiagramFileError):
    """A malformed labels.json or tolerances.json (a usage error; names the
    file and what is wrong)."""


def parse_b():
    """AUTO's auto.parseB, through the drivers' one way to AUTO
    (autosession.init: AUTO_DIR, default build/auto/07p) on first use;
    DiagramFileError if there is no AUTO-07p there."""
    try:
        return autosession.init().parseB
    except autosession.AutoMissing as exc:
        raise DiagramFileError(f"{exc} (its auto.parseB reads the b-files)") from None


def read_branches(path):
    """The branches of one b-file, fully parsed by auto.parseB."""
    parser = parse_b()
    if not os.path.isfile(path):
        raise DiagramFileError(f"{path}: no such file")
    try:
        branches = parser.parseBR(path)
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


def segments(branch):
    """[(index of its first point, stable)] of a branch's stability segments,
    from AUTO's PT signs (parseB's stability(): the signed number of each
    segment's last point, negative = stable)."""
    out, start = [], 0
    for end in branch.stability():
        out.append((start, end < 0))
        start = abs(end)
    return out


def stability_text(branch, segs, limit=8):
    """'U from V = 0 (point 1), S from V = 2 (point 2), ...'."""
    name, x = branch.coordnames[0], branch.coordarray[0]
    parts = [f"{'S' if stable else 'U'} from {name} = {x[i]:.6g} (point {i + 1})"
             for i, stable in segs[:limit]]
    if len(segs) > limit:
        parts.append(f"... {len(segs) - limit} more")
    return ", ".join(parts)


NOT_WRITTEN = "not written by the figure"
PROBLEM_RUN = re.compile(r"(\S+?)(?: branch \d+)?: ")   # the run a problem's text names


class Comparison:
    """Differences between two diagrams: structural problems (text), value
    rows (run, branch, label, type, column, reference, ours, rel. error) and
    the special points compared (run, label, type, column, reference, ours,
    rel. change, (column changed most, its rel. change))."""

    def __init__(self, rtol=RTOL, atol=ATOL, ignore=(), rules_file=LABEL_FILE):
        self.rtol, self.atol, self.ignore = rtol, atol, list(ignore)
        self.rules_file = rules_file
        self.problems, self.rows, self.special = [], [], []
        self.reference = {}   # run -> the reference's branches (causes.starts)
        self.points = self.values = self.changes = 0

    def ok(self):
        return not self.problems and not self.rows

    def files(self, run, ref_path, our_path):
        ref = read_branches(ref_path)
        self.reference[run] = ref
        if not os.path.exists(our_path):
            self.problems.append(f"{run}: {NOT_WRITTEN} ({our_path} missing)")
            return
        ours = read_branches(our_path)
        if len(ref) != len(ours):
            self.problems.append(f"{run}: {len(ours)} branches, reference has {len(ref)}")
            return
        for number, (a, b) in enumerate(zip(ref, ours), 1):
            self.branches(f"{run} branch {number}", run, a, b)

    def ignoring_rule(self, run, branch, index, ty):
        """The number of the labels.json rule that leaves this labelled
        point out, or None."""
        for number, rule in enumerate(self.ignore, 1):
            if not fnmatch.fnmatchcase(run, rule["run"]) or rule["type"] != ty:
                continue
            values = dict(zip(branch.coordnames, branch.coordarray[:, index]))
            if all(values[c] >= v for c, v in rule.get("from", {}).items()) and \
                    all(values[c] <= v for c, v in rule.get("to", {}).items()):
                return number
        return None

    def ignored(self, run, branch, index, ty):
        """True if a labels.json rule leaves this labelled point out."""
        return self.ignoring_rule(run, branch, index, ty) is not None

    def check_rules(self, where, run, branch):
        """SettingsError if a rule for this run bounds a column the branch
        does not have (it would never match, or fail)."""
        for number, rule in enumerate(self.ignore, 1):
            if not fnmatch.fnmatchcase(run, rule["run"]):
                continue
            for bound in ("from", "to"):
                for column in rule.get(bound, {}):
                    if column not in branch.coordnames:
                        raise SettingsError(
                            f"{self.rules_file}: rule {number} (run {rule['run']!r}, type "
                            f"{rule['type']}) bounds column {column!r} in {bound!r}, which "
                            f"{where} does not have (its columns: "
                            f"{', '.join(branch.coordnames)})")

    def stability(self, run, branch):
        """The branch's stability segments (segments()) without the changes
        next to a labelled point that labels.json leaves out, or between the
        first and the last such point of one rule: there the segment goes on
        as before the change."""
        spans = {}
        for index, _, ty in labelled_points(branch):
            number = self.ignoring_rule(run, branch, index, ty)
            if number is not None:
                first, last = spans.get(number, (index, index))
                spans[number] = (min(first, index), max(last, index))
        kept = []
        for start, stable in segments(branch):
            if kept and any(start >= first and start - 1 <= last
                            for first, last in spans.values()):
                continue  # a change between points start - 1 and start, left out
            if not kept or stable != kept[-1][1]:
                kept.append((start, stable))
        return kept

    def compare_stability(self, where, run, ref, ours, floor):
        """Segments in the same order, each change within the local step
        (module docstring); a difference names where it is."""
        ref_segs, our_segs = self.stability(run, ref), self.stability(run, ours)
        name, x_ref, x_ours = ref.coordnames[0], ref.coordarray[0], ours.coordarray[0]
        word = {True: "stable", False: "unstable", None: "no further segment"}
        for k in range(max(len(ref_segs), len(our_segs))):
            a = ref_segs[k] if k < len(ref_segs) else None
            b = our_segs[k] if k < len(our_segs) else None
            if a is None or b is None or a[1] != b[1]:
                at = (f"from {name} = {x_ours[b[0]]:.6g} (point {b[0] + 1}): ours "
                      f"{word[b[1]]}" if b else "ours: " + word[None])
                there = (f"reference {word[a[1]]} from {name} = {x_ref[a[0]]:.6g} "
                         f"(point {a[0] + 1})" if a else "reference: " + word[None])
                self.problems.append(
                    f"{where}: stability differs {at}, {there}; segments ours "
                    f"[{stability_text(ours, our_segs)}], reference "
                    f"[{stability_text(ref, ref_segs)}]")
                return
            if k == 0:
                continue
            i, j = a[0], b[0]
            step = max(abs(x_ref[i] - x_ref[i - 1]), abs(x_ours[j] - x_ours[j - 1]))
            allowed = step + self.rtol * abs(x_ref[i]) + floor
            self.changes += 1
            if not abs(x_ours[j] - x_ref[i]) <= allowed:
                self.problems.append(
                    f"{where}: stability change to {word[b[1]]} at {name} = {x_ours[j]:.6g} "
                    f"(point {j + 1}), reference {name} = {x_ref[i]:.6g} (point {i + 1}): "
                    f"{abs(x_ours[j] - x_ref[i]):.3g} apart, more than the local step "
                    f"{step:.3g} (+ tolerance)")

    def non_finite(self, where, side, branch):
        """A problem naming the first NaN or infinite value of a branch."""
        bad = ~numpy.isfinite(branch.coordarray)
        if bad.any():
            index = int(numpy.flatnonzero(bad.any(axis=0))[0])
            column = int(numpy.flatnonzero(bad[:, index])[0])
            self.problems.append(
                f"{where}: {int(bad.sum())} non-finite value(s) in {side}, the first "
                f"{branch.coordnames[column]} = {branch.coordarray[column, index]} at point "
                f"{index + 1} ({branch.coordnames[0]} = {branch.coordarray[0, index]:.6g})")

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
        self.check_rules(where, run, ref)
        self.non_finite(where, "ours", ours)
        self.non_finite(where, "the reference", ref)
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
        self.compare_stability(where, run, ref, ours, floors[0])

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

    def structural(self):
        """The structural problems, each change once with the problems that
        follow from it indented under it (causes.fold)."""
        problems = [(PROBLEM_RUN.match(p).group(1), p) for p in self.problems]
        missing = {run for run, p in problems if NOT_WRITTEN in p}
        lines = []
        for _, own, follow in causes.fold(problems, causes.starts(self.reference,
                                                                  labelled_points), missing):
            lines += [f"  {p}" for p in own]
            lines += [f"      which is why {p} ({why})" for _, p, why in follow]
        return lines

    def report(self):
        lines = self.summary() + self.structural()
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


def is_reference_set(directory):
    """A set under tests/reference/, or any directory with a MANIFEST; any
    other directory is a run of one's own compared as the baseline
    (docs/regression.md)."""
    root = os.path.realpath(REFERENCE_ROOT)
    return os.path.commonpath([os.path.realpath(directory), root]) == root or \
        os.path.exists(os.path.join(directory, reference_set.MANIFEST))


def run_names(reference_dir):
    """The runs of a reference set, after checking it against its MANIFEST;
    of any other directory, its b-files."""
    if not is_reference_set(reference_dir):
        runs = sorted(map(reference_set.run_name, reference_set.run_files(reference_dir)))
        if not runs:
            raise DiagramFileError(f"{reference_dir}: no b-files to compare (and no "
                                   f"{reference_set.MANIFEST}: not a reference set)")
        return runs
    try:
        return reference_set.verify(reference_dir)
    except reference_set.SetError as exc:
        raise DiagramFileError(str(exc)) from exc


RULE_KEYS = ("run", "type", "reason", "from", "to")


def ignore_rules(reference_dir):
    """The labels.json rules of a reference set ([] without one);
    SettingsError naming the file and the rule if one is malformed.  The
    columns a rule bounds are checked against each run it applies to
    (Comparison.check_rules)."""
    path = os.path.join(reference_dir, LABEL_FILE)
    if not os.path.exists(path):
        return []
    shape = ('expected {"ignore": [{"run": ..., "type": ..., "reason": ..., '
             '"from": {column: value}, "to": {column: value}}, ...]}')
    try:
        with open(path) as f:
            text = json.load(f)
    except (OSError, ValueError) as exc:
        raise SettingsError(f"{path}: {shape} ({exc})") from exc
    if not isinstance(text, dict) or not isinstance(text.get("ignore"), list):
        raise SettingsError(f"{path}: {shape} (no \"ignore\" list)")
    types = set(parse_b().all_point_types)
    for number, rule in enumerate(text["ignore"], 1):
        what = f"{path}: rule {number}"
        if not isinstance(rule, dict):
            raise SettingsError(f"{what} is not an object: {shape}")
        unknown = sorted(set(rule) - set(RULE_KEYS))
        if unknown:
            raise SettingsError(f"{what}: unknown key(s) {', '.join(map(repr, unknown))} "
                                f"(known: {', '.join(RULE_KEYS)})")
        for key in ("run", "type", "reason"):
            if not (isinstance(rule.get(key), str) and rule[key]):
                raise SettingsError(f"{what}: {key!r} must be given, a non-empty string")
        if rule["type"] not in types:
            raise SettingsError(f"{what}: type {rule['type']!r} is not an AUTO point type "
                                f"({' '.join(sorted(types - {'No Label'}))})")
        for bound in ("from", "to"):
            values = rule.get(bound, {})
            if not isinstance(values, dict) or not all(
                    isinstance(c, str) and isinstance(v, (int, float))
                    and not isinstance(v, bool) and math.isfinite(v) for c, v in values.items()):
                raise SettingsError(f"{what}: {bound!r} must map column names to finite "
                                    f"numbers, got {values!r}")
    return text["ignore"]


def tolerances(reference_dir):
    """(rtol, atol): the defaults, overridden by reference_dir/tolerances.json;
    SettingsError for an unknown key or a value that is not a finite number
    >= 0."""
    path = os.path.join(reference_dir, TOLERANCE_FILE)
    if not os.path.exists(path):
        return RTOL, ATOL
    try:
        with open(path) as f:
            values = json.load(f)
    except (OSError, ValueError) as exc:
        raise SettingsError(f"{path}: expected {{\"rtol\": R, \"atol\": A}} ({exc})") from exc
    if not isinstance(values, dict):
        raise SettingsError(f"{path}: expected {{\"rtol\": R, \"atol\": A}}, got {values!r}")
    unknown = sorted(set(values) - {"rtol", "atol", "reason", "named"})
    if unknown:
        raise SettingsError(f"{path}: unknown key(s) {', '.join(map(repr, unknown))} "
                            "(known: rtol, atol, reason, named)")
    values.pop("named", None)    # named_tolerances
    if not isinstance(values.pop("reason", ""), str):
        raise SettingsError(f"{path}: 'reason' must be a text")
    for key, value in values.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not (math.isfinite(value) and value >= 0):
            raise SettingsError(f"{path}: {key!r} must be a finite number >= 0, got {value!r}")
    return float(values.get("rtol", RTOL)), float(values.get("atol", ATOL))


def named_tolerances(reference_dir):
    """The rules of tolerances.json's "named" list, [] without one: each
    {"match": a shell pattern on the named points' names, "rtol", "atol"
    (finite, >= 0; default 0), "reason"}; SettingsError if malformed."""
    path = os.path.join(reference_dir, TOLERANCE_FILE)
    if not os.path.exists(path):
        return []
    with open(path) as f:
        rules = json.load(f).get("named", [])
    shape = 'expected "named": [{"match": pattern, "rtol": R, "atol": A, "reason": why}, ...]'
    if not isinstance(rules, list):
        raise SettingsError(f"{path}: {shape}")
    for number, rule in enumerate(rules, 1):
        if not isinstance(rule, dict) or set(rule) - {"match", "rtol", "atol", "reason"}:
            raise SettingsError(f"{path}: named rule {number}: {shape}")
        for key in ("match", "reason"):
            if not (isinstance(rule.get(key), str) and rule[key]):
                raise SettingsError(f"{path}: named rule {number}: {key!r} must be given, "
                                    "a non-empty string")
        for key in ("rtol", "atol"):
            value = rule.get(key, 0.0)
            if isinstance(value, bool) or not isinstance(value, (int, float)) \
                    or not (math.isfinite(value) and value >= 0):
                raise SettingsError(f"{path}: named rule {number}: {key!r} must be a finite "
                                    f"number >= 0, got {value!r}")
    return rules


def compare_dirs(reference_dir, run_dir, runs=None, rtol=None, atol=None, raw=False):
    """Compare both directories run by run: the given runs, or (runs None)
    every run of the reference set (checked against its MANIFEST) and every
    b-file under run_dir that the set stores (runs.json), which must have a
    reference; or, reference_dir not a reference set, its b-files.  None tolerances come
    from tolerances(); raw compares every labelled point as stored (no
    labels.json rules)."""
    if not os.path.isdir(reference_dir):
        raise DiagramFileError(f"{reference_dir}: no such reference directory "
                               "(`make refs-<fig>` creates it)")
    if not os.path.isdir(run_dir):
        raise DiagramFileError(f"{run_dir}: no such run directory"
                               + (" (a file)" if os.path.exists(run_dir) else ""))
    default_rtol, default_atol = tolerances(reference_dir)
    result = Comparison(default_rtol if rtol is None else rtol,
                        default_atol if atol is None else atol,
                        [] if raw else ignore_rules(reference_dir),
                        os.path.join(reference_dir, LABEL_FILE))
    # a run of one's own as the baseline: its b-files alone (docs/regression.md)
    if runs is None and is_reference_set(reference_dir):
        runs = run_names(reference_dir)
        try:
            written = reference_set.stored(reference_dir, map(reference_set.run_name,
                                                              reference_set.run_files(run_dir)))
        except reference_set.SetError as exc:
            raise DiagramFileError(str(exc)) from exc
        for run in sorted(set(written) - set(runs)):
            result.problems.append(f"{run}: written by the figure, not in the reference set "
                                   "(a new run: `make refs-<fig>` adds it)")
    elif runs is None:
        runs = run_names(reference_dir)
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
    parser.add_argument("--what-moved", action="store_true",
                        help="a deliberate change of the model: exit 0 unless a named point "
                             "could not be followed (moved points are the answer, not a failure)")
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
        rules = named_tolerances(reference_dir)
    except SettingsError as exc:
        print(f"compare: {what}: usage error: {exc}", file=sys.stderr)
        return 2
    except DiagramFileError as exc:
        print(f"compare: {what}: error: {exc}", file=sys.stderr)
        return 2
    tol = f"rtol {result.rtol:g}, atol {result.atol:g}"
    reference, ours = named_points.of_reference(reference_dir), named_points.of_run(run_dir)
    if reference is not None and ours is not None:
        print(f"compare: {what}: the named points")
        print("\n".join(named_points.report(reference, ours)))
    if args.what_moved:
        lost = named_points.unfollowed(ours or {})
        print(f"compare: {what}: what moved (a deliberate change): "
              + (f"not followed: {', '.join(lost)}" if lost else
                 "every named point followed")
              + ("" if ours is not None else "; the run has no named points"))
        if not result.ok():
            print(f"  the runs in detail ({len(result.problems)} structural, "
                  f"{len(result.rows)} of {result.values} values outside {tol}):")
            print(result.report())
        return 1 if lost or ours is None else 0
    moved = named_points.outside(reference or {}, ours or {}, rules)
    if rules and ours is None:
        moved = ["    the run has no named points (no result.json)"]
    if moved:
        print(f"compare: {what}: named points outside their tolerances "
              f"({TOLERANCE_FILE}, \"named\"):")
        print("\n".join(moved))
    if result.ok() and not moved:
        named = f"; the named points within their tolerances ({TOLERANCE_FILE})" if rules else ""
        print(f"compare: {what}: agree ({result.points} labelled points, "
              f"{result.values} values within {tol}; {result.changes} stability changes "
              f"within the local step{named})")
        return 0
    print(f"compare: {what}: DIFFERENT ({len(result.problems)} structural, "
          f"{len(result.rows)} of {result.values} values outside {tol})")
    print(result.report())
    return 1


if __name__ == "__main__":
    sys.exit(main())
