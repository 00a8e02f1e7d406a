"""A side-stay geometry for every figure and study (shared.geometry,
mk/gear.mk): the environment read and checked, the tree of a geometry,
the parameters reaching the model and the simulator, straight rolling at
side-stay angles (shared.rolling) and the torque-link position y_tlk.

Run: /usr/bin/python3 -m pytest -q tests/model/test_geometry.py
"""
import math
import os
import pathlib
import subprocess

import pytest

import helpers
from mlgshimmy.shared import gear, geometry, mlgmodel, rolling, rolling_state, simulator

ROOT = pathlib.Path(helpers.ROOT)
TEN = {"rho": math.radians(10), "mu": math.radians(10), "eom_terms": 2.0}


def make(*args, **env):
    clean = {k: v for k, v in os.environ.items()
             if k not in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES", "MLG_RUN_ROOT",
                          "MLG_BASE_RUN_ROOT", geometry.ENV_RHO, geometry.ENV_MU,
                          geometry.ENV_EOM, "MLG_SET")}
    return subprocess.run(["make", "--no-print-directory", *args], cwd=ROOT,
                          env={**clean, **env}, capture_output=True, text=True)


@pytest.mark.parametrize("environ, key", [
    ({}, (0.0, 0.0, 0)),
    ({"MLG_RHO_DEG": "", "MLG_MU_DEG": "", "MLG_EOM": ""}, (0.0, 0.0, 0)),
    ({"MLG_RHO_DEG": "10"}, (10.0, 0.0, 2)),                 # EOM 2 with an angle
    ({"MLG_MU_DEG": "-0", "MLG_RHO_DEG": "0", "MLG_EOM": "0"}, (0.0, 0.0, 0)),
    ({"MLG_EOM": "1"}, (0.0, 0.0, 1)),
    ({"MLG_RHO_DEG": "1e1", "MLG_MU_DEG": "-20.0", "MLG_EOM": "0"}, (10.0, -20.0, 0)),
])
def test_the_environment_names_a_geometry(environ, key):
    assert geometry.from_environment(environ).key() == key


def test_the_baseline_changes_nothing():
    g = geometry.Geometry()
    assert g.baseline and g.parameters() == {} and g.simulator_params() == {}
    assert g.describe() == "" and g.suffix() == ""


@pytest.mark.parametrize("environ, variable", [
    ({"MLG_RHO_DEG": "ten"}, "RHO="), ({"MLG_MU_DEG": "95"}, "MU="),
    ({"MLG_MU_DEG": "nan"}, "MU="), ({"MLG_EOM": "3"}, "EOM="), ({"MLG_EOM": "2.0"}, "EOM="),
])
def test_a_bad_geometry_names_its_make_variable(environ, variable):
    with pytest.raises(geometry.GeometryError, match=variable):
        geometry.from_environment(environ)


def test_a_degenerate_side_stay_is_refused_in_degrees(tmp_path):
    """RHO=89.999 was refused by the library, in radians, after make had
    started the figure (and a figure with parts had made its directory)."""
    with pytest.raises(geometry.GeometryError) as error:
        geometry.from_environment({geometry.ENV_RHO: "89.999"})
    assert str(error.value) == (
        "RHO=89.999 MU=0: the side-stay angle p = 83 deg (docs/model.md 4.13) makes the gear "
        "geometry degenerate (cos p ~ 0); give angles with |p| <= 81.89 deg")
    proc = make("fig07", "RHO=89.999", MLG_RUN_ROOT=str(tmp_path))
    assert proc.returncode != 0 and "p = 83 deg" in proc.stderr and "fig07" not in proc.stdout
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("rho, mu", [(81.8, 0), (82, 0), (-82.1, 0), (0, 89), (60, 60),
                                     (75, -40), (89.999, 0)])
def test_the_degenerate_side_stay_is_the_librarys(rho, mu):
    """The check in degrees refuses exactly what c/parameters.c does."""
    try:
        geometry.from_environment({geometry.ENV_RHO: str(rho), geometry.ENV_MU: str(mu)})
        ours = None
    except geometry.GeometryError as exc:
        ours = str(exc)
    try:
        mlgmodel.Model("figures", rho=math.radians(rho), mu=math.radians(mu), eom_terms=2)
        library = None
    except ValueError as exc:
        library = str(exc)
    assert (ours is None) == (library is None), (ours, library)


