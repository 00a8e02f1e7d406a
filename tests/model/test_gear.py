"""The gear a run is made for (shared.gear, shared.overlay, mk/gear.mk): an
overlay of any constant per run, validated up front, in its own tree, and
recorded in every cached result, which is refused for another gear.

Run: /usr/bin/python3 -m pytest -q tests/model/test_gear.py
"""
import json
import os
import pathlib
import subprocess

import pytest

import helpers
from mlgshimmy.shared import gear, geometry, jobs, mlgmodel, overlay

ROOT = pathlib.Path(helpers.ROOT)
GEAR_ENV = ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES", "MLG_RUN_ROOT",
            "MLG_BASE_RUN_ROOT", "MLG_RHO_DEG", "MLG_MU_DEG", "MLG_EOM", "MLG_SET")


def make(*args, **env):
    clean = {k: v for k, v in os.environ.items() if k not in GEAR_ENV}
    return subprocess.run(["make", "--no-print-directory", *args], cwd=ROOT,
                          env={**clean, **env}, capture_output=True, text=True)


def test_the_header_names_are_the_library_s():
    """overlay reads c/mlg_parameters.h as text (no build needed): the same
    names as the built library, each with its unit."""
    units = overlay.known()
    assert set(units) == set(mlgmodel.FIELDS)
    assert units["k_tlk"] == "N/m" and units["I_psi"] == "kg m^2" and units["M"] == "kg"


def test_an_overlay_is_parsed_sorted_and_tagged():
    items = overlay.parse("k_tlk=3.51e7, I_psi=160")
    assert items == (("I_psi", 160.0), ("k_tlk", 3.51e7))
    g = gear.Gear(changes=items)
    assert not g.baseline and g.symmetric
    assert g.tag == "I_psi_160+k_tlk_35100000"
    assert g.parameters() == {"I_psi": 160.0, "k_tlk": 3.51e7}
    assert g.simulator_params() == {"I_psi": "160.0", "k_tlk": "35100000.0"}
    assert g.describe() == "I_psi = 160 kg m^2, k_tlk = 35100000 N/m"
    both = gear.Gear(geometry.Geometry(10, 10, 2), items)
    assert both.tag == "rho10_mu10_eom2+I_psi_160+k_tlk_35100000"
    assert both.parameters()["rho"] == pytest.approx(0.174532925199)
    assert gear.tree("/x/build", g) == "/x/build/gear/I_psi_160+k_tlk_35100000"
    assert gear.tree("/x/build", gear.Gear(geometry.Geometry(10, 10, 2))) == \
        "/x/build/geometry/rho10_mu10_eom2"
    assert gear.tree("/x/build", gear.Gear()) == "/x/build"
    assert gear.Gear.from_record(both.record()) == both
    assert gear.Gear(changes=overlay.parse("k_tlk=3.51e7")).tag != \
        gear.Gear(changes=overlay.parse("k_tlk=3.5100001e7")).tag


@pytest.mark.parametrize("text, says", [
    ("k_tk=3e7", "did you mean k_tlk?"),
    ("Fstar=0.5", "Fstar cannot be overlaid: each figure sets it"),
    ("rho=0.1", "RHO=<degrees>"),
    ("k_tlk=fast", "'fast' is not a number"),
    ("k_tlk=nan", "'nan' is not a number"),
    ("k_tlk=1e400", "must be finite"),
    ("k_tlk", "is not NAME=VALUE"),
    ("c_psi=1 c_psi=2", "c_psi is given twice"),
])
def test_a_bad_overlay_names_the_entry(text, says):
    with pytest.raises(overlay.OverlayError, match="SET: ") as error:
        overlay.parse(text)
    assert says in str(error.value)


def test_a_value_out_of_range_is_refused_in_its_units(monkeypatch):
    monkeypatch.setattr(gear, "current", lambda: gear.Gear(changes=(("k_tlk", -1.0),)))
    with pytest.raises(ValueError, match=r"SET='k_tlk=-1': parameter k_tlk = -1 N/m"):
        gear.check()


def test_make_gives_each_gear_its_own_tree(tmp_path):
    """SET and a geometry each get a tree; a MLG_RUN_ROOT given on make's
    command line is the base of that tree, never the tree itself, so the
    paper's gear and a changed one never share one."""
    def where(*args):
        proc = make("fig10-plot", *args)
        assert proc.returncode != 0                                  # nothing is computed
        return proc.stderr
    base = f"MLG_RUN_ROOT={tmp_path}"
    assert f"{tmp_path}/fig10/result.json" in where(base)
    assert f"{tmp_path}/gear/k_tlk_35100000/fig10/result.json" in \
        where(base, "SET=k_tlk=3.51e7")
    assert f"{tmp_path}/gear/rho10_mu10_eom2+k_tlk_35100000/fig10/result.json" in \
        where(base, "SET=k_tlk=3.51e7", "RHO=10", "MU=10")
    assert f"{tmp_path}/geometry/rho10_mu10_eom2/fig10/result.json" in \
        where(base, "RHO=10", "MU=10")


def test_make_refuses_a_bad_overlay_in_one_line():
    proc = make("fig10-plot", "SET=k_tk=3e7")
    assert proc.returncode != 0
    assert "SET: no parameter or constant named 'k_tk'; did you mean k_tlk?" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_the_studies_with_their_own_gear_refuse_an_overlay():
    proc = make("-n", "sidestay", "RHO=10", "MU=10", "SET=k_tlk=3.51e7")
    assert proc.returncode != 0 and "takes no SET yet" in proc.stderr


def test_a_result_made_for_another_gear_is_refused(tmp_path, monkeypatch):
    """A result copied from a changed gear's tree into the paper's is not
    drawn as the paper's gear: read names both gears."""
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    changed = gear.Gear(changes=(("k_tlk", 3.51e7),))
    monkeypatch.setattr(gear, "current", lambda: changed)
    monkeypatch.setattr(jobs.cache, "provenance", lambda parameter_set: {
        "parameter_set": parameter_set, "model": gear.current().record()})
    jobs.write("figx", {"numbers": {"H1 [m/s]": 1.0}})
    assert jobs.read("figx") == {"numbers": {"H1 [m/s]": 1.0}}
    monkeypatch.setattr(gear, "current", lambda: gear.Gear())
    with pytest.raises(jobs.BadResult, match=r"was made for k_tlk = 35100000 N/m, not for "
                                             r"the paper's gear as asked"):
        jobs.read("figx")
    assert jobs.read("figx", model=changed)["numbers"]["H1 [m/s]"] == 1.0
    stored = json.loads((tmp_path / "figx" / "result.json").read_text())
    del stored["provenance"]["model"]
    (tmp_path / "figx" / "result.json").write_text(json.dumps(stored))
    with pytest.raises(jobs.BadResult, match="made for an unrecorded gear"):
        jobs.read("figx")


def test_a_run_root_given_to_regress_leaves_it_in_its_private_directory(tmp_path):
    """`make regress-<fig> MLG_RUN_ROOT=R` runs, compares and publishes as
    without it: the figure's runs go to regress's private directory, never
    to R (it was sent outside it and stopped: no such run directory)."""
    proc = make("regress-fig09", f"MLG_RUN_ROOT={tmp_path / 'elsewhere'}")
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    assert "fig09 vs tests/reference/fig09: agree" in proc.stdout
    assert not (tmp_path / "elsewhere").exists()
