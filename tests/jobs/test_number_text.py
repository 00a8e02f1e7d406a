"""Numbers typed on make's command line (RHO, MU, SET, a grid's axis) are
plain ASCII decimals: Python's float() reads '1_0' and Arabic-Indic digits
as 10, which a typo must not silently become (#38)."""
import pytest

from mlgshimmy.shared import geometry, number_text, overlay
from mlgshimmy.shared.jobs import grid

NOT_PLAIN = ["1_0", "\u0661\u0660", "\uff11\uff10", "inf", "nan", "0x10", "1e", "10deg"]


@pytest.mark.parametrize("text, value", [
    ("10", 10.0), ("-2.5", -2.5), (".5", 0.5), ("5.", 5.0), ("+3E-2", 0.03), (" 7 ", 7.0)])
def test_plain_numbers_are_read(text, value):
    assert number_text.parse(text) == value


@pytest.mark.parametrize("text", NOT_PLAIN)
def test_anything_else_is_refused_by_every_reader(text):
    assert number_text.parse(text) is None
    with pytest.raises(geometry.GeometryError,
                       match=r"^RHO=.* \(MLG_RHO_DEG\) is not a number in degrees: give ASCII"):
        geometry.from_environment({geometry.ENV_RHO: text})
    with pytest.raises(overlay.OverlayError, match=r"^SET: 'k_tlk=.*' is not a number: give ASCII"):
        overlay.parse(f"k_tlk={text}")
    with pytest.raises(grid.GridError, match=r"^SWEEP_RHO=.* is not a number .*each ASCII"):
        grid.axis(f"0,{text}", "SWEEP_RHO", "degrees")

