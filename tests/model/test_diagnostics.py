"""mlg_diagnose from Python (shared.domain): the layout of mlg_diagnostics
is the library's (MLG_DIAGNOSTICS, c/mlg_parameters.h), so every field is read
at its own place, the first, a tyre pair in the middle and the last.

Run: /usr/bin/python3 -m pytest -q tests/model/test_diagnostics.py
"""
import math

import pytest

from mlgshimmy.shared import domain, mlgmodel


def test_every_field_is_read_at_its_place():
    rho, mu = 0.1, 0.2
    model = mlgmodel.Model("figures", Fstar=1.3, V=50.0, rho=rho, mu=mu, eom_terms=2.0)
    u = model.equilibrium()
    u["psi_dot"] = 0.3
    d = domain.diagnose(model, u)
    assert d["status"] == 0
    assert [name for name, _ in mlgmodel.DIAGNOSTICS] == [k for k in d if k != "status"]
    assert d["F_z"] == pytest.approx(1.3 * model["g_0"] * model["m_0"], rel=1e-15)  # II.A
    assert d["r_tlk"] == pytest.approx(model.r_tlk(u["eta"]), rel=1e-15)
    assert len(d["F"]) == 2 and min(d["F"]) > 0.0
    sin_p = (math.sin(rho) * math.cos(model["phi0"])
             - math.cos(rho) * math.sin(mu) * math.sin(model["phi0"]))   # docs/model.md 4.13
    assert d["p"] == pytest.approx(math.asin(sin_p), rel=1e-14)
    # eq. (16) with the side-stay twist (eom_terms 2): c_psi (psi' + beta' sin p), beta' = 0
    assert d["M_cpsi"] == pytest.approx(model["c_psi"] * 0.3, rel=1e-14)
