"""make point (studies.point_view): one labelled point of a diagram, its
multipliers as AUTO's d-file has them and a simulation from it.  An orbit
run (Fig. 8's case: V = 300 m/s, F* = 0.2, zero freeplay) and the
equilibria it starts from, made here by AUTO.

Run: /usr/bin/python3 -m pytest -q tests/figures/test_point_view.py   (about 20 s)
"""
import os
import subprocess

import numpy as np
import pytest

from helpers import ROOT
from mlgshimmy.shared import diagrams, rundirs
from mlgshimmy.shared import continuation as ct
from mlgshimmy.studies import point_view


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    path = str(tmp_path_factory.mktemp("point") / "runs")
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv(rundirs.CLAIMED_ENV, raising=False)
        start = ct.Start("figures", Fstar=0.2, V=0.0)
        eq = ct.equilibria(path, "eq", start, stop={"V": 400.0}, expect=["HB"])
        ct.periodic_from(path, "po", eq("HB1"), stop={"V": 300.0}, expect=["UZ"])
        yield path


def test_an_orbit_point_keeps_its_multipliers_and_a_simulation_stays_on_it(runs):
    label = [int(s["LAB"]) for s in diagrams.read_diagram(
        [os.path.join(runs, f"{k}.po") for k in "bsd"], "test")() if s["TY name"] == "UZ"][0]
    found = point_view.compute(os.path.join(runs, "po"), label)
    assert found["type"] == "UZ" and found["V"] == pytest.approx(300.0, abs=1e-6)
    mult = np.array(found["multipliers"]["re"]) + 1j * np.array(found["multipliers"]["im"])
    assert len(mult) == 10
    # a stable orbit (Fig. 8 settles on it): the trivial multiplier at 1, the rest inside
    assert np.min(np.abs(mult - 1.0)) < 1e-3
    assert np.sort(np.abs(mult))[-2] < 1.0
    # started on the orbit, the simulation keeps its amplitude (0.0375 rad) over 40 periods
    psi = np.array(found["states"]["psi"])
    amplitude = 0.5 * (psi.max() - psi.min())
    assert amplitude == pytest.approx(0.0375, rel=0.01)
    series = np.array(found["series"]["psi"])
    last = series[-point_view.SAMPLES_PER_PERIOD * 5:]
    assert 0.5 * (last.max() - last.min()) == pytest.approx(amplitude, rel=2e-3)
    assert found["series"]["t"][-1] == pytest.approx(point_view.PERIODS * found["period"])


def test_an_equilibrium_point_has_its_jacobians_eigenvalues(runs):
    found = point_view.compute(os.path.join(runs, "eq"), 2)     # HB1, the Hopf point
    assert found["type"] == "HB" and found["period"] == 0.0
    eig = np.array(found["multipliers"]["re"]) + 1j * np.array(found["multipliers"]["im"])
    critical = eig[np.argmin(np.abs(eig.real))]
    assert abs(critical.real) < 1e-3 and abs(critical.imag) > 100.0   # the Hopf pair


@pytest.mark.parametrize("args, message", [
    (["RUN=build/no/such", "LABEL=1"], "point: RUN=build/no/such: no build/no/b.such (a run "
     "directory and run name, e.g. RUN=build/fig10/po3 after make fig10)"),
])
def test_make_point_refuses_a_missing_run_in_one_line(args, message):
    proc = subprocess.run(["make", "-s", "--no-print-directory", "point", *args], cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode != 0
    assert [line for line in proc.stderr.splitlines() if not line.startswith("make")] == [message]
