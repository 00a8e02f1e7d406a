"""The driver layer's structure and its cache: figure modules import only the
shared layer, the layer's AUTO-free modules stay AUTO-free, and a cached
result reads back as the AUTO branches it was made from."""
import ast
import glob
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DRIVERS = os.path.join(os.path.dirname(HERE), "drivers")
sys.path.insert(0, HERE)
sys.path.insert(0, DRIVERS)
from check import check  # noqa: E402

FIGURE_MODULE = re.compile(r"fig\d\d$")


def imports(path):
    """The top-level names of every module a file imports."""
    tree = ast.parse(open(path).read())
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module.split(".")[0])
    return names


def no_figure_imports_a_figure():
    for path in sorted(glob.glob(os.path.join(DRIVERS, "*.py"))):
        figures = sorted(n for n in imports(path) if FIGURE_MODULE.match(n))
        check(f"{os.path.basename(path)} imports no figure module", not figures, str(figures))


def auto_free(module):
    """Whether importing drivers/<module>.py loads neither AUTO nor autoglue
    (run in a fresh interpreter, with AUTO_DIR pointing nowhere)."""
    code = (f"import sys; sys.path.insert(0, {DRIVERS!r}); import {module}; "
            "bad = [m for m in ('auto', 'autoglue') if m in sys.modules]; "
            "print(' '.join(bad)); sys.exit(1 if bad else 0)")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(os.environ, AUTO_DIR="/nonexistent", MPLBACKEND="Agg"))
    return proc.returncode == 0, (proc.stdout + proc.stderr).strip()[-300:]


def layer_without_auto():
    for module in ("paths", "branches", "spectrum", "plotting", "results", "simulator",
                   "surfaces", "paper_table", "freeplay_profile", "fig06", "fig15", "fig19",
                   "liftoff"):
        ok, detail = auto_free(module)
        check(f"{module} imports no AUTO", ok, detail)


def cache_round_trip():
    """A stored branch reads back with the same columns, stability and
    labels as AUTO's own reading of the b-file; the cache file is written
    atomically (no partial file left) and a missing result names its make
    target."""
    os.environ.setdefault("AUTO_DIR", os.path.join(os.path.dirname(HERE), "build", "auto", "07p"))
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["MLG_RUN_ROOT"] = tmp
        from mlgshimmy.shared import autoglue
        from mlgshimmy.shared import branches
        import numpy
        from mlgshimmy.shared import jobs
        reference = os.path.join(os.path.dirname(HERE), "tests", "reference", "fig13", "y1_orbits",
                                 "b.y1_po0")
        bd = autoglue.init().parseB.parseBR(reference)
        path = jobs.write("test", {"orbits": jobs.stored(bd, ("V", "psi_amp", "T")),
                                      "inf": numpy.inf})
        check("cache: no partial file left beside the result",
              os.listdir(os.path.dirname(path)) == ["result.json"],
              str(os.listdir(os.path.dirname(path))))
        data = jobs.read("test")
        back = jobs.loaded(data["orbits"])
        same = all(numpy.array_equal(numpy.asarray(a[c]), b[c]) for a, b in zip(bd, back)
                   for c in ("V", "psi_amp", "T"))
        check("cache: columns read back exactly", len(back) == len(bd) and same)
        check("cache: stability read back", all(
            numpy.array_equal(branches.stable_mask(a), branches.stable_mask(b))
            for a, b in zip(bd, back)))
        check("cache: labelled points read back", all(
            branches.labelled_points(a) == branches.labelled_points(b) for a, b in zip(bd, back)),
            str(branches.labelled_points(back[0])))
        check("cache: infinity kept", data["inf"] == numpy.inf, str(data["inf"]))
        try:
            jobs.read("fig99")
            check("cache: a missing result is an error naming `make fig99`", False, "no error")
        except jobs.MissingResult as exc:
            check("cache: a missing result is an error naming `make fig99`",
                  "make fig99" in str(exc), str(exc))


def parts_in_stages():
    """Parts that need others: their stage, the make rules that run them
    after what they need (drivers/parts.mk, dry run), a single part's run
    that refuses to compute a part it needs, a cycle refused by name."""
    from mlgshimmy.shared import jobs
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["MLG_RUN_ROOT"] = tmp
        from mlgshimmy.shared import paths
        paths.RUN_ROOT = tmp
        jobs = {"a": lambda: 1, "b": lambda: 2,
                "sum": jobs.Needs(["a", "b"], lambda p: p["a"] + p["b"]),
                "twice": jobs.Needs(["sum"], lambda p: 2 * p["sum"])}
        parts = jobs.Parts("toy", jobs, "figures")
        check("parts: stages 1, 1, 2, 3", [parts.stage(n) for n in jobs] == [1, 1, 2, 3],
              str([parts.stage(n) for n in jobs]))
        check("parts: stage 2 lists the part that needs stage 1 only", parts.of_stage(2) == ["sum"])
        rules = os.path.join(tmp, "toy", "parts.mk")
        os.makedirs(os.path.dirname(rules))
        with open(rules, "w") as out:
            out.write(parts.make_rules())
        proc = subprocess.run(["make", "-n", "-j1", "-f", "drivers/parts.mk", "FIGURE=toy",
                               f"MLG_RUN_ROOT={tmp}", "INPUTS="], cwd=os.path.dirname(HERE),
                              capture_output=True, text=True)
        order = re.findall(r"--part (\w+)", proc.stdout)
        check("parts.mk: every part, each after the parts it needs (make -n)",
              order == ["a", "b", "sum", "twice"], proc.stdout + proc.stderr)
        try:
            parts.compute("sum", alone=True)
            check("parts: a single part's run refuses to compute a part it needs", False)
        except jobs.MissingResult as exc:
            check("parts: a single part's run refuses to compute a part it needs, naming it",
                  "part a is not cached" in str(exc) and "stage 1" in str(exc), str(exc))
        parts.compute("twice")   # the serial assembly computes what is missing
        check("parts: computed in order when assembling", jobs.read("toy", "twice") == 6)
        try:
            jobs.Parts("toy", {"x": jobs.Needs(["x"], lambda p: 0)}, "figures")
            check("parts: a part that needs itself is refused", False)
        except ValueError as exc:
            check("parts: a part that needs itself is refused", "needs itself" in str(exc),
                  str(exc))


def auto_threads():
    """AUTO's thread count comes from MLG_AUTO_THREADS (1 unless set), never
    from an inherited OMP_NUM_THREADS; a bad value is refused by name."""
    def threads(**env):
        code = (f"import sys, os; sys.path.insert(0, {DRIVERS!r}); import autoglue; "
                "print(os.environ['OMP_NUM_THREADS'])")
        base = {k: v for k, v in os.environ.items() if k != "MLG_AUTO_THREADS"}
        proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                              env=dict(base, MPLBACKEND="Agg", **env))
        return (proc.stdout + proc.stderr).strip()
    out = threads(OMP_NUM_THREADS="4")
    check("AUTO threads: an inherited OMP_NUM_THREADS=4 is not used (1)", out == "1", out)
    out = threads(OMP_NUM_THREADS="4", MLG_AUTO_THREADS="2")
    check("AUTO threads: MLG_AUTO_THREADS=2 is used", out == "2", out)
    out = threads(MLG_AUTO_THREADS="two")
    check("AUTO threads: MLG_AUTO_THREADS=two is refused by name",
          "MLG_AUTO_THREADS='two'" in out, out)


def main():
    no_figure_imports_a_figure()
    layer_without_auto()
    cache_round_trip()
    parts_in_stages()
    auto_threads()


if __name__ == "__main__":
    main()
