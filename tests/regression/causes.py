"""Which structural difference of a comparison follows from which, so that
the report gives each change once with its consequences under it.

A run that starts where another run of the reference set has a labelled
point (not that run's own start: the same first parameter and L2 norm, to
the b-file's printed digits) continues from it: a change in the parent
explains a change in the child.  A run the figure did not write, in a
directory where a run it did write changed, most likely follows from that
change (the figure branched differently after it: an orbit branch that now
ends at a Hopf point needs no run from there)."""
import os

import numpy

SAME = 1e-7   # relative: a run's first point and the parent's labelled point


def starts(reference, labelled_points):
    """{run: parent run} over the reference branches ({run: [branches]}),
    labelled_points(branch) -> [(index, label, type)]."""
    ends = []
    for run, branches in reference.items():
        for branch in branches:
            for index, _, _ in labelled_points(branch):
                if index > 0:
                    ends.append((run, branch, index))
    out = {}
    for run, branches in reference.items():
        first = branches[0]
        names = first.coordnames[:1] + ["L2-NORM"]
        for parent, branch, index in ends:
            if parent == run or not all(n in branch.coordnames and n in first.coordnames
                                        for n in names):
                continue
            a = numpy.array([first.coordarray[first.coordnames.index(n), 0] for n in names])
            b = numpy.array([branch.coordarray[branch.coordnames.index(n), index] for n in names])
            if numpy.allclose(a, b, rtol=SAME, atol=0.0):
                out[run] = parent
                break
    return out


def fold(problems, parents, missing):
    """The problems ([(run, text)], in order) grouped by cause:
    [(run, [its own texts], [(run, text, why) that follow from it])].  A
    problem follows from the topmost ancestor run (parents) with a problem
    of its own; a run in `missing` (not written by the figure) without one
    from the first run of its directory that was written and has a problem."""
    runs = list(dict.fromkeys(run for run, _ in problems))

    def cause(run):
        found, why, parent, seen = None, None, parents.get(run), set()
        while parent is not None and parent not in seen:
            if parent in runs:
                found, why = parent, f"starts from {parent}"
            seen.add(parent)
            parent = parents.get(parent)
        if found is None and run in missing:
            here = os.path.dirname(run)
            written = [r for r in runs if r not in missing and r != run
                       and os.path.dirname(r) == here]
            if written:
                found, why = written[0], f"not made once {written[0]} changed"
        return found, why

    groups = {}
    for run, text in problems:
        root, why = cause(run)
        if root is None:
            groups.setdefault(run, ([], []))[0].append(text)
        else:
            groups.setdefault(root, ([], []))[1].append((run, text, why))
    return [(run, own, follow) for run, (own, follow) in groups.items()]
