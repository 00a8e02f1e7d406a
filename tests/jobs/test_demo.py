"""AUTO's own workflow in the run directory of `make demo`
(docs/auto-workflow.md): `auto mlg.auto` (AUTO's launcher, through the
directory's auto.env) reproduces Fig. 7's Hopf point at F* = 1 and its
periodic orbits, and `@r mlg` / `@sv mlg` run and save straight rolling from
c.mlg, both with the executable make built (AUTO must not rebuild it: its
own link line has no room for the library). AUTO's launcher exits 0 even
when the script fails, so the test reads the files it writes.

Run: /usr/bin/python3 -m pytest -q tests/jobs/test_demo.py   (about 10 s)
"""
import os
import pathlib
import re
import subprocess

import pytest

import helpers
from mlgshimmy.shared import mlgmodel

ROOT = pathlib.Path(helpers.ROOT)
V_HOPF = 346.1          # m/s, the paper's Fig. 7 (the `figures` set is calibrated to it)
HB, EP, UZ = 3, 9, -4   # AUTO's point types in b-files


def clean_env():
    """The environment without a make of ours around it (AUTO_DIR kept:
    the AUTO the test run uses)."""
    return {k: v for k, v in os.environ.items()
            if k not in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES")}


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    """make demo into a scratch directory (DEMO_DIR), not build/demo."""
    where = tmp_path_factory.mktemp("demo") / "demo"
    proc = subprocess.run(["make", "--no-print-directory", "demo", f"DEMO_DIR={where}"],
                          cwd=ROOT, env=clean_env(), capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for name in ("mlg.c", "mlg.o", "mlg.exe", "c.mlg", "mlg.auto", "auto.env"):
        assert (where / name).is_file(), name
    return where


def in_demo(demo, command):
    """`command` in a shell that sourced the directory's auto.env."""
    proc = subprocess.run(["bash", "-c", f". ./auto.env && {command}"], cwd=demo,
                          env=clean_env(), capture_output=True, text=True, timeout=300)
    return proc.returncode, proc.stdout + proc.stderr


def built(demo):
    return {name: (demo / name).stat().st_mtime_ns for name in ("mlg.o", "mlg.exe")}


def points(bfile):
    """(branch, type, label, first ICP value) of every labelled point of a b-file."""
    rows = []
    for line in bfile.read_text().splitlines():
        f = line.split()
        if len(f) > 4 and f[0] != "0" and f[3] != "0":
            rows.append((abs(int(f[0])), int(f[2]), int(f[3]), float(f[4])))
    return rows


def test_auto_script_reproduces_fig07_hopf_point(demo):
    before = built(demo)
    status, out = in_demo(demo, "auto mlg.auto")
    assert "Traceback" not in out, out
    bfile = demo / "b.fig07"
    assert bfile.is_file() and (demo / "s.fig07").is_file(), out
    pts = points(bfile)
    hopf = [v for br, ty, lab, v in pts if br == 1 and ty == HB]
    assert len(hopf) == 1, pts
    assert abs(hopf[0] - V_HOPF) <= 1e-3 * V_HOPF, hopf      # 1e-3 relative
    assert re.search(r"Hopf point HB: V = 346\.1\d* m/s", out), out
    # the orbits: a second branch from the Hopf point, ending at V = 600
    orbit_ends = [v for br, ty, lab, v in pts if br == 2 and ty in (EP, UZ)]
    assert orbit_ends and abs(orbit_ends[-1] - 600.0) <= 1e-6, pts
    # AUTO used the executable make built, and no compiler ran
    assert built(demo) == before
    assert "gcc " not in out and "gfortran " not in out
    assert not list(demo.glob("fort.*"))


def test_at_r_and_at_sv(demo):
    before = built(demo)
    status, out = in_demo(demo, "@r mlg && @sv mlg")
    assert status == 0, out
    assert "Saving fort.7 as b.mlg ... done" in out
    hopf = [v for br, ty, lab, v in points(demo / "b.mlg") if ty == HB]
    assert len(hopf) == 1 and abs(hopf[0] - V_HOPF) <= 1e-3 * V_HOPF, hopf
    assert built(demo) == before


def test_c_mlg_keeps_dsmax_near_2():
    """c.mlg alone (as @r mlg reads it) steps at most 2 m/s, the advice for
    straight rolling in V."""
    text = (ROOT / "constants" / "c.mlg").read_text()
    assert float(re.search(r"DSMAX\s*=\s*([0-9.eE+-]+)", text).group(1)) <= 2.0


def test_at_r_rebuilds_an_edited_mlg_c_or_runs_nothing(tmp_path):
    """@r mlg after editing mlg.c: AUTO's cmds.make compiled it alone, failed
    on mlg_model.h and (its .IGNORE) ran the old mlg.exe.  Now it is built with
    the library (mlg.mk, through MAKEFILES in auto.env); a broken mlg.c
    removes mlg.o and mlg.exe, so that nothing old runs."""
    where = tmp_path / "demo"
    proc = subprocess.run(["make", "--no-print-directory", "demo", f"DEMO_DIR={where}"],
                          cwd=ROOT, env=clean_env(), capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    source = where / "mlg.c"
    before = built(where)
    source.write_text(source.read_text().replace("p.V = 50.0;", "p.V = 60.0;"))
    os.utime(source, ns=(before["mlg.o"] + 10**9,) * 2)      # edited after make demo
    status, out = in_demo(where, "@r mlg")
    assert status == 0, out
    assert "No such file" not in out and "(ignored)" not in out, out
    assert all(built(where)[name] > before[name] for name in before), out
    first = points(where / "fort.7")[0]
    assert first[:3] == (1, EP, 1) and first[3] == 60.0, first      # the edited STPNT ran
    # a broken mlg.c: the build fails, said in one line, and no executable runs
    source.write_text(source.read_text().replace("p.V = 60.0;", "p.V = 60.0 +;"))
    (where / "fort.7").unlink()
    status, out = in_demo(where, "@r mlg")
    assert "@r mlg: mlg.c does not build with the model library (above): mlg.o and mlg.exe " \
        "removed, so that no old executable runs; fix mlg.c and run it again" in out, out
    assert not (where / "mlg.exe").exists() and not (where / "fort.7").exists(), out


def test_stpnt_starts_at_the_par_it_is_given(demo):
    """run(PAR={'Fstar': 0.2}) from the STPNT: label 1 is straight rolling at
    F* = 0.2 (STPNT read the run's PAR; it had returned the F* = 1 state),
    by PAR name or PAR index, and an impossible load is refused in one line."""
    script = demo / "start.py"
    script.write_text(
        "import numpy\n"
        "if 'bool' not in vars(numpy): numpy.bool = numpy.bool_\n"
        "for par in ({'Fstar': 0.2, 'V': 300.0}, {2: 0.5}):\n"
        "    s = run(e='mlg', c='mlg', PAR=par, ICP=['V'], NMX=2)(1)\n"
        "    print('START', s['V'], s['Fstar'], *[float(s[n][0]) for n in s.coordnames])\n")
    status, out = in_demo(demo, "auto start.py")
    starts = [[float(x) for x in line.split()[1:]] for line in out.splitlines()
              if line.startswith("START")]
    assert len(starts) == 2, out
    for V, Fstar, *u in starts:
        model = mlgmodel.Model("figures", V=V, Fstar=Fstar)
        expected = model.equilibrium()
        assert u == pytest.approx([expected[n] for n in mlgmodel.UNAMES], abs=1e-9)
        assert max(abs(model.rhs(u))) < 1e-8
    assert starts[0][:2] == [300.0, 0.2] and starts[1][:2] == [50.0, 0.5]
    assert starts[0][2 + mlgmodel.UNAMES.index("eta")] == pytest.approx(0.27013, abs=1e-5)
    script.write_text("run(e='mlg', c='mlg', PAR={'Fstar': -1.0}, ICP=['V'], NMX=2)\n")
    status, out = in_demo(demo, "auto start.py")
    assert "mlg: invalid starting parameters: " in out and "Fstar" in out, out
