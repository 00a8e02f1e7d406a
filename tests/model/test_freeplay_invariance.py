"""The paper's invariance claim (section V), tested for every freeplay law.

A law whose force is k_tlk y_fp G(y / y_fp) for one shape G (the profile at
a constant scale: eps = 0.1 y_fp, or no eps at all as in eq. 14) makes
straight rolling's linearisation independent of y_fp (its stiffness at
y = 0 is k_tlk G'(0)): the Hopf points do not move.  The orbits scale
linearly in y_fp as far as the rest of the model is linear at their
amplitude (a few mrad: measured below 1e-4).

A law with a fixed physical scale (eps = 0.1 mm whatever y_fp) changes the
shape G with y_fp and must break this: its orbits' amplitudes no longer
scale (the corners are reached at another relative width), and for atan
and tanh, whose stiffness at y = 0 depends on eps / y_fp, the Hopf points
move too.  cubic and hertz are exactly zero inside |y| < y_fp - eps: their
Hopf points stay put even at a fixed eps < y_fp; only the orbits, which
reach the corners, break the scaling.  Eq. (14) has no eps: invariant
either way.

Fig. 10's gear (F* = 1) at V = 100 m/s on the stable high-frequency orbit,
y_fp = 0.5 and 1 mm; runs started at psi = 0.01 rad y_fp / 1 mm, so that a
scaled run is the scaled trajectory throughout.

Run: /usr/bin/python3 -m pytest -q tests/model/test_freeplay_invariance.py
"""
import numpy
import pytest

from mlgshimmy.shared import mlgmodel, naming, simulator

GRID = numpy.linspace(0.5, 200.0, 400)          # V [m/s]: H1-H3 of Fig. 10 lie inside
SCALED, FIXED = {"eps_abs": 0.0, "eps_rel": 0.1}, {"eps_abs": 0.1, "eps_rel": 0.0}
SIMULATION = ("--V", 100, "--Fstar", 1, "--t-end", 6, "--dt-out", 2e-5, "--rtol", 1e-10,
              "--atol", 1e-12)
LINEAR = 2e-4      # relative: what the rest of the model leaves of the scaling
BROKEN = 1e-3      # relative: a fixed scale moves the orbit by at least this
HOPF = 1e-9        # relative: the bisection's resolution of a Hopf point


def hopf(law, yfp, scale):
    return naming.scanned("figures", "V", GRID, Fstar=1.0, yfp=yfp, freeplay_law=law, **scale)


def orbit(law, yfp, scale):
    params = {"freeplay_law": law, "yfp": yfp, **scale}
    out = simulator.simulate(None, *SIMULATION, "--psi0", 0.01 * yfp, params=params)
    return out["psi_amplitude_rad"], out["frequency_hz"]


def scaling_error(small, large):
    """|A(1 mm) / (2 A(0.5 mm)) - 1| and the frequencies' relative change."""
    return abs(large[0] / (2 * small[0]) - 1), abs(large[1] / small[1] - 1)


@pytest.fixture(scope="module", params=range(5), ids=lambda k: mlgmodel.LAWS[k])
def law(request):
    k = request.param
    one = orbit(k, 1.0, SCALED)      # eps = 0.1 mm at 1 mm: both scalings' run
    return {"law": k, "name": mlgmodel.LAWS[k],
            "hopf": {y: hopf(k, y, SCALED) for y in (0.5, 1.0, 2.0)},
            "hopf_fixed": hopf(k, 0.5, FIXED),
            "scaled": scaling_error(orbit(k, 0.5, SCALED), one),
            "fixed": scaling_error(orbit(k, 0.5, FIXED), one)}


def test_at_a_constant_scale_the_hopf_points_do_not_move(law):
    at = law["hopf"]
    assert {"H1", "H2", "H3"} <= set(at[1.0]), law["name"]     # Fig. 10's three
    for y in (0.5, 2.0):
        assert set(at[y]) == set(at[1.0])
        for name, v in at[1.0].items():
            assert at[y][name] == pytest.approx(v, rel=HOPF), (law["name"], name, y)


def test_at_a_constant_scale_the_orbits_scale_linearly(law):
    amplitude, frequency = law["scaled"]
    print(f"# {law['name']}: eps = 0.1 y_fp: amplitude off linear by {amplitude:.2e}, "
          f"frequency by {frequency:.2e}; eps = 0.1 mm: {law['fixed'][0]:.2e}, "
          f"{law['fixed'][1]:.2e}")
    assert amplitude < LINEAR and frequency < LINEAR


def test_a_fixed_physical_scale_breaks_the_invariance(law):
    amplitude, frequency = law["fixed"]
    moved = max(abs(law["hopf_fixed"].get(n, numpy.inf) / v - 1)
                for n, v in law["hopf"][1.0].items())
    if law["name"] == "nonsmooth":          # no eps: the same model either way
        assert law["fixed"] == law["scaled"] and moved < HOPF
        return
    assert amplitude > BROKEN, f"{law['name']}: amplitudes still scale at a fixed eps"
    if law["name"] in ("atan", "tanh"):     # stiffness at y = 0 depends on eps / y_fp
        assert moved > BROKEN
    else:                                   # zero inside |y| < y_fp - eps
        assert moved < HOPF
