"""mlgmodel.Model.set refuses what is not a finite number by the
parameter's name (#38): 10**400 raised an OverflowError naming nothing, a
name with a NUL was cut by ctypes and set V, and a NaN was only refused
when the model was next evaluated."""
import math

import pytest

from mlgshimmy.shared import mlgmodel


def test_a_value_beyond_a_double_names_the_parameter():
    with pytest.raises(ValueError) as error:
        mlgmodel.Model(V=10**400)
    assert str(error.value) == "parameter V is beyond the range of a double (|value| < 1.8e308)"


def test_a_name_with_a_nul_sets_nothing():
    model = mlgmodel.Model(V=100.0)
    with pytest.raises(KeyError) as error:
        model.set(**{"V\0x": 5.0})
    assert error.value.args[0] == r"no parameter or constant named 'V\x00x' (a name holds no NUL)"
    assert model["V"] == 100.0


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_a_non_finite_value_is_refused_by_set(value):
    model = mlgmodel.Model()
    rho = model["rho"]
    with pytest.raises(ValueError) as error:
        model.set(rho=value)
    assert str(error.value) == f"parameter rho = {value!r} is not finite"
    assert model["rho"] == rho
