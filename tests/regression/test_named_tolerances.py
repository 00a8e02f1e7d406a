"""Named points compared with their tolerances (tolerances.json "named":
compare_diagrams.named_tolerances, named_points.outside): a named point
that moved by more than rtol |reference| + atol, vanished or is new makes
the comparison DIFFERENT (exit 1), one within its tolerance does not, and
one that no rule matches is only reported.  The smoothing study's set
(tests/reference/smoothing) holds its eps table this way.

Run: /usr/bin/python3 -m pytest -q tests/regression/test_named_tolerances.py
"""
import json
import os
import shutil
import subprocess
import sys

import pytest

import compare_diagrams as cd
import named_points

RULES = [{"match": "H* at eps/y_fp = *", "rtol": 1e-9, "reason": "eigenvalue scan"},
         {"match": "S *", "atol": 2e-3, "reason": "bisection to 1e-3 m/s"}]
REFERENCE = {"H1 [m/s] at eps/y_fp = 0.1": 1.4581594746679292, "S [m/s] at eq. (14)": 41.603,
             "free text quantity": 7.0}


def test_a_value_within_its_tolerance_passes_and_one_beyond_it_is_named():
    inside = {**REFERENCE, "H1 [m/s] at eps/y_fp = 0.1": 1.4581594746679292 * (1 + 5e-10),
              "S [m/s] at eq. (14)": 41.6049, "free text quantity": 99.0}
    assert named_points.outside(REFERENCE, inside, RULES) == []
    beyond = {**inside, "H1 [m/s] at eps/y_fp = 0.1": 1.4581594746679292 * (1 + 2e-9),
              "S [m/s] at eq. (14)": 41.6051}
    lines = named_points.outside(REFERENCE, beyond, RULES)
    assert len(lines) == 2
    assert "H1 [m/s] at eps/y_fp = 0.1" in lines[0] and "eigenvalue scan" in lines[0]
    assert "S [m/s] at eq. (14)" in lines[1] and "tolerance 0.002" in lines[1]


def test_a_vanished_or_new_point_under_a_rule_is_a_difference():
    ours = {q: v for q, v in REFERENCE.items() if not q.startswith("H1")}
    ours["H2 [m/s] at eps/y_fp = 0.1"] = 28.3
    ours["unmatched new"] = 1.0
    lines = named_points.outside(REFERENCE, ours, RULES)
    assert lines == ["    H1 [m/s] at eps/y_fp = 0.1: 1.458159475 -> vanished",
                     "    H2 [m/s] at eps/y_fp = 0.1: new, 28.3"]


@pytest.mark.parametrize("rule, message", [
    ({"rtol": 1e-9, "reason": "r"}, "'match' must be given"),
    ({"match": "H*", "rtol": -1.0, "reason": "r"}, "'rtol' must be a finite number >= 0"),
    ({"match": "H*", "rtol": 1e-9}, "'reason' must be given"),
    ({"match": "H*", "rtol": 1e-9, "reason": "r", "tol": 1}, "named rule 1"),
])
def test_a_malformed_rule_is_a_usage_error_naming_it(tmp_path, rule, message):
    (tmp_path / "tolerances.json").write_text(json.dumps({"named": [rule]}))
    with pytest.raises(cd.SettingsError, match=message):
        cd.named_tolerances(str(tmp_path))
    assert cd.tolerances(str(tmp_path)) == (cd.RTOL, cd.ATOL)   # the file's other keys


def run_compare(tmp_path, numbers):
    """compare_diagrams.py on a reference of one b-file of fig07's set with
    REFERENCE as its named points under RULES, and a run with the same
    b-file whose result holds `numbers`: (exit status, output)."""
    ref, run = tmp_path / "ref", tmp_path / "run"
    for d in (ref, run):
        d.mkdir(exist_ok=True)
        shutil.copy(os.path.join(cd.REFERENCE_ROOT, "fig07", "b.po_F1"), d)
    named_points.write(str(ref), REFERENCE)
    (ref / "tolerances.json").write_text(json.dumps({"named": RULES}))
    (run / "result.json").write_text(json.dumps({"data": {"numbers": numbers}}))
    proc = subprocess.run([sys.executable, os.path.join(cd.ROOT, "tests", "regression",
                                                        "compare_diagrams.py"),
                           str(ref), str(run)], capture_output=True, text=True,
                          env={**os.environ, "PYTHONPATH": os.path.join(cd.ROOT, "drivers")})
    return proc.returncode, proc.stdout + proc.stderr


def test_the_command_line_fails_on_a_named_point_outside_its_tolerance(tmp_path):
    status, out = run_compare(tmp_path, REFERENCE)
    assert status == 0 and "the named points within their tolerances" in out, out
    status, out = run_compare(tmp_path, {**REFERENCE, "S [m/s] at eq. (14)": 41.61})
    assert status == 1, out
    assert "named points outside their tolerances" in out and "S [m/s] at eq. (14)" in out
