"""The driver layer's structure and its cache: the layer's AUTO-free
modules stay AUTO-free, a cached result reads back as the AUTO branches it
was made from, a figure's parts run in stages, and AUTO's thread count is
ours.  (That figures and studies import only the shared layer is
tests/jobs/test_rooms.py's.)"""
import os
import re
import subprocess
import sys

import numpy
import pytest

from mlgshimmy.shared import autosession
from mlgshimmy.shared import branches
from mlgshimmy.shared import jobs
from mlgshimmy.shared import paths

DRIVERS = os.path.join(paths.ROOT, "drivers")


def python(code, **env):
    """code run by a fresh interpreter with the package on its path."""
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(os.environ, PYTHONPATH=DRIVERS, MPLBACKEND="Agg", **env))


def auto_free(module):
    """Whether importing mlgshimmy.<module> loads neither AUTO nor autoglue
    (run in a fresh interpreter, with AUTO_DIR pointing nowhere)."""
    code = (f"import sys; import mlgshimmy.{module}; "
            "bad = [m for m in ('auto', 'mlgshimmy.shared.autoglue') if m in sys.modules]; "
            "print(' '.join(bad)); sys.exit(1 if bad else 0)")
    proc = python(code, AUTO_DIR="/nonexistent")
    return proc.returncode == 0, (proc.stdout + proc.stderr).strip()[-300:]


# the old flat modules plotting, results, paper_table and freeplay_profile
# are shared.draw, shared.jobs, shared.paper and shared.freeplay
@pytest.mark.parametrize("module", (
    "shared.paths", "shared.branches", "shared.spectrum", "shared.draw", "shared.jobs",
    "shared.simulator", "shared.surfaces", "shared.paper", "shared.freeplay", "figures.fig06",
    "figures.fig15", "figures.fig19", "shared.liftoff", "shared.lyapunov"))
def test_module_imports_no_auto(module):
    ok, detail = auto_free(module)
    assert ok, f"mlgshimmy.{module} imports AUTO or autoglue: {detail}"


def test_autoglue_import_loads_no_auto_and_init_names_a_missing_one():
    """Importing autoglue (and continuation, which runs AUTO) does nothing
    to the process; init() then says where it looked for AUTO."""
    code = ("import sys; from mlgshimmy.shared import autosession, continuation; "
            "assert 'auto' not in sys.modules, 'auto imported'; autosession.init()")
    proc = python(code, AUTO_DIR="/nonexistent")
    assert proc.returncode != 0 and "AutoMissing" in proc.stderr \
        and "AUTO_DIR=/nonexistent" in proc.stderr, proc.stderr[-400:]


REFERENCE = os.path.join(paths.ROOT, "tests", "reference", "fig13", "y1_orbits", "b.y1_po0")


@pytest.fixture
def run_root(tmp_path, monkeypatch):
    monkeypatch.setenv("MLG_RUN_ROOT", str(tmp_path))
    return tmp_path


@pytest.fixture
def cached(run_root):
    """A reference diagram as AUTO reads it, written to the cache and read
    back: (diagram, path written, data read, branches loaded)."""
    bd = autosession.init().parseB.parseBR(REFERENCE)
    path = jobs.write("test", {"orbits": jobs.stored(bd, ("V", "psi_amp", "T")),
                               "inf": numpy.inf})
    data = jobs.read("test")
    return bd, path, data, jobs.loaded(data["orbits"])


def test_cache_leaves_no_partial_file_beside_the_result(cached):
    _, path, _, _ = cached
    assert os.listdir(os.path.dirname(path)) == ["result.json"], os.listdir(os.path.dirname(path))


def test_cache_reads_back_columns_stability_labels_and_infinity(cached):
    """A stored branch reads back with the same columns, stability and
    labels as AUTO's own reading of the b-file; infinity is kept."""
    bd, _, data, back = cached
    same = all(numpy.array_equal(numpy.asarray(a[c]), b[c]) for a, b in zip(bd, back)
               for c in ("V", "psi_amp", "T"))
    assert len(back) == len(bd) and same, "columns not read back exactly"
    assert all(numpy.array_equal(branches.stable_mask(a), branches.stable_mask(b))
               for a, b in zip(bd, back)), "stability not read back"
    assert all(branches.labelled_points(a) == branches.labelled_points(b)
               for a, b in zip(bd, back)), str(branches.labelled_points(back[0]))
    assert data["inf"] == numpy.inf, str(data["inf"])


def test_cache_missing_result_names_its_make_target(run_root):
    with pytest.raises(jobs.MissingResult) as error:
        jobs.read("fig99")
    assert "make fig99" in str(error.value), str(error.value)


