"""Compare AUTO-07p bifurcation diagrams (b-files) with stored references.

    compare_diagrams.py REFERENCE_DIR RUN_DIR [--runs NAME ...] [--rtol R] [--atol A]
    compare_diagrams.py --figure FIG [RUN_DIR]

(run with /usr/bin/python3 or $PYTHON from the Makefile; AUTO_DIR as for the drivers)

Every b.<name> file of REFERENCE_DIR (or only the --runs names) is read with
AUTO's own reader (auto.parseB) and compared with b.<name> in RUN_DIR:
- the same number of branches, with the same branch numbers and columns;
- per branch, the same sequence of special-point types (EP, HB, LP, UZ, ...);
- at every labelled point, every column agrees: |ours - ref| <= rtol*|ref| + atol
  (where the sequences differ: at the points before the first changed type).
Point counts, step sizes and timings are never compared.

The defaults rtol = 1e-5 and atol = 1e-10 can be set for one figure in
REFERENCE_DIR/tolerances.json ({"rtol": 1e-4, "atol": 1e-8}); command-line
options override both. atol is the floor for columns at or near zero (e.g.
psi_mean of a symmetric orbit, ~1e-17): it is in the column's own units, and
every column (SI units, PAR units) is physically meaningful only far above it.

--figure FIG compares tests/reference/FIG with RUN_DIR (default
build/regress/FIG, where `make regress` runs). Prints a table of differences
(run, branch, label, type, column, reference, ours, relative error).
Exit status: 0 agree, 1 differences, 2 a file missing or unreadable (named).
"""
import argparse
import glob
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "drivers"))
import autoglue  # noqa: E402  (makes AUTO's python package importable)

REFERENCE_ROOT = os.path.join(ROOT, "tests", "reference")
REGRESS_ROOT = os.path.join(ROOT, "build", "regress")
RTOL, ATOL = 1e-5, 1e-10
TOLERANCE_FILE = "tolerances.json"


class DiagramFileError(Exception):
    """A b-file or reference directory that is missing or cannot be read."""


def read_branches(path):
    """The branches of one b-file, fully parsed by auto.parseB."""
    if not os.path.isfile(path):
        raise DiagramFileError(f"{path}: no such file")
    try:
        branches = autoglue.auto.parseB.parseBR(path)
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
    """Differences between two diagrams: structural problems (text) and
    value rows (run, branch, label, type, column, reference, ours, rel. error)."""

    def __init__(self, rtol=RTOL, atol=ATOL):
        self.rtol, self.atol = rtol, atol
        self.problems, self.rows = [], []
        self.points = self.values = 0

    def ok(self):
        return not self.problems and not self.rows

    def files(self, run, ref_path, our_path):
        ref, ours = read_branches(ref_path), read_branches(our_path)
        if len(ref) != len(ours):
            self.problems.append(f"{run}: {len(ours)} branches, reference has {len(ref)}")
            return
        for number, (a, b) in enumerate(zip(ref, ours), 1):
            self.branches(f"{run} branch {number}", run, a, b)

    def branches(self, where, run, ref, ours):
        if ref.BR != ours.BR:
            self.problems.append(f"{where}: branch number BR {ours.BR}, reference {ref.BR}")
        if ref.coordnames != ours.coordnames:
            self.problems.append(f"{where}: columns {ours.coordnames}, "
                                 f"reference {ref.coordnames}")
            return
        ref_points, our_points = labelled_points(ref), labelled_points(ours)
        if [p[2] for p in ref_points] != [p[2] for p in our_points]:
            self.problems.append(f"{where}: special points [{sequence(our_points)}], "
                                 f"reference [{sequence(ref_points)}]")
        for (i, label, ty), (j, _, our_ty) in zip(ref_points, our_points):
            if our_ty != ty:  # values are compared up to the first changed type
                break
            self.points += 1
            for column, expected, value in zip(ref.coordnames, ref.coordarray[:, i],
                                               ours.coordarray[:, j]):
                self.values += 1
                if not abs(value - expected) <= self.rtol * abs(expected) + self.atol:
                    rel = abs(value - expected) / abs(expected) if expected else float("inf")
                    self.rows.append((run, ref.BR, label, ty, column, expected, value, rel))

    def report(self):
        lines = [f"  {p}" for p in self.problems]
        if self.rows:
            header = ("run", "BR", "LAB", "TY", "column", "reference", "ours", "rel. error")
            cells = [header] + [(run, str(br), str(lab), ty, col, f"{a:.10e}", f"{b:.10e}",
                                 f"{rel:.2e}") for run, br, lab, ty, col, a, b, rel in self.rows]
            widths = [max(len(row[k]) for row in cells) for k in range(len(header))]
            for row in cells:
                lines.append("  " + "  ".join(c.rjust(w) if k >= 5 else c.ljust(w)
                                              for k, (c, w) in enumerate(zip(row, widths))))
        return "\n".join(lines)


def run_names(reference_dir):
    if not os.path.isdir(reference_dir):
        raise DiagramFileError(f"{reference_dir}: no such reference directory "
                               "(`make refs` creates it)")
    names = sorted(os.path.basename(p)[2:] for p in glob.glob(os.path.join(reference_dir, "b.*")))
    if not names:
        raise DiagramFileError(f"{reference_dir}: no b-files in the reference directory")
    return names


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


def compare_dirs(reference_dir, run_dir, runs=None, rtol=None, atol=None):
    """Compare b.<run> of both directories for every run (default: every
    b-file of reference_dir); None tolerances come from tolerances()."""
    default_rtol, default_atol = tolerances(reference_dir)
    result = Comparison(default_rtol if rtol is None else rtol,
                        default_atol if atol is None else atol)
    for run in runs or run_names(reference_dir):
        result.files(run, os.path.join(reference_dir, f"b.{run}"),
                     os.path.join(run_dir, f"b.{run}"))
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
