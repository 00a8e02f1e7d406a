"""The C library as installed: make install (PREFIX, DESTDIR), the SONAME,
pkg-config and the example program c/examples/evaluate.c built against the
installed copy (docs/c-library.md).

Run: /usr/bin/python3 -m pytest -q tests/release/test_c_library.py
"""
import os
import pathlib
import re
import subprocess

import helpers

ROOT = pathlib.Path(helpers.ROOT)


def header_version():
    """(MAJOR, MINOR, PATCH) from c/mlg_version.h, the one source."""
    text = (ROOT / "c" / "mlg_version.h").read_text()
    return tuple(int(re.search(rf"^#define MLG_VERSION_{part} +(\d+) *$", text, re.M).group(1))
                 for part in ("MAJOR", "MINOR", "PATCH"))


def run(args, **kw):
    proc = subprocess.run(args, cwd=kw.pop("cwd", ROOT), capture_output=True, text=True, **kw)
    assert proc.returncode == 0, f"{args}: exit {proc.returncode}\n{proc.stdout}\n{proc.stderr}"
    return proc.stdout


def readelf_dynamic(path):
    return run(["readelf", "-d", str(path)])


def test_build_tree_library_has_soname():
    """build/lib/libmlg.so (what the drivers load) is a symlink to the real
    libmlg.so.MAJOR.MINOR.PATCH, whose SONAME is libmlg.so.MAJOR."""
    major, minor, patch = header_version()
    run(["make", "-s", "--no-print-directory", "build/lib/libmlg.so"])
    lib = ROOT / "build" / "lib"
    real = f"libmlg.so.{major}.{minor}.{patch}"
    assert os.readlink(lib / "libmlg.so") == real
    assert os.readlink(lib / f"libmlg.so.{major}") == real
    assert f"Library soname: [libmlg.so.{major}]" in readelf_dynamic(lib / real)


def parse_example(output):
    """The numbers the example prints: version line, u*, max |f|, the
    Jacobian rows and the central-difference check per column."""
    state = dict(re.findall(r"^  (\w+) += +(\S+)$", output, re.M))
    fd = dict(re.findall(r"^  (\w+) +(\d\.\de[-+]\d+)", output, re.M))
    rows = {m.group(1): [float(x) for x in m.group(2).split()]
            for m in re.finditer(r"^  (\w+) +((?:[- ]\d\.\d{4}e[-+]\d+ *){10})$", output, re.M)}
    fmax = float(re.search(r"^max \|f\(u\*\)\| = (\S+)$", output, re.M).group(1))
    return {k: float(v) for k, v in state.items()}, {k: float(v) for k, v in fd.items()}, rows, fmax


