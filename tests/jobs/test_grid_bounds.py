"""Job grids are bounded and one point is one job: a range with a tiny step
and a grid over the limit are refused at once, naming the limit; two
spellings of one value are one point."""
import os
import subprocess
import sys
import time

import pytest

from mlgshimmy.shared.jobs import grid


def test_two_spellings_of_one_value_are_one_point():
    assert grid.axis("10,1e1,10.0", "SWEEP_RHO") == [10.0]
    assert grid.axis("0,-0", "SWEEP_MU") == [0.0]
    assert [f"{v:g}" for v in grid.axis("-0,5", "X")] == ["0", "5"]


def test_different_values_of_one_name_are_still_refused():
    with pytest.raises(grid.GridError, match="same grid point"):
        grid.axis("10,10.0000001", "SWEEP_RHO")


def test_a_tiny_step_is_refused_at_once():
    started = time.monotonic()
    with pytest.raises(grid.GridError, match=r"SWEEP_RHO=.*limit of 2000 points"):
        grid.axis("0:10:1e-300", "SWEEP_RHO")
    assert time.monotonic() - started < 1.0


def test_a_plane_over_the_limit_is_refused(monkeypatch):
    rho = grid.axis("0:39:1", "SWEEP_RHO")
    mu = grid.axis("0:49:1", "SWEEP_MU")
    assert len(grid.plane(rho, mu)) == 40 * 50
    rho = grid.axis("0:40:1", "SWEEP_RHO")
    with pytest.raises(grid.GridError, match="41 x 50 = 2050 points, more than the limit of 2000"):
        grid.plane(rho, mu)
    monkeypatch.setenv(grid.MAX_POINTS_ENV, "3000")
    assert len(grid.plane(rho, grid.axis("0:49:1", "SWEEP_MU"))) == 2050
    monkeypatch.setenv(grid.MAX_POINTS_ENV, "lots")
    with pytest.raises(grid.GridError, match="MLG_GRID_MAX_POINTS='lots'"):
        grid.max_points()


def test_the_sweep_targets_refuse_a_tiny_step_in_a_second():
    started = time.monotonic()
    proc = subprocess.run([sys.executable, "-m", "mlgshimmy.studies.sweep", "targets",
                           "--rho=0:10:1e-300", "--mu=0"], capture_output=True, text=True,
                          timeout=60, env=dict(os.environ))
    assert proc.returncode != 0 and "limit of 2000 points" in proc.stderr, proc.stderr
    assert time.monotonic() - started < 10
