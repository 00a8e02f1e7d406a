"""The named points of a figure (its result's "numbers": H1-H3 and S of
Fig. 10, a_12 and b_12 of Fig. 12, ...), reference against ours, in the
paper's names: the first lines of a regression's report.

A reference set stores them as named.json (reference_set.py writes it from
the run's result.json); a run directory has them in its result.json.  The
set's tolerances.json may compare them too ("named": compare_diagrams.py,
outside).
"""
import fnmatch
import json
import os

NAMED = "named.json"
UNFOLLOWED = "stops (MX"     # fig10.numbers: where a branch stopped with no convergence


def of_run(run_dir):
    """{quantity: value} of the result.json in run_dir, or None; a reference
    set given as the run (compared with itself) has its named.json."""
    try:
        with open(os.path.join(run_dir, "result.json")) as f:
            numbers = json.load(f)["data"]["numbers"]
    except FileNotFoundError:
        return of_reference(run_dir)
    except (OSError, ValueError, KeyError, TypeError):
        return None
    return {q: v for q, v in numbers.items() if isinstance(v, (int, float))} \
        if isinstance(numbers, dict) else None


def of_reference(reference_dir):
    """{quantity: value} a reference set stores, or None."""
    try:
        with open(os.path.join(reference_dir, NAMED)) as f:
            return json.load(f)["numbers"]
    except (OSError, ValueError, KeyError):
        return None


def write(directory, numbers):
    with open(os.path.join(directory, NAMED), "w") as f:
        json.dump({"numbers": numbers}, f, indent=1, sort_keys=True)
        f.write("\n")


def report(reference, ours):
    """The lines: one per named point of both, reference -> ours with the
    absolute and relative change; then the vanished and the new ones."""
    lines = ["  named points (reference -> ours):"]
    for q in [q for q in reference if q in ours]:
        ref, new = reference[q], ours[q]
        rel = f"{(new - ref) / ref:+.3%}" if ref else "-"
        lines.append(f"    {q:<34} {ref:.6g} -> {new:.6g}  ({new - ref:+.4g}, {rel})")
    for q in [q for q in reference if q not in ours]:
        lines.append(f"    {q:<34} {reference[q]:.6g} -> vanished")
    for q in [q for q in ours if q not in reference]:
        lines.append(f"    {q:<34} new: {ours[q]:.6g}")
    return lines


def unfollowed(ours):
    """The quantities that say a branch could not be followed."""
    return [q for q in ours if UNFOLLOWED in q]


def outside(reference, ours, rules):
    """The lines naming every named point that a rule (the first whose
    shell pattern "match" fits its name) compares and that moved by more
    than rtol |reference| + atol, vanished, or is new; [] if none."""
    def rule_of(q):
        return next((r for r in rules if fnmatch.fnmatchcase(q, r["match"])), None)
    lines = []
    for q, ref in reference.items():
        rule = rule_of(q)
        if rule is None:
            continue
        if q not in ours:
            lines.append(f"    {q}: {ref:.10g} -> vanished")
            continue
        allowed = rule.get("rtol", 0.0) * abs(ref) + rule.get("atol", 0.0)
        if not abs(ours[q] - ref) <= allowed:
            lines.append(f"    {q}: {ref:.10g} -> {ours[q]:.10g} ({ours[q] - ref:+.3g}; "
                         f"tolerance {allowed:.3g}: {rule['reason']})")
    lines += [f"    {q}: new, {ours[q]:.10g}" for q in ours
              if q not in reference and rule_of(q) is not None]
    return lines