def test_a_rejected_gear_makes_no_directory(tmp_path):
    """A figure with parts wrote its parts.mk into the gear's tree before the
    gear was checked (k_tlk = -1 left build/gear/k_tlk_-1/fig11/)."""
    proc = subprocess.run(["/usr/bin/python3", "-m", "mlgshimmy.figures.fig11", "rules"],
                          cwd=ROOT, capture_output=True, text=True,
                          env={**os.environ, "MLG_SET": "k_tlk=-1", "MLG_RUN_ROOT": str(tmp_path)})
    assert proc.returncode == 1
    assert proc.stderr == "fig11: SET='k_tlk=-1': parameter k_tlk = -1 N/m: stiffness must be > 0\n"
    assert os.listdir(tmp_path) == []


def test_parameters_tags_and_trees():
    g = geometry.Geometry(10, -20, 2)
    assert g.parameters() == {"rho": math.radians(10), "mu": math.radians(-20), "eom_terms": 2.0}
    assert g.tag == "rho10_mu-20_eom2" and g.mirror().tag == "rho-10_mu20_eom2"
    assert geometry.Geometry(10.00001, 0, 2).tag != geometry.Geometry(10, 0, 2).tag
    assert geometry.Geometry(0, 0, 2).tag == "rho0_mu0_eom2"     # not the baseline
    base = "/x/build"
    assert gear.tree(base, gear.Gear(geometry.Geometry())) == base
    inner = gear.tree(base, gear.Gear(g))
    assert inner == "/x/build/geometry/rho10_mu-20_eom2"
    assert gear.tree(inner, gear.Gear(g)) == inner                  # a make from a make
    assert gear.tree(inner, gear.Gear(g.mirror())) != inner


def test_make_gives_each_geometry_its_own_tree(tmp_path):
    def where(*args):
        proc = make("fig10-plot", *args, MLG_RUN_ROOT=str(tmp_path))
        assert proc.returncode != 0                                  # nothing is computed
        return proc.stderr
    assert f"{tmp_path}/fig10/result.json" in where()
    assert f"{tmp_path}/fig10/result.json" in where("RHO=0", "MU=0", "EOM=0")
    assert f"{tmp_path}/geometry/rho10_mu10_eom2/fig10/result.json" in where("RHO=10", "MU=10")
    assert f"{tmp_path}/geometry/rho10_mu10_eom0/fig10/result.json" in \
        where("RHO=10.0", "MU=1e1", "EOM=0")
    assert f"{tmp_path}/geometry/rho-10_mu0_eom2/fig10/result.json" in where("RHO=-10")


@pytest.mark.parametrize("args, named", [(("RHO=abc",), "RHO="), (("MU=90",), "MU="),
                                         (("RHO=1", "EOM=5"), "EOM=")])
def test_make_refuses_a_bad_geometry(args, named):
    proc = make("fig10-plot", *args)
    assert proc.returncode != 0 and named in proc.stderr and "rejected" in proc.stderr


def test_the_studies_with_their_own_angles_stay_in_the_base_tree():
    proc = make("-n", "sidestay", "RHO=10", "MU=10")
    assert proc.returncode == 0
    line = next(l for l in proc.stdout.splitlines() if "studies.sidestay" in l)
    assert "MLG_RUN_ROOT=" in line and "/geometry/" not in line and "MLG_RHO_DEG= " in line


@pytest.mark.parametrize("args, tree", [((), "/build/atlas/"),
                                        (("RHO=10", "MU=10"), "/build/geometry/rho10_mu10_eom2/atlas/")])
def test_a_job_grid_lists_its_cells_in_the_geometry_tree(args, tree):
    """The cells make waits for (mk/jobs.mk: `atlas targets` in a $(shell),
    which does not see make's exported geometry) lie in the tree the cells
    are written to."""
    proc = make("-n", "atlas", "ATLAS_V=10", "ATLAS_FSTAR=0.1", *args)
    assert proc.returncode == 0, proc.stderr
    assert any(l.startswith("mkdir -p ") and l.endswith(tree.rstrip("/"))
               for l in proc.stdout.splitlines()), proc.stdout
    assert "cell V10_F0.1" in proc.stdout, proc.stdout


