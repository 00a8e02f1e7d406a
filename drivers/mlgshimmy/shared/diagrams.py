"""Reading a run's diagram, checked complete and sound: every branch ends, the
s-file holds every labelled solution whole, no value is non-finite, no MX,
and the expected special points occur.  RunError names what is wrong."""
from __future__ import annotations

import os
from typing import Any, List, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import autosession, branches
from mlgshimmy.shared.runerror import MX, NON_FINITE, RunError


def special_points(bd: Any) -> List[Tuple[int, int, str]]:
    """List (branch number, label, type) of every labelled point."""
    return [(branch.BR, label, ty) for branch in bd
            for _, label, ty in branches.labelled_points(branch)]


# AUTO ends every branch with a labelled point of one of these types (the
# stop it reached, a stop value, or no convergence); a branch whose last
# point is not one was cut short.
BRANCH_ENDS = ("EP", "UZ", "MX")


def read_diagram(outputs: str, what: str, log: Optional[str] = None,
                 ends: Sequence[str] = BRANCH_ENDS) -> Any:
    """The diagram of a run's b-, s- and d-files, its b-file parsed now (AUTO
    reads lazily), checked complete by its content (AUTO ignores write
    errors, so a full disk leaves files cut at any byte): every branch ends
    in a labelled point of a type in `ends` (EP, UZ or MX, and the types the
    run was told to STOP at), the s-file holds a whole solution for every
    label of the b-file, and the b-file's last line is whole.  RunError otherwise
    (saying so when the file system is full)."""
    auto = autosession.init()
    try:
        with open(outputs[0], "rb") as f:
            text = f.read()
    except OSError as exc:
        raise RunError(f"{what}: {outputs[0]} unreadable ({exc.strerror})", log) from exc
    if not text.endswith(b"\n"):
        raise RunError(f"{what}: {outputs[0]} is empty or cut short" + _full(outputs[0]), log)
    try:
        bd = auto.bifDiag.bifDiag(*outputs)
        lengths = [len(branch) for branch in bd]
        labels = [lab for branch in bd for _, lab, _ in branches.labelled_points(branch)]
        cut = [branch.BR for branch in bd
               if not any(index == len(branch) - 1 and kind in ends
                          for index, _, kind in branches.labelled_points(branch))]
    except Exception as exc:  # any parser failure means an unreadable file
        raise RunError(f"{what}: {outputs[0]} unreadable ({type(exc).__name__}: {exc})"
                       + _full(outputs[0]), log) from exc
    if not lengths or min(lengths) == 0 or cut:
        raise RunError(f"{what}: {outputs[0]} is empty or cut short"
                       + (f" (branch {cut[0]} has no end point)" if cut else "")
                       + _full(outputs[0]), log)
    saved = solution_labels(outputs[1], what, log)
    if sorted(labels) != sorted(saved):
        raise RunError(f"{what}: {outputs[1]} holds solutions {sorted(saved)}, the b-file "
                       f"labels {sorted(labels)}: cut short" + _full(outputs[1]), log)
    return bd


def solution_labels(path: str, what: str, log: Optional[str] = None) -> List[int]:
    """The labels of an s-file's solutions, each read in full (AUTO's parseS
    reads only the headers, so a solution cut at a line end passed): after
    its header (IBR NTOT ITP LAB NFPR ISW NTPL NAR NROWPR NTST NCOL NPARX)
    NROWPR lines holding NTPL points of NAR values and NPARX parameters,
    and, when NROWPR is more than those take, the direction: NFPR indices,
    NFPR values and NTPL points of NAR - 1 values.  RunError naming the file
    otherwise."""
    try:
        with open(path, "rb") as f:
            lines = f.read().split(b"\n")
    except OSError as exc:
        raise RunError(f"{what}: {path} unreadable ({exc.strerror})", log) from exc
    if lines.pop():
        raise RunError(f"{what}: {path}: its last line is cut short" + _full(path), log)
    labels, at = [], 0
    while at < len(lines):
        try:
            header = [int(word) for word in lines[at].split()]
        except ValueError:
            header = []
        if len(header) not in (12, 16):
            raise RunError(f"{what}: {path}: line {at + 1} is not a solution header: cut "
                           "short or not an s-file" + _full(path), log)
        _, _, _, label, nfpr, _, ntpl, nar, nrowpr, _, _, nparx = header[:12]
        block = lines[at + 1:at + 1 + nrowpr]
        values = len(b" ".join(block).split())
        # the line counts AUTO writes (wrtsp8): 7 values a line, 20 indices
        plain = ((nar - 1) // 7 + 1) * ntpl + (nparx + 6) // 7
        expected = nar * ntpl + nparx + (2 * nfpr + (nar - 1) * ntpl if nrowpr > plain else 0)
        if len(block) != nrowpr or values != expected:
            raise RunError(f"{what}: {path}: solution {label} has {values} values in "
                           f"{len(block)} lines, its header says {expected} in {nrowpr}: "
                           "cut short" + _full(path), log)
        labels.append(label)
        at += 1 + nrowpr
    return labels


def _full(path):
    """' (the file system ... is full)' when it is, else ''."""
    try:
        stat = os.statvfs(os.path.dirname(os.path.abspath(path)))
    except OSError:
        return ""
    return f" (the file system of {os.path.dirname(path)} is full)" if stat.f_bavail == 0 else ""


def check_diagram(bd: Any, what: str, expect: Sequence[str] = ()) -> None:
    """Raise RunError about `what` if a branch of bd holds non-finite values,
    ends in MX, or a special point type listed in expect does not occur."""
    for branch in bd:
        if not numpy.all(numpy.isfinite(branch.coordarray)):
            raise RunError(f"{what}: non-finite values on branch {branch.BR} "
                           "(AUTO continued past a rejected step)", kind=NON_FINITE)
    points = special_points(bd)
    mx = [(br, lab) for br, lab, ty in points if ty == "MX"]
    if mx:
        raise RunError(f"{what}: no convergence (MX) at "
                       + ", ".join(f"branch {br} label {lab}" for br, lab in mx), kind=MX)
    found = {ty for _, _, ty in points}
    missing = [ty for ty in expect if ty not in found]
    if missing:
        raise RunError(f"{what}: expected special points {missing} missing"
                       f" (found {sorted(found)})")
