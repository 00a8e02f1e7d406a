"""What make knows about the drivers: a dry run needs nothing built, a
result depends on every file its driver imports (the generated import
closure), a redraw needs no AUTO, the model without its library says what
to build, and a result is never left half-written."""
import json
import os
import shutil
import subprocess
import sys

import pytest

from mlgshimmy.shared import jobs, paths

ROOT = paths.ROOT
OLD = ["-o", "build/models/mlg.exe", "-o", "build/lib/libmlg.so", "-o", "build/bin/mlg_simulate",
       "-o", "build/.stamp-auto", "-o", "build/.stamp-packages"]


def make(clone, *args):
    proc = subprocess.run(["make", "--no-print-directory", *args], cwd=clone, capture_output=True,
                          text=True, env={k: v for k, v in os.environ.items()
                                          if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL",
                                                       "MLG_RUN_ROOT")})
    return proc


@pytest.fixture(scope="module")
def clone(tmp_path_factory):
    """This checkout's sources as a fresh clone has them: nothing built."""
    path = tmp_path_factory.mktemp("clone") / "repo"
    shutil.copytree(ROOT, path, ignore=shutil.ignore_patterns("build", ".git", "__pycache__"))
    return path


def test_dry_runs_in_a_fresh_clone(clone):
    for goal in ("figures", "regress"):
        proc = make(clone, "-n", goal)
        assert proc.returncode == 0, f"make -n {goal}: {proc.stderr[-3000:]}"
        assert "mlgshimmy.figures.fig11 --part large" in proc.stdout
    assert not os.path.exists(clone / "build" / "lib" / "libmlg.so")


def compute_lines(proc):
    return sorted(line.split()[2].rsplit(".", 1)[1] for line in proc.stdout.splitlines()
                  if line.endswith("--compute") and "mlgshimmy.figures." in line)


def test_a_result_depends_on_its_import_closure(clone):
    figures = ["fig07", "fig13", "fig14", "fig16", "fig18"]
    make(clone, "-n", *OLD, *figures)           # writes the .d files
    for fig in figures:
        os.makedirs(clone / "build" / fig, exist_ok=True)
        (clone / "build" / fig / "result.json").write_text("{}")
    proc = make(clone, "-n", *OLD, *figures)
    assert compute_lines(proc) == [], proc.stdout
    profile = clone / "drivers" / "mlgshimmy" / "shared" / "freeplay.py"
    os.utime(profile, None)
    proc = make(clone, "-n", *OLD, *figures)
    assert compute_lines(proc) == ["fig13", "fig14", "fig16", "fig18"], proc.stdout
    # a module imported only inside a function counts too: fig07 draws
    # with shared.draw, imported where the figure is plotted
    for fig in figures:
        (clone / "build" / fig / "result.json").write_text("{}")
    os.utime(clone / "drivers" / "mlgshimmy" / "shared" / "draw" / "__init__.py", None)
    assert "fig07" in compute_lines(make(clone, "-n", *OLD, *figures))


def test_the_model_without_its_library_says_what_to_build():
    code = ("from mlgshimmy.shared import mlgmodel; mlgmodel.LIBRARY = '/nonexistent/libmlg.so'\n"
            "try:\n    mlgmodel.Model('figures')\nexcept mlgmodel.LibraryMissing as exc:\n"
            "    print(exc)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert "make build/lib/libmlg.so" in out and "/nonexistent/libmlg.so" in out


def test_importing_the_drivers_changes_nothing():
    """No import runs AUTO, reads the library, rewrites the environment or
    exits: every module of the package imports with AUTO_DIR pointing
    nowhere and no library."""
    code = ("import importlib, os, pkgutil, sys, mlgshimmy\n"
            "from mlgshimmy.shared import mlgmodel\n"
            "mlgmodel.LIBRARY = '/nonexistent'\n"
            "before = dict(os.environ)\n"
            "for m in pkgutil.walk_packages(mlgshimmy.__path__, 'mlgshimmy.'):\n"
            "    if not m.name.endswith('__main__'):\n"
            "        importlib.import_module(m.name)\n"
            "print(sorted(k for k in set(before) | set(os.environ) if before.get(k) != os.environ.get(k)),"
            " 'auto' in sys.modules, mlgmodel._lib is None)\n")
    env = dict(os.environ, AUTO_DIR="/nonexistent")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["[]", "False", "True"]


def test_a_redraw_needs_no_auto(tmp_path):
    """fig07 computed (with AUTO), then redrawn with AUTO_DIR pointing
    nowhere: the plot step never loads AUTO."""
    env = dict(os.environ, MLG_RUN_ROOT=str(tmp_path), MPLBACKEND="Agg")
    subprocess.run([sys.executable, "-m", "mlgshimmy.figures.fig07", "--compute"], env=env,
                   check=True, capture_output=True)
    code = ("import runpy, sys; sys.argv = ['fig07', '--plot']\n"
            "runpy.run_module('mlgshimmy.figures.fig07', run_name='__main__')\n"
            "assert 'auto' not in sys.modules, 'AUTO was imported'\n")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(env, AUTO_DIR="/nonexistent"))
    assert proc.returncode == 0, proc.stderr
    assert os.path.getsize(tmp_path / "figures" / "fig07.png") > 10000


