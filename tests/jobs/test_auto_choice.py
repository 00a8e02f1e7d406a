"""Which AUTO-07p the Makefile uses (mk/auto.mk): an AUTO_DIR given once is
checked (mk/check-auto.sh) and remembered in build/auto-dir, so that a later
make without AUTO_DIR uses it instead of starting the source build; an
invalid one is refused and not remembered; make forget-auto returns to the
source build; make clean keeps the choice. Each test works in a scratch
copy of the Makefile and mk/ (the repository's build/ is not touched).

Run: /usr/bin/python3 -m pytest -q tests/jobs/test_auto_choice.py
"""
import os
import pathlib
import shutil
import subprocess

import pytest

import helpers

ROOT = pathlib.Path(helpers.ROOT)
DEBIAN_AUTO = pathlib.Path("/usr/lib/auto-07p")


def usable_auto():
    """An AUTO-07p on this machine to choose: the repository's source build
    or Debian's package (skip if neither)."""
    for candidate in (ROOT / "build" / "auto" / "07p", DEBIAN_AUTO):
        if (candidate / "python" / "auto" / "__init__.py").is_file():
            return candidate
    pytest.skip("no AUTO-07p built or installed")


@pytest.fixture
def tree(tmp_path):
    """A scratch copy of the sources, nothing built."""
    shutil.copytree(ROOT, tmp_path, dirs_exist_ok=True,
                    ignore=shutil.ignore_patterns("build", ".git", "__pycache__"))
    return tmp_path


def make(tree, *args):
    """make in `tree` as a user's shell would start it: no AUTO_DIR and no
    make of ours around it. (exit status, stdout + stderr)."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("AUTO_DIR", "MAKEFLAGS", "MAKELEVEL", "MFLAGS", "MAKEOVERRIDES")}
    proc = subprocess.run(["make", "--no-print-directory", *args], cwd=tree, env=env,
                          capture_output=True, text=True)
    return proc.returncode, proc.stdout + proc.stderr


def exported_auto_dir(tree):
    """AUTO_DIR as the Makefile exports it to recipes (drivers, tests)."""
    status, out = make(tree, "--eval=print-auto-dir: ; @echo \"AUTO_DIR=$$AUTO_DIR\"",
                       "print-auto-dir")
    assert status == 0, out
    return out.strip().splitlines()[-1].removeprefix("AUTO_DIR=")


def test_no_choice_builds_from_source_and_says_so(tree):
    status, out = make(tree, "-n", "auto")
    assert status == 0, out
    assert "mk/build-auto.sh build/auto" in out
    assert "building AUTO-07p from source under build/auto/" in out
    assert exported_auto_dir(tree) == str(tree / "build" / "auto" / "07p")


def test_given_auto_dir_is_remembered(tree):
    auto = usable_auto()
    status, out = make(tree, "auto", f"AUTO_DIR={auto}")
    assert status == 0, out
    assert "auto: using AUTO-07p" in out and f"at {auto}," in out
    assert "remembered AUTO_DIR=" in out
    assert (tree / "build" / "auto-dir").read_text() == f"{auto}\n"

    # later, without AUTO_DIR: the same AUTO, printed, and no source build
    status, out = make(tree, "auto")
    assert status == 0, out
    assert f"at {auto}," in out and "as remembered in build/auto-dir" in out
    status, out = make(tree, "-n", "auto")
    assert status == 0 and "build-auto.sh" not in out, out
    assert exported_auto_dir(tree) == str(auto)


def test_invalid_auto_dir_is_refused_and_not_remembered(tree):
    auto = usable_auto()
    assert make(tree, "auto", f"AUTO_DIR={auto}")[0] == 0
    status, out = make(tree, "auto", f"AUTO_DIR={tree}/nowhere")
    assert status != 0
    assert f"AUTO_DIR={tree}/nowhere: no such directory" in out
    status, out = make(tree, "auto", f"AUTO_DIR={tree}/mk")
    assert status != 0 and "not a built AUTO-07p (no python/auto/__init__.py)" in out
    assert (tree / "build" / "auto-dir").read_text() == f"{auto}\n"


def test_clean_keeps_the_choice_and_forget_drops_it(tree):
    auto = usable_auto()
    assert make(tree, "auto", f"AUTO_DIR={auto}")[0] == 0
    (tree / "build" / "junk").write_text("x")
    status, out = make(tree, "clean")
    assert status == 0, out
    assert sorted(p.name for p in (tree / "build").iterdir()) == ["auto-dir"]
    assert exported_auto_dir(tree) == str(auto)

    status, out = make(tree, "forget-auto")
    assert status == 0 and not (tree / "build" / "auto-dir").exists(), out
    status, out = make(tree, "-n", "auto")
    assert "mk/build-auto.sh build/auto" in out

    assert make(tree, "auto", f"AUTO_DIR={auto}")[0] == 0
    assert make(tree, "distclean")[0] == 0 and not (tree / "build").exists()


def test_source_build_path_given_forgets_the_choice(tree):
    auto = usable_auto()
    assert make(tree, "auto", f"AUTO_DIR={auto}")[0] == 0
    status, out = make(tree, "-n", "auto", "AUTO_DIR=build/auto/07p")
    assert "mk/build-auto.sh build/auto" in out and "rm -f build/auto-dir" in out


def test_switching_auto_marks_models_for_rebuild(tree):
    """build/auto-link/auto-dir, a prerequisite of every equations object
    and executable, changes (content and time) only when AUTO_DIR does."""
    stamp = tree / "build" / "auto-link" / "auto-dir"
    assert make(tree, "build/auto-link/auto-dir", "AUTO_DIR=/one")[0] == 0
    assert stamp.read_text() == "/one\n"
    before = stamp.stat().st_mtime_ns
    assert make(tree, "build/auto-link/auto-dir", "AUTO_DIR=/one")[0] == 0
    assert stamp.stat().st_mtime_ns == before
    assert make(tree, "build/auto-link/auto-dir", "AUTO_DIR=/two")[0] == 0
    assert stamp.read_text() == "/two\n"


@pytest.mark.skipif(not DEBIAN_AUTO.is_dir(), reason="Debian's auto-07p is not installed")
def test_debian_package_layout_is_accepted():
    """Debian 12's auto-07p: AUTO_DIR=/usr/lib/auto-07p, auto_f2c.h in /usr/include."""
    proc = subprocess.run([str(ROOT / "mk" / "check-auto.sh"), str(DEBIAN_AUTO)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert "(Debian package auto-07p) at /usr/lib/auto-07p, headers /usr/include/" in proc.stdout
