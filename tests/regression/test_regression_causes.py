"""The regression's structural detail with each change once and what follows
from it under it (tests/regression/causes.py): which run starts from which,
and the folding, on stand-in branches; and on Fig. 10's reference set.

Run: /usr/bin/python3 -m pytest -q tests/regression/test_regression_causes.py
"""
import os

import numpy

import causes
import compare_diagrams


class Branch:
    """A stand-in b-file branch: columns V and L2-NORM, labelled points
    at the given indices."""

    def __init__(self, V, norm, labelled=()):
        self.coordnames = ["V", "L2-NORM"]
        self.coordarray = numpy.array([V, norm], dtype=float)
        self.labelled = list(labelled)


def labelled(branch):
    return [(i, k + 1, "UZ") for k, i in enumerate(branch.labelled)]


def test_a_run_starts_from_another_runs_labelled_point_not_from_its_start():
    reference = {"eq": [Branch([0.0, 1.5, 3.0], [0.40, 0.41, 0.42], [0, 1])],
                 "eq_again": [Branch([0.0, 2.0], [0.40, 0.43], [0])],
                 "po1": [Branch([1.5, 9.0], [0.41, 0.5], [0, 1])],
                 "po1_1": [Branch([9.0, 12.0], [0.5, 0.6], [0])]}
    assert causes.starts(reference, labelled) == {"po1": "eq", "po1_1": "po1"}


def test_consequences_are_folded_under_their_topmost_cause():
    problems = [("eq", "eq: stability change"), ("po1", "po1: special points differ"),
                ("po1_1", "po1_1: special points differ"), ("table/po1", "table/po1: ends at UZ"),
                ("table/po2", "table/po2: not written by the figure"),
                ("other/po9", "other/po9: not written by the figure")]
    parents = {"po1": "eq", "po1_1": "po1"}
    groups = causes.fold(problems, parents, {"table/po2", "other/po9"})
    assert groups == [
        ("eq", ["eq: stability change"],
         [("po1", "po1: special points differ", "starts from eq"),
          ("po1_1", "po1_1: special points differ", "starts from eq")]),
        ("table/po1", ["table/po1: ends at UZ"],
         [("table/po2", "table/po2: not written by the figure",
           "not made once table/po1 changed")]),
        ("other/po9", ["other/po9: not written by the figure"], [])]


def test_fig10s_reference_set_knows_which_orbit_run_starts_where():
    reference_dir = os.path.join(compare_diagrams.REFERENCE_ROOT, "fig10")
    reference = {run: compare_diagrams.read_branches(compare_diagrams.b_file(reference_dir, run))
                 for run in compare_diagrams.run_names(reference_dir)}
    parents = causes.starts(reference, compare_diagrams.labelled_points)
    assert parents["po1"] == "hb1" and parents["po3"] == "hb3"
    assert parents["table/po3_1"] == "table/po3"
    assert "eq" not in parents and "table/eq" not in parents   # one start, not a parent
