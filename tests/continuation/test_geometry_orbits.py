"""AUTO's periodic orbits at a side-stay geometry against the time
simulation (a check that does not depend on the drivers' continuation):
at rho = mu = 10 deg (complete equations), F* = 0.2, zero freeplay, the
orbit born at the Hopf point of straight rolling, continued to V = 300 m/s,
is started in the simulator at its own first point (mlg_simulate --u0);
after 3 s the simulation's torsional amplitude (half peak-to-peak, about
its own mean) and frequency equal AUTO's within 1e-4."""
import math

import pytest

from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import geometry
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import simulator

GEOMETRY = geometry.Geometry(10.0, 10.0, 2)
TOL = 1e-4
SIMULATED = 3.0      # s (the summary is of the last second: 38 periods)


@pytest.fixture(scope="module")
def orbit(tmp_path_factory):
    rundir = str(tmp_path_factory.mktemp("geometry-orbits"))
    start = ct.Start("figures", Fstar=0.2, V=geometry.V_FROM, **GEOMETRY.parameters())
    eq = ct.equilibria(rundir, "eq", start, stop={"V": 400.0}, expect=["HB"])
    return ct.periodic_from(rundir, "po", eq("HB1"), stop={"V": 300.0}, expect=["UZ"])("UZ1")


@pytest.fixture(scope="module")
def simulated(orbit):
    u0 = ",".join(repr(float(orbit[name][0])) for name in mlgmodel.UNAMES)
    return simulator.simulate(None, "--V", orbit["V"], "--Fstar", 0.2, "--t-end", SIMULATED,
                              "--dt-out", 1e-5, "--rtol", 1e-10, "--atol", 1e-12, "--u0", u0,
                              params=GEOMETRY.simulator_params())


def test_the_orbit_is_off_centre(orbit):
    """The side stay yaws the orbit: its mean torsion is not zero."""
    assert orbit["psi_mean"] > 1e-2 * orbit["psi_amp"], orbit["psi_mean"]


@pytest.mark.parametrize("measure, key", (("psi_amp", "psi_amplitude_rad"),
                                          ("freq", "frequency_hz")))
def test_auto_orbit_equals_the_simulation(orbit, simulated, measure, key):
    assert math.isclose(simulated[key], orbit[measure], rel_tol=TOL), \
        f"{measure}: AUTO {orbit[measure]!r}, simulation {simulated[key]!r}"