def test_a_result_killed_while_written_is_not_left(tmp_path, monkeypatch):
    """cache.write interrupted halfway through the JSON: no result.json, no
    temporary file; the old result, if any, stays whole."""
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    jobs.write("figX", {"value": 1.0})
    real_dump = json.dump

    def dump_then_die(data, out, **kw):
        out.write(json.dumps(data)[:20])
        raise KeyboardInterrupt
    monkeypatch.setattr(json, "dump", dump_then_die)
    with pytest.raises(KeyboardInterrupt):
        jobs.write("figX", {"value": 2.0})
    monkeypatch.setattr(json, "dump", real_dump)
    assert jobs.read("figX") == {"value": 1.0}
    assert sorted(os.listdir(tmp_path / "figX")) == ["result.json"]


def test_make_deletes_a_target_whose_recipe_failed():
    proc = subprocess.run(["make", "-pn", "-f", os.path.join(ROOT, "Makefile"), "help"],
                          cwd=ROOT, capture_output=True, text=True)
    assert "\n.DELETE_ON_ERROR:" in proc.stdout


def test_a_result_depends_on_the_thread_count(clone):
    """A result made with one AUTO thread count is out of date for another
    (the stamp build/auto-link/auto-threads, written by a make that may
    build); a dry run says so but writes no stamp, so the next plain make
    does not redo every result."""
    stamp = clone / "build" / "auto-link" / "auto-threads"
    stamp.parent.mkdir(parents=True, exist_ok=True)
    stamp.write_text("1")                   # as a make with AUTO_THREADS=1 left it
    os.makedirs(clone / "build" / "fig07", exist_ok=True)
    (clone / "build" / "fig07" / "result.json").write_text("{}")
    before = stamp.stat().st_mtime_ns
    assert compute_lines(make(clone, "-n", *OLD, "fig07", "AUTO_THREADS=1")) == []
    for _ in range(2):
        assert compute_lines(make(clone, "-n", *OLD, "fig07", "AUTO_THREADS=2")) == ["fig07"]
    assert stamp.read_text() == "1" and stamp.stat().st_mtime_ns == before, \
        "a dry run rewrote the thread-count stamp"
    assert compute_lines(make(clone, "-n", *OLD, "fig07", "AUTO_THREADS=1")) == []


def test_a_package_added_to_the_list_reinstalls(clone):
    """The package list is a stamp: one package more than the stamp holds
    is a change (the stamp compared word by word both ways), which a dry
    run lists without rewriting the stamp."""
    listed = make(clone, "-n", "-p", "help").stdout
    packages = next(line.split(":=", 1)[1].split() for line in listed.splitlines()
                    if line.startswith("PACKAGES :="))
    stamp, installed = clone / "build" / ".packages-list", clone / "build" / ".stamp-packages"
    stamp.parent.mkdir(parents=True, exist_ok=True)
    stamp.write_text(" ".join(packages[:-1]))
    installed.write_text("")
    os.utime(installed, (stamp.stat().st_mtime + 10,) * 2)
    assert "mk/install-packages.sh" in make(clone, "-n", "packages").stdout
    assert stamp.read_text() == " ".join(packages[:-1]), "a dry run rewrote the package list"
    stamp.write_text(" ".join(packages))
    os.utime(installed, (stamp.stat().st_mtime + 10,) * 2)
    assert "mk/install-packages.sh" not in make(clone, "-n", "packages").stdout


def test_make_gear_makes_every_figure_unless_asked_for_the_answers(clone):
    """make gear's first step makes GEAR_FIGURES at the paper's gear: every
    figure by default, the three the design answers read with
    GEAR_FIGURES=answers; a name that is no figure stops it, named."""
    def figures_made(*args):
        proc = make(clone, "-n", "gear", "RHO=20", "MU=5", *args)
        assert proc.returncode == 0, proc.stderr[-2000:]
        line = next(line for line in proc.stdout.splitlines() if "RHO= MU= EOM= SET=" in line)
        return line.split("SET= ", 1)[1].split()
    every = figures_made()
    assert {"fig06", "fig10", "fig11", "fig19", "criterion"} <= set(every) and len(every) == 17, \
        every
    assert figures_made("GEAR_FIGURES=answers") == ["fig07", "fig10", "fig18"]
    proc = make(clone, "-n", "gear", "RHO=20", "MU=5", "GEAR_FIGURES=fig07 fig99;true")
    assert proc.returncode != 0 and "GEAR_FIGURES: not a figure: fig99;true" in proc.stderr, \
        proc.stderr[-2000:]


def test_make_gear_makes_the_laws_study_at_the_gear_unless_told_otherwise(clone):
    """GEAR_STUDIES (default laws) is made at the gear after its figures;
    GEAR_STUDIES= makes none; a study not made at a gear stops it, named."""
    def at_gear(*args):
        proc = make(clone, "-n", "gear", "RHO=20", "MU=5", "GEAR_FIGURES=fig07", *args)
        assert proc.returncode == 0, proc.stderr[-2000:]
        return next(line for line in proc.stdout.splitlines()
                    if line.startswith("make --no-print-directory fig07")).split()[2:]
    assert at_gear() == ["fig07", "laws"]
    assert at_gear("GEAR_STUDIES=") == ["fig07"]
    assert at_gear("GEAR_STUDIES=laws atlas") == ["fig07", "laws", "atlas"]
    proc = make(clone, "-n", "gear", "RHO=20", "MU=5", "GEAR_STUDIES=atlass;true")
    assert proc.returncode != 0 and \
        "GEAR_STUDIES: not a study made at a gear: atlass;true" in proc.stderr, proc.stderr[-2000:]
