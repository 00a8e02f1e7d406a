"""shared.checks, the qualitative checks the report lists under each
figure, holds to the tree: every test it names exists, every reference set
it names is stored, every docs heading it links is in docs/reproduction.md,
and every figure of the report has an entry."""
import ast
import os
import re

import pytest

from helpers import ROOT
from mlgshimmy.shared import checks
from mlgshimmy import report

ENTRIES = sorted({(feature, test) for _, found in checks.CHECKS.values() for feature, test in found})


def _tests_in(path):
    tree = ast.parse(open(os.path.join(ROOT, path)).read())
    return {node.name for node in tree.body if isinstance(node, ast.FunctionDef)}


@pytest.mark.parametrize("feature, test", ENTRIES, ids=[t for _, t in ENTRIES])
def test_the_named_check_exists(feature, test):
    if test.startswith("make regress-"):
        figure = test[len("make regress-"):]
        assert os.path.isdir(os.path.join(ROOT, "tests", "reference", figure)), test
    elif "::" in test:
        path, name = test.split("::")
        assert name in _tests_in(path), f"{test}: no such test"
    else:
        assert re.fullmatch(r"tests/c/test_\w+\.c", test) and \
            os.path.isfile(os.path.join(ROOT, test)), test


def test_every_heading_is_a_section_of_the_docs():
    with open(os.path.join(ROOT, checks.DOCS)) as docs:
        headings = {line.lstrip("#").strip() for line in docs if line.startswith("#")}
    assert {h for h, _ in checks.CHECKS.values()} - headings == set()


def test_every_report_figure_has_its_checks():
    assert {f for f, _, _ in report.FIGURES} - set(checks.CHECKS) == set()


@pytest.mark.parametrize("heading, anchor", [
    ("Fig. 10 — F* = 1 with ±1 mm of freeplay, diagram in V",
     "fig-10--f--1-with-1-mm-of-freeplay-diagram-in-v"),
    ("Fig. 18 — a, b, c in $F^*$; regions; $\\kappa^*$", "fig-18--a-b-c-in-f-regions-kappa"),
])
def test_anchor_as_github_makes_it(heading, anchor):
    assert checks.anchor(heading) == anchor


def test_title_is_the_heading_without_its_tex():
    assert checks.title("Fig. 13 — $\\varepsilon = 0.1\\,y_{fp}$, diagrams in V and orbits in "
                        "$y_{fp}$") == "Fig. 13 — ε = 0.1 y_fp, diagrams in V and orbits in y_fp"
    assert checks.title("Fig. 18 — a, b, c in $F^*$; regions; $\\kappa^*$") == \
        "Fig. 18 — a, b, c in F*; regions; κ*"