def test_install_pkg_config_and_example(tmp_path):
    """make install DESTDIR=<tmp> PREFIX=/usr, then the example built with
    `pkg-config --cflags --libs mlg` (sysroot and search path in the
    DESTDIR only) links the installed shared library and prints the
    straight-rolling state and Jacobian of the `figures` set at F* = 1."""
    major, minor, patch = header_version()
    version = f"{major}.{minor}.{patch}"
    dest = tmp_path / "root"
    run(["make", "-s", "--no-print-directory", "install", f"DESTDIR={dest}", "PREFIX=/usr"])
    lib, include = dest / "usr" / "lib", dest / "usr" / "include" / "mlg"

    # layout: headers under their own directory, with names that cannot clash
    assert sorted(p.name for p in include.iterdir()) == [
        "mlg_model.h", "mlg_parameters.h", "mlg_version.h"]
    real = f"libmlg.so.{version}"
    assert (lib / real).is_file() and not (lib / real).is_symlink()
    assert os.readlink(lib / f"libmlg.so.{major}") == real
    assert os.readlink(lib / "libmlg.so") == real
    assert f"Library soname: [libmlg.so.{major}]" in readelf_dynamic(lib / real)
    assert "mlg_rhs_jacobian" in run(["nm", "--defined-only", str(lib / "libmlg.a")])

    env = dict(os.environ, PKG_CONFIG_SYSROOT_DIR=str(dest),
               PKG_CONFIG_LIBDIR=str(lib / "pkgconfig"), PKG_CONFIG_PATH="")
    assert run(["pkg-config", "--modversion", "mlg"], env=env).strip() == version
    flags = run(["pkg-config", "--cflags", "--libs", "mlg"], env=env).split()
    assert f"-I{include}" in flags and f"-L{lib}" in flags and "-lmlg" in flags

    example = tmp_path / "evaluate"
    run(["cc", "-std=c11", "-Wall", "-Wextra", "-Wpedantic", "-Werror",
         str(ROOT / "c" / "examples" / "evaluate.c"), *flags, "-o", str(example)], cwd=tmp_path)
    assert f"Shared library: [libmlg.so.{major}]" in readelf_dynamic(example)

    output = run([str(example)], cwd=tmp_path, env=dict(os.environ, LD_LIBRARY_PATH=str(lib)))
    assert output.startswith(f"mlg {version} (library {version})\n")
    state, fd, rows, fmax = parse_example(output)
    # straight rolling at F* = 1: beta*, eta* of docs/model.md 7 (4 digits,
    # half a unit of the last one; c_psi does not enter the equilibrium)
    assert abs(state["beta"] - (-0.00974)) <= 5e-6
    assert abs(state["eta"] - 0.3982) <= 5e-5
    assert all(state[k] == 0.0 for k in ("psi", "delta", "psi_dot", "delta_dot", "beta_dot",
                                         "eta_dot", "lambda_L", "lambda_R"))
    assert fmax <= 1e-10
    # Jacobian: the kinematic rows d(q)/dt = q_dot are exact identities, and
    # the even (beta, eta) and odd (psi, delta, lambda) blocks do not couple
    assert len(rows) == 10
    assert rows["psi"] == [0, 0, 0, 0, 1, 0, 0, 0, 0, 0]
    assert rows["eta"] == [0, 0, 0, 0, 0, 0, 0, 1, 0, 0]
    assert rows["psi_dot"][2] == rows["psi_dot"][3] == 0.0 and rows["psi_dot"][0] < 0
    assert rows["beta_dot"][0] == rows["beta_dot"][1] == 0.0
    # exact Jacobian against central differences: 1e-8 of each column's
    # largest entry, except eta_dot, where the damper's sign(eta') eta'^2
    # leaves a first-order difference (1.6e-5 at the example's step)
    assert len(fd) == 10
    assert all(v <= 1e-8 for k, v in fd.items() if k != "eta_dot"), fd
    assert fd["eta_dot"] <= 1e-4


def test_uninstall_removes_what_install_wrote(tmp_path):
    dest = tmp_path / "root"
    run(["make", "-s", "--no-print-directory", "install", f"DESTDIR={dest}", "PREFIX=/opt/mlg"])
    assert (dest / "opt" / "mlg" / "lib" / "pkgconfig" / "mlg.pc").is_file()
    run(["make", "-s", "--no-print-directory", "uninstall", f"DESTDIR={dest}", "PREFIX=/opt/mlg"])
    assert [p for p in dest.rglob("*") if p.is_file() or p.is_symlink()] == []


def make_install(*args):
    return subprocess.run(["make", "-s", "--no-print-directory", *args], cwd=ROOT,
                          capture_output=True, text=True)


def test_install_refuses_paths_that_leave_destdir(tmp_path):
    """A DESTDIR with a space (two words to make: once installed into both,
    and uninstall deleted the second's files), a relative PREFIX (installed
    into <DESTDIR>usr/local), a ".." or a shell character: refused before
    anything is written or deleted, naming the variable."""
    # the file that `uninstall DESTDIR="<tmp>/x/with <tmp>/y"` deleted
    kept = tmp_path / "y" / "usr" / "local" / "include" / "mlg" / "mlg_model.h"
    kept.parent.mkdir(parents=True)
    kept.write_text("not ours\n")
    cases = [(f"DESTDIR={tmp_path}/x/with {tmp_path}/y", "DESTDIR=", "contains a space"),
             (f"DESTDIR={tmp_path}/a;b", "DESTDIR=", "holds a character other than"),
             ("PREFIX=usr/local", "PREFIX='usr/local' must be an absolute path", ""),
             ("PREFIX=/usr/../../etc", "PREFIX='/usr/../../etc' has a \"..\" component", ""),
             ("LIBDIR=/usr/lib/a|b", "LIBDIR='/usr/lib/a|b' holds a character other than", "")]
    for goal in ("install", "uninstall"):
        for setting, named, why in cases:
            dest = [] if setting.startswith("DESTDIR=") else [f"DESTDIR={tmp_path}/stage"]
            proc = make_install(goal, setting, *dest)
            assert proc.returncode == 2 and named in proc.stderr and why in proc.stderr, \
                (goal, setting, proc.stderr)
    assert sorted(str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*")
                  if not p.is_dir()) == ["y/usr/local/include/mlg/mlg_model.h"]
    assert kept.read_text() == "not ours\n"
    assert not list(tmp_path.glob("stage*")) and not (tmp_path / "x").exists()
