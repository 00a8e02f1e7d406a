"""mk/build-auto.sh on a fresh machine, with a stubbed apt-get on PATH: the
Debian diff (.debian.tar.xz) missing from the mirror made apt print
`E: Failed to fetch ... 404` and the build `apt-get source exited non-zero`,
which read as fatal though the build goes on (it needs only the .dsc and the
.orig tarball, whose sha256 it checks).  Nothing is downloaded here."""
import hashlib
import os
import stat
import subprocess
import tarfile

import pytest

import helpers

ROOT = helpers.ROOT
SCRIPT = os.path.join(ROOT, "mk", "build-auto.sh")
SOURCES = "/etc/apt/sources.list.d/mlg-shimmy-src.sources"
ORIG, DSC = "auto-07p_0.9.2+dfsg.orig.tar.gz", "auto-07p_0.9.2+dfsg-3.dsc"
FAILED = ("E: Failed to fetch http://deb.debian.org/debian/pool/main/a/auto-07p/"
          "auto-07p_0.9.2+dfsg-3.debian.tar.xz  404  Not Found [IP: 151.101.2.132 80]")

if os.geteuid() != 0 or not os.path.exists(SOURCES):
    pytest.skip(f"build-auto.sh needs root and writes {SOURCES} when missing: not here",
                allow_module_level=True)


def stubbed(tmp_path, arrives):
    """A PATH whose apt-get `source` writes the .dsc and .orig (if arrives)
    and fails on the Debian diff as the mirror did."""
    files = tmp_path / "files"
    files.mkdir()
    tree = tmp_path / "tree" / "auto" / "07p"     # no configure: the build stops at it
    tree.mkdir(parents=True)
    (tree / "README").write_text("not AUTO\n")
    with tarfile.open(files / ORIG, "w:gz") as tar:
        tar.add(tmp_path / "tree" / "auto", arcname="auto")
    digest = hashlib.sha256((files / ORIG).read_bytes()).hexdigest()
    (files / DSC).write_text(f"Source: auto-07p\nChecksums-Sha256:\n {digest} "
                             f"{(files / ORIG).stat().st_size} {ORIG}\n")
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    copy = f"cp {files}/* . && " if arrives else ""
    (bin_dir / "apt-get").write_text(
        "#!/bin/sh\n"
        'if [ "$1" = update ]; then echo "Hit:1 http://deb.debian.org/debian bookworm InRelease"; '
        "exit 0; fi\n"
        f"{copy}echo '{FAILED}' >&2; exit 100\n")
    (bin_dir / "apt-get").chmod(stat.S_IRWXU)
    return dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}")


def build(tmp_path, env):
    proc = subprocess.run(["bash", SCRIPT, str(tmp_path / "auto")], env=env,
                          stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)
    return proc, proc.stdout + proc.stderr


def test_a_missing_debian_diff_is_one_line_not_an_error(tmp_path):
    proc, out = build(tmp_path, stubbed(tmp_path, arrives=True))
    log = tmp_path / "auto" / "download" / "apt-get-source.log"
    assert ("build-auto: the .dsc and .orig tarball arrived, not all of the Debian source "
            "package (the Debian diff is not needed here; apt-get's output: "
            f"{log})") in out, out
    assert "E: Failed" not in out and "exited non-zero" not in out, out
    assert FAILED in log.read_text()
    assert f"build-auto: {ORIG} sha256 " in out and f"matches {DSC}" in out, out
    # the build goes on to unpack it (the stub's tree has no configure)
    assert proc.returncode != 0 and "build-auto: error: no configure script found in " \
        f"{tmp_path}/auto/download/{ORIG}" in proc.stderr, out


def test_apt_get_source_without_the_files_stops_the_build_showing_its_output(tmp_path):
    proc, out = build(tmp_path, stubbed(tmp_path, arrives=False))
    assert proc.returncode != 0
    assert FAILED in proc.stderr
    assert "build-auto: error: apt-get source auto-07p did not download the .dsc and .orig " \
        "tarball" in proc.stderr, out
