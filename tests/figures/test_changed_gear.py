"""A changed gear gets complete answers (the small part of the robustness
suite that `make test` runs): `make regress-fig10 SET='k_tlk=...'` at the
torque-link stiffness 10 % down and 10 % up completes, reports S, H1-H3 and
V_crit reference -> new in the paper's names first, draws the figure of
what moved, in the gear's own tree, and leaves the paper's gear's reference
set as its MANIFEST has it.  Both run side by side, as two users would."""
import os
import re
import subprocess

import pytest

import compare_diagrams as cd
import named_points

CHANGES = {"k_tlk=3.51e7": "k_tlk_35100000", "k_tlk=4.29e7": "k_tlk_42900000"}


@pytest.fixture(scope="module")
def regressed():
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MLG_RUN_ROOT", "MLG_SET")}
    procs = {change: subprocess.Popen(["make", "--no-print-directory", "regress-fig10",
                                       f"SET={change}"], cwd=cd.ROOT, env=env,
                                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
             for change in CHANGES}
    return {change: (proc.wait(), proc.stdout.read()) for change, proc in procs.items()}


def moved(output):
    """{quantity: (reference, new)} of the named-point lines of the report."""
    out = {}
    for line in output.splitlines():
        m = re.match(r"\s+(.+?\[m/s\])\s+(\S+) -> (\S+)  \(", line)
        if m:
            out[m.group(1)] = (float(m.group(2)), float(m.group(3)))
    return out


@pytest.mark.parametrize("change", CHANGES)
def test_a_stiffness_change_completes_with_every_named_point(regressed, change):
    status, output = regressed[change]
    assert status == 0, output[-3000:]
    assert "every named point followed" in output
    points = moved(output)
    assert set(points) == {"H1 [m/s]", "H2 [m/s]", "H3 [m/s]", "S1 [m/s]",
                           "V_crit (zero freeplay) [m/s]"}
    cd.run_names(os.path.join(cd.REFERENCE_ROOT, "fig10"))   # the set as its MANIFEST says
    reference = named_points.of_reference(os.path.join(cd.REFERENCE_ROOT, "fig10"))
    for quantity, (ref, new) in points.items():
        assert ref == pytest.approx(reference[quantity], rel=1e-5)
    # a stiffer link raises V_crit (346.1 -> 389.2 m/s at +10 %, 304.6 at -10 %)
    sign = 1 if change.endswith("4.29e7") else -1
    assert sign * (points["V_crit (zero freeplay) [m/s]"][1] - 346.1) > 30.0
    assert abs(points["S1 [m/s]"][1] / points["S1 [m/s]"][0] - 1) < 0.01
    published = os.path.join(cd.REGRESS_ROOT, "gear", CHANGES[change])
    assert os.path.exists(os.path.join(published, "figures", "fig10_what_moved.png"))
    assert named_points.of_run(os.path.join(published, "fig10"))["S1 [m/s]"] == \
        pytest.approx(points["S1 [m/s]"][1], rel=1e-5)
