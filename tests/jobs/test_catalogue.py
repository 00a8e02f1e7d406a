"""One declaration per figure and study (DECLARED in its module), read by
shared.jobs.catalogue without importing anything: a figure added as its
module and its docs section is seen by make, make help, the report and
make submit; a declaration that cannot be read is refused naming its file.

Run: /usr/bin/python3 -m pytest -q tests/jobs/test_catalogue.py
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

import helpers

ROOT = pathlib.Path(helpers.ROOT)
sys.path.insert(0, str(ROOT / "drivers" / "mlgshimmy" / "shared" / "jobs"))
import catalogue  # noqa: E402  (a file of the standard library only, as make runs it)

THROWAWAY = '''"""Fig. 99: a throwaway figure, added by tests/jobs/test_catalogue.py."""
from mlgshimmy.shared import jobs

DECLARED = {
    "fig99": {
        "help": "Fig. 99: a throwaway figure",
        "time": "1 s",
        "report": "A figure that only a test adds.",
    },
}


def compute():
    return {"x": 1}


def plot(result):
    print(f"fig99: x = {result['x']}")


if __name__ == "__main__":
    jobs.run_figure("fig99", compute, plot)
'''
# what the copy needs built to run `make report` and `make submit-<fig>` without
# compiling again (their times kept: make finds them up to date)
BUILT = ["lib", "obj", "models", "bin", "auto-link", "auto-dir", ".stamp-packages",
         ".packages-list"]


def make(tree, *args):
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES", "MLG_RUN_ROOT",
                        "MLG_BASE_RUN_ROOT")}
    env["AUTO_DIR"] = helpers.make_variable("AUTO_DIR")   # the tree's AUTO, built or chosen
    proc = subprocess.run(["make", "--no-print-directory", *args], cwd=tree, env=env,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, f"make {' '.join(args)}:\n{proc.stdout}\n{proc.stderr}"
    return proc.stdout


@pytest.fixture(scope="module")
def tree(tmp_path_factory):
    """A copy of the repository with fig99 added as two files: its module and
    its docs section."""
    tree = tmp_path_factory.mktemp("catalogue") / "tree"
    shutil.copytree(ROOT, tree, ignore=shutil.ignore_patterns("build", ".git"))
    for name in BUILT:
        source = ROOT / "build" / name
        if source.is_dir():
            shutil.copytree(source, tree / "build" / name, symlinks=True)
        elif source.exists():
            shutil.copy2(source, tree / "build" / name)
    (tree / "drivers" / "mlgshimmy" / "figures" / "fig99.py").write_text(THROWAWAY)
    with open(tree / "docs" / "reproduction.md", "a") as docs:
        docs.write("\n## Fig. 99 - a throwaway figure\n\nAdded by a test.\n")
    return tree


def test_make_and_help_see_a_new_figure(tree):
    line = re.search(r"^  fig99 +1 s  Fig\. 99: a throwaway figure$", make(tree, "help"), re.M)
    assert line, "make help does not list fig99"
    dry = make(tree, "-n", "fig99")
    assert "-m mlgshimmy.figures.fig99  --compute" in dry and \
        "-m mlgshimmy.figures.fig99  --plot" in dry, dry
    figures = make(tree, "--eval=print-figures: ; @echo $(FIGURES)", "print-figures").split()
    assert "fig99" in figures and "fig07" in figures


def test_the_report_and_submit_see_a_new_figure(tree):
    drawn = make(tree, "fig99")
    assert drawn.count("fig99: x = 1") == 1, drawn   # drawn once, by the job that computed it
    make(tree, "report")
    page = (tree / "build" / "report" / "index.html").read_text()
    assert 'id="fig99"' in page and "A figure that only a test adds." in page
    out = make(tree, "submit-fig99", "SUBMIT_ARGS=--dry-run")
    assert "--name fig99 --stage -" in out and "AUTO_THREADS=1 fig99" in out, out
    assert "sbatch --parsable -J fig99-s1 --array=1" in out, out


def test_a_removed_figure_leaves_the_catalogue(tree):
    module = tree / "drivers" / "mlgshimmy" / "figures" / "fig99.py"
    text = module.read_text()
    module.unlink()
    try:
        assert "fig99" not in make(tree, "help")
    finally:
        module.write_text(text)


def test_every_figure_and_study_declares_itself():
    declared = {e["module"] for e in catalogue.entries()}
    for room in catalogue.ROOMS:
        for name in catalogue.modules(room):
            assert f"{room}.{name}" in declared, f"{room}/{name} has no DECLARED"


@pytest.mark.parametrize("entry, message", [
    ('{"fig98": {"help": "x", "time": "1 s", "report": "x", "colour": 1}}',
     "fig98: unknown key 'colour'"),
    ('{"fig98": {"help": "x", "time": "soon", "report": "x"}}', "fig98: time 'soon'"),
    ('{"fig98": {"time": "1 s", "report": "x"}}', "fig98: 'help' is missing"),
    ('{"fig98": {"help": "x", "time": "1 s", "report": "x", "needs": ["gpu"]}}',
     "needs 'gpu'"),
    ('{"fig98": {"help": "x", "time": "1 s", "report": "x", "after": ["fig97"]}}',
     "after 'fig97', which nothing declares"),
    ('{"fig98": {"help": HELP, "time": "1 s", "report": "x"}}', "literals only"),
])
def test_a_bad_declaration_is_refused_naming_its_file(tmp_path, entry, message):
    for room in catalogue.ROOMS:
        (tmp_path / room).mkdir()
    module = tmp_path / "figures" / "fig98.py"
    module.write_text(f"DECLARED = {entry}\n")
    with pytest.raises(catalogue.DeclarationError) as caught:
        catalogue.entries(str(tmp_path))
    assert str(module) in str(caught.value) and message in str(caught.value), caught.value
