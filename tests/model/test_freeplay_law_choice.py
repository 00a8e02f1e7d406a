"""The freeplay law chosen by name (FREEPLAY=, or the overlay entry
freeplay_law=<name>): one table in c/freeplay_laws.h, read by the drivers
as text and by the library; part of the gear's identity, tree, provenance
and title; drawn by Figs. 6 and 15.

Run: /usr/bin/python3 -m pytest -q tests/model/test_freeplay_law_choice.py
"""
import os
import pathlib
import subprocess

import numpy
import pytest

import helpers
from mlgshimmy.shared import freeplay, gear, mlgmodel, overlay

ROOT = pathlib.Path(helpers.ROOT)
GEAR_ENV = ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES", "MLG_RUN_ROOT",
            "MLG_BASE_RUN_ROOT", "MLG_RHO_DEG", "MLG_MU_DEG", "MLG_EOM", "MLG_SET")


def make(*args):
    clean = {k: v for k, v in os.environ.items() if k not in GEAR_ENV}
    return subprocess.run(["make", "--no-print-directory", *args], cwd=ROOT, env=clean,
                          capture_output=True, text=True)


def test_the_header_s_laws_are_the_library_s():
    assert overlay.laws() == tuple(mlgmodel.LAWS)
    assert overlay.laws()[:2] == ("atan", "nonsmooth")
    assert {"tanh", "cubic", "hertz"} <= set(overlay.laws())


def test_a_law_is_an_overlay_entry_named_by_what_it_is():
    items = overlay.parse("freeplay_law=tanh k_tlk=3.51e7")
    tanh = overlay.laws().index("tanh")
    assert items == (("freeplay_law", float(tanh)), ("k_tlk", 3.51e7))
    g = gear.Gear(changes=items)
    assert g.tag == "freeplay_tanh+k_tlk_35100000"
    assert g.law() == tanh and g.parameters()["freeplay_law"] == tanh
    assert g.describe() == "freeplay law tanh, k_tlk = 35100000 N/m"
    assert overlay.parse(overlay.text(items)) == items
    assert gear.Gear.from_record(g.record()) == g
    # the paper's law is the paper's gear
    assert overlay.parse("freeplay_law=atan") == ()


def test_a_misspelt_law_is_refused_in_one_line():
    with pytest.raises(overlay.OverlayError, match="no freeplay law named 'tahn'; did you "
                                                   "mean tanh"):
        overlay.parse("freeplay_law=tahn")
    with pytest.raises(overlay.OverlayError, match="no freeplay law named '2'"):
        overlay.parse("freeplay_law=2")
    proc = make("fig06-plot", "FREEPLAY=cubik")
    assert proc.returncode != 0 and "did you mean cubic?" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_make_gives_a_law_its_own_tree(tmp_path):
    proc = make("fig10-plot", f"MLG_RUN_ROOT={tmp_path}", "FREEPLAY=hertz")
    assert proc.returncode != 0                  # nothing is computed
    assert f"{tmp_path}/gear/freeplay_hertz/fig10/result.json" in proc.stderr
    proc = make("fig10-plot", f"MLG_RUN_ROOT={tmp_path}", "FREEPLAY=atan")
    assert f"{tmp_path}/fig10/result.json" in proc.stderr


@pytest.mark.parametrize("law", range(5))
def test_the_profile_drawn_is_the_gear_s_law(law, monkeypatch):
    """freeplay.force (Figs. 6, 15, 19) evaluates the gear's law: the same
    force as the vector field's torque-link moment / r_tlk at that law."""
    monkeypatch.setattr(gear, "current", lambda: gear.Gear(
        changes=((overlay.LAW, float(law)),) if law else ()))
    model = mlgmodel.Model("figures", Fstar=1.0, V=50.0, yfp=1.0, freeplay_law=law)
    u = model.equilibrium()
    r = model.r_tlk(u["eta"])
    from mlgshimmy.shared import domain
    for y in (0.4e-3, 1.0e-3, 1.04e-3, 1.3e-3, -2e-3):
        u["psi"] = y / r
        d = domain.diagnose(model, u)
        want = d["M_kpsi"] / d["r_tlk"]
        got = freeplay.force(numpy.array([y]), 1e-3, model.epsilon_m(), model["k_tlk"])[0]
        assert got == pytest.approx(want, rel=1e-12, abs=1e-9)
