"""The drivers from a notebook (#40): the model's vector field, frequencies
in Hz, "did you mean" on a misspelt name, and `make venv` (or its
one-sentence refusal); the type hints: tests/release/test_type_hints.py."""
import os
import subprocess
import sys

import numpy
import pytest

from helpers import ROOT
from mlgshimmy.shared import mlgmodel, spectrum

def test_rhs_vanishes_at_straight_rolling_and_is_the_jacobians_f():
    model = mlgmodel.Model(Fstar=0.2, V=300.0, yfp=1.0)
    u = model.equilibrium()
    assert numpy.max(numpy.abs(model.rhs(u))) < 1e-9
    moved = dict(u, psi=0.01)
    f = model.rhs(moved)
    # dpsi/dt is psi_dot; dpsi_dot/dt follows J to first order
    h = 1e-7
    slope = (model.rhs(dict(u, psi=h)) - model.rhs(dict(u, psi=-h))) / (2 * h)
    numpy.testing.assert_allclose(slope, model.jacobian(u)[:, 0], rtol=1e-5, atol=1e-6)
    assert f[mlgmodel.UNAMES.index("psi_dot")] < 0.0     # the torque links pull psi back


@pytest.mark.parametrize("call, message", [
    (lambda: mlgmodel.Model(Fstr=1.0), "no parameter or constant named 'Fstr'; did you mean Fstar?"),
    (lambda: mlgmodel.Model("figure"), "unknown parameter set 'figure'; did you mean figures?"),
    (lambda: mlgmodel.Model().rhs({"pzi": 0.0}), "no state named 'pzi'; did you mean psi?"),
])
def test_a_misspelt_name_gets_a_suggestion(call, message):
    with pytest.raises((KeyError, ValueError)) as error:
        call()
    assert error.value.args[0] == message


def test_a_state_of_the_wrong_length_is_refused_by_its_length():
    with pytest.raises(ValueError, match="a state has 10 values .* not 3"):
        mlgmodel.Model().rhs([0.0] * 3)


def test_stability_changes_give_hertz_as_hopf_scan_does():
    grid = numpy.linspace(300.0, 400.0, 11)
    (V, kind, hz), = spectrum.stability_changes("figures", "V", grid, Fstar=1.0, yfp=0.0)
    assert kind == "HB" and V == pytest.approx(346.1, abs=1e-3)
    assert spectrum.hopf_scan("figures", "V", grid, Fstar=1.0, yfp=0.0) == [(V, hz)]
    eig = spectrum.eigenvalues(mlgmodel.Model(V=V, Fstar=1.0, yfp=0.0))
    assert hz == pytest.approx(numpy.min(numpy.abs(eig.imag[numpy.argsort(abs(eig.real))[:2]]))
                               / (2 * numpy.pi), rel=1e-6)


def _make_venv(tmp_path, python):
    return subprocess.run(["make", "-s", "--no-print-directory", "venv",
                           f"VENV={tmp_path / 'v'}", f"PYTHON={python}"],
                          cwd=ROOT, capture_output=True, text=True)


def test_make_venv_imports_the_drivers(tmp_path):
    proc = _make_venv(tmp_path, sys.executable)
    assert proc.returncode == 0, proc.stderr
    out = subprocess.run([str(tmp_path / "v" / "bin" / "python"), "-c",
                          "import mlgshimmy.shared.mlgmodel as m; print(m.__file__)"],
                         cwd=tmp_path, capture_output=True, text=True, env={})
    assert out.stdout.strip() == os.path.join(ROOT, "drivers", "mlgshimmy", "shared",
                                              "mlgmodel.py")


def test_make_venv_refuses_an_interpreter_without_numpy_in_one_sentence(tmp_path):
    bare = tmp_path / "bare"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(bare)], check=True)
    proc = _make_venv(tmp_path, bare / "bin" / "python")
    assert proc.returncode != 0
    assert proc.stderr.splitlines()[0] == (
        f"venv: PYTHON={bare}/bin/python (Python {sys.version_info[0]}.{sys.version_info[1]}) "
        "has no numpy; the interpreter must be Python >= 3.9 with numpy, scipy and matplotlib: "
        "Debian's /usr/bin/python3 has them (make setup installs them), or give "
        "PYTHON=<such an interpreter>")
