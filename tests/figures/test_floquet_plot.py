"""The Floquet-multiplier plot's crossings (studies.floquet_plot) and
AUTO's Fortran numbers in d-files (shared.floquet).

Run: /usr/bin/python3 -m pytest -q tests/figures/test_floquet_plot.py
"""
import numpy
import pytest

from mlgshimmy.shared import floquet
from mlgshimmy.studies import floquet_plot


def steps(values, extra):
    """Multipliers: the trivial 1, a stable complex pair, and extra(v)."""
    return [(v, numpy.array([1.0, 0.5 + 0.3j, 0.5 - 0.3j, *extra(v)])) for v in values]


def test_a_real_multiplier_through_minus_one_is_period_doubling():
    found = floquet_plot.crossings(steps(numpy.arange(0, 10.5, 1.0), lambda v: [-0.5 - 0.1 * v]))
    assert found == {"torus": [], "period doubling": [5.5], "fold": []}


def test_a_real_multiplier_through_plus_one_is_a_fold_the_trivial_one_is_not():
    found = floquet_plot.crossings(steps(numpy.arange(0, 10.5, 1.0), lambda v: [1.35 - 0.1 * v]))
    assert found["fold"] == [3.5] and found["period doubling"] == []


def test_a_complex_pair_leaving_the_unit_circle_is_a_torus_point():
    found = floquet_plot.crossings(steps(numpy.arange(0, 10.5, 1.0),
                                         lambda v: [(0.9 + 0.02 * v) * numpy.exp(1j * s)
                                                    for s in (0.7, -0.7)]))
    assert found["torus"] == pytest.approx([5.0]) and found["fold"] == []


@pytest.mark.parametrize("text, value", [("-4.76747+288", -4.76747e288), ("1.5D+02", 150.0),
                                         ("1.5E-03", 1.5e-3), ("42.0", 42.0), ("-3", -3.0)])
def test_fortran_numbers(text, value):
    assert floquet.fortran_number(text) == value


D_FILE_BLOCK = """\
   2   129   7        5.14441E+01   2.04749E+02
   2   129         Multiplier  1    1.01367E+00   0.00000E+00  Abs. Val.   1.01367E+00
   2   129         Multiplier  2   -9.71553E-01   2.42974E-01  Abs. Val.   1.00147E+00
   2   129         Multiplier  3   -9.71553E-01  -2.42974E-01  Abs. Val.   1.00147E+00
   2   129         Multiplier  4    1.79769+308   1.79769+308  Abs. Val.   1.79769+308
"""


def test_an_infinite_multiplier_is_read_as_a_real_infinity(tmp_path):
    """AUTO prints the multiplier it cannot compute (an MX point's, FLOWKM)
    as CMPLX(HUGE, HUGE) with a three-digit exponent and no E (at rho = 5,
    mu = -15 deg, slice 1.5625 of Fig. 11, this stopped the torus part): it
    is a real infinity, so the complex pair in the block stays the critical one."""
    path = tmp_path / "d.po"
    path.write_text(D_FILE_BLOCK)
    (value, mults), = floquet.read(str(path))
    assert value == pytest.approx(51.4441)
    assert mults[3] == complex(numpy.inf, 0.0)
    rate, angle = floquet.critical(mults)
    assert rate == pytest.approx(abs(complex(-0.971553, 0.242974)) - 1.0, rel=1e-9)
    assert angle == pytest.approx(numpy.pi - numpy.arctan(0.242974 / 0.971553), rel=1e-9)