@pytest.fixture
def toy(run_root):
    """Parts that need others: a and b (stage 1), sum (2), twice (3)."""
    work = {"a": lambda: 1, "b": lambda: 2,
            "sum": jobs.Needs(["a", "b"], lambda p: p["a"] + p["b"]),
            "twice": jobs.Needs(["sum"], lambda p: 2 * p["sum"])}
    return jobs.Parts("toy", work, "figures")


def test_parts_stages(toy):
    stages = [toy.stage(n) for n in toy.jobs]
    assert stages == [1, 1, 2, 3], stages
    assert toy.of_stage(2) == ["sum"], "stage 2 does not list the part that needs stage 1 only"


def test_parts_make_rules_run_each_part_after_what_it_needs(toy, run_root):
    """mk/parts.mk on the parts' rules (make -n): every part, each after
    the parts it needs."""
    rules = run_root / "toy" / "parts.mk"
    rules.parent.mkdir()
    rules.write_text(toy.make_rules())
    proc = subprocess.run(["make", "-n", "-j1", "-f", "mk/parts.mk", "FIGURE=toy",
                           f"MLG_RUN_ROOT={run_root}", "INPUTS="], cwd=paths.ROOT,
                          capture_output=True, text=True)
    order = re.findall(r"--part (\w+)", proc.stdout)
    assert order == ["a", "b", "sum", "twice"], proc.stdout + proc.stderr


def test_parts_after_waits_for_parts_it_does_not_read(run_root):
    """A part with `after` (jobs.Needs) is a later stage and an order-only
    prerequisite in mk/parts.mk: listed first, it still runs after them."""
    work = {"short": jobs.Needs((), lambda _: 1, after=["input"]), "input": lambda: 2,
            "chain": jobs.Needs(["input"], lambda p: p["input"])}
    parts = jobs.Parts("toy", work, "figures")
    assert [parts.stage(n) for n in work] == [2, 1, 2]
    rules = run_root / "toy" / "parts.mk"
    rules.parent.mkdir()
    rules.write_text(parts.make_rules())
    assert f"short.json: | {run_root}/toy/parts/input.json" in rules.read_text()
    proc = subprocess.run(["make", "-n", "-j1", "-f", "mk/parts.mk", "FIGURE=toy",
                           f"MLG_RUN_ROOT={run_root}", "INPUTS="], cwd=paths.ROOT,
                          capture_output=True, text=True)
    assert re.findall(r"--part (\w+)", proc.stdout) == ["input", "short", "chain"], \
        proc.stdout + proc.stderr
    parts.compute("short")   # the serial assembly: nothing to read
    assert jobs.read("toy", "short") == 1


def test_parts_a_single_parts_run_refuses_to_compute_a_part_it_needs(toy):
    with pytest.raises(jobs.MissingResult) as error:
        toy.compute("sum", alone=True)
    assert "part a is not cached" in str(error.value) and "stage 1" in str(error.value), \
        str(error.value)


def test_parts_computed_in_order_when_assembling(toy):
    toy.compute("twice")   # the serial assembly computes what is missing
    assert jobs.read("toy", "twice") == 6


def test_parts_a_part_that_needs_itself_is_refused(run_root):
    with pytest.raises(ValueError) as error:
        jobs.Parts("toy", {"x": jobs.Needs(["x"], lambda p: 0)}, "figures")
    assert "needs itself" in str(error.value), str(error.value)


def auto_threads(**env):
    """OMP_NUM_THREADS once autoglue has found AUTO (or the error)."""
    code = ("import os; from mlgshimmy.shared import autosession; autosession.init(); "
            "print(os.environ['OMP_NUM_THREADS'])")
    base = {k: v for k, v in os.environ.items() if k != "MLG_AUTO_THREADS"}
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(base, PYTHONPATH=DRIVERS, MPLBACKEND="Agg", **env))
    return (proc.stdout + proc.stderr).strip()


def test_auto_threads_not_inherited_from_omp_num_threads():
    """AUTO's thread count comes from MLG_AUTO_THREADS (1 unless set), never
    from an inherited OMP_NUM_THREADS."""
    out = auto_threads(OMP_NUM_THREADS="4")
    assert out == "1", out


def test_auto_threads_from_mlg_auto_threads():
    out = auto_threads(OMP_NUM_THREADS="4", MLG_AUTO_THREADS="2")
    assert out == "2", out


def test_auto_threads_bad_value_refused_by_name():
    out = auto_threads(MLG_AUTO_THREADS="two")
    assert "MLG_AUTO_THREADS='two'" in out, out