def test_y_tlk_at_rho_mu_10_as_in_the_model_notes():
    """docs/model.md 8.7: the links sit at y_tlk = -0.46 mm inside the
    freeplay (y_fp = 1 mm, eps = 0.1 mm, F* = 1)."""
    model = mlgmodel.Model("figures", Fstar=1.0, V=50.0, yfp=1.0, eps_rel=0.1, **TEN)
    u = model.equilibrium()
    y = geometry.y_tlk(model, u)
    assert y == pytest.approx(-0.462257e-3, rel=1e-5)
    # eq. (15) at that deflection is the torque-link moment the model uses
    from mlgshimmy.shared import domain
    d = domain.diagnose(model, u)
    assert d["M_kpsi"] / d["r_tlk"] == pytest.approx(
        mlgmodel.torque_link_force(0, model["k_tlk"], y, 1e-3, model.epsilon_m()), rel=1e-12)
    mirror = mlgmodel.Model("figures", Fstar=1.0, V=50.0, yfp=1.0, eps_rel=0.1,
                            **{**TEN, "rho": -TEN["rho"], "mu": -TEN["mu"]})
    assert geometry.y_tlk(mirror, mirror.equilibrium()) == pytest.approx(-y, rel=1e-9)
    baseline = mlgmodel.Model("figures", Fstar=1.0, V=50.0, yfp=1.0, eps_rel=0.1)
    assert geometry.y_tlk(baseline, baseline.equilibrium()) == 0.0


def test_straight_rolling_is_continued_from_zero_freeplay():
    """Where Newton from psi = 0 finds the one equilibrium (F* = 1) the
    continuation gives the same state; at light load and large freeplay,
    where it finds none, the continuation does (the links near one edge)."""
    fixed = {"eps_abs": 0.1, "eps_rel": 0.0}
    u = rolling.state("figures", 1.0, 1.0, fixed, **TEN)
    v = mlgmodel.Model("figures", Fstar=1.0, V=50.0, yfp=1.0, **fixed, **TEN).equilibrium()
    assert max(abs(u[k] - v[k]) for k in u) < 1e-12
    with pytest.raises(RuntimeError):
        mlgmodel.Model("figures", Fstar=0.3, V=50.0, yfp=1.5, **fixed, **TEN).equilibrium()
    model = mlgmodel.Model("figures", Fstar=0.3, V=50.0, yfp=1.5, **fixed, **TEN)
    w = rolling.state("figures", 0.3, 1.5, fixed, **TEN)
    assert max(abs(f) for f in rolling._residual(model, list(w.values()))[0]) < 1e-6
    assert 0.5 < geometry.y_tlk(model, w) / 1.5e-3 < 1.0
    # at rho = mu = 0 it is solved once per load, as before
    assert rolling_state.rolling_state(0.3, 1.5) is rolling_state.rolling_state(0.3, 0.2)


def test_the_geometry_reaches_the_simulator(tmp_path):
    """A 1 ms run starts from the equilibrium of the geometry it is given."""
    g = geometry.Geometry(10, 10, 2)
    numbers = simulator.simulate(str(tmp_path / "r.csv"), "--V", 50, "--Fstar", 1.0,
                                 "--t-end", 1e-3, params=g.simulator_params())
    u = mlgmodel.Model("figures", V=50.0, Fstar=1.0, **g.parameters()).equilibrium()
    assert numbers["equilibrium_beta_rad"] == pytest.approx(u["beta"], rel=1e-8)
    plain = simulator.simulate(str(tmp_path / "p.csv"), "--V", 50, "--Fstar", 1.0,
                               "--t-end", 1e-3)
    assert plain["equilibrium_beta_rad"] != pytest.approx(u["beta"], rel=1e-3)


def test_a_figure_at_a_geometry_says_so(monkeypatch):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    monkeypatch.setattr(gear, "current", lambda: gear.Gear(geometry.Geometry(10, -20, 2)))
    fig, _ = plt.subplots()
    fig.suptitle("Fig. 10")
    gear.stamp(fig)
    assert fig._suptitle.get_text() == ("Fig. 10 [side stay rho = 10 deg, mu = -20 deg, "
                                        "the complete equations of motion]")
    bare, _ = plt.subplots(1, 2)
    gear.stamp(bare)
    assert "rho = 10 deg" in bare._suptitle.get_text()
    one, ax = plt.subplots()          # one titled axes (Fig. 11): the gear under its title
    ax.set_title("Fig. 11")
    gear.stamp(one)
    assert one._suptitle is None
    assert ax.get_title() == ("Fig. 11\nside stay rho = 10 deg, mu = -20 deg, "
                              "the complete equations of motion")
    plt.close("all")
    monkeypatch.setattr(gear, "current", lambda: gear.Gear())
    fig, _ = plt.subplots()
    gear.stamp(fig)
    assert fig._suptitle is None
    plt.close("all")
