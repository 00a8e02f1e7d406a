"""LICENSE and CITATION.cff: present, and the software version they state
is the one of c/mlg_version.h (the one source of the version).

Run: /usr/bin/python3 -m pytest -q tests/release/test_release_files.py
"""
import pathlib
import re

import pytest

import helpers

ROOT = pathlib.Path(helpers.ROOT)


def header_version():
    text = (ROOT / "c" / "mlg_version.h").read_text()
    return ".".join(re.search(rf"^#define MLG_VERSION_{p} +(\d+) *$", text, re.M).group(1)
                    for p in ("MAJOR", "MINOR", "PATCH"))


def test_license_is_bsd_3_clause_like_auto():
    text = (ROOT / "LICENSE").read_text()
    assert text.startswith("BSD 3-Clause License\n")
    assert "Neither the name of the copyright holder" in text
    assert "AUTO-07p" in text


def test_citation_version_is_the_library_version():
    text = (ROOT / "CITATION.cff").read_text()
    assert re.search(r"^version: (\S+)$", text, re.M).group(1) == header_version()
    assert re.search(r"^license: BSD-3-Clause$", text, re.M)


def test_citation_names_the_paper():
    yaml = pytest.importorskip("yaml")
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert cff["cff-version"] == "1.2.0"
    assert cff["type"] == "software" and cff["authors"] and cff["message"]
    paper = cff["preferred-citation"]
    assert paper["type"] == "article"
    assert paper["title"] == ("Effects of freeplay on the dynamic stability of an aircraft "
                              "main landing gear")
    assert [a["family-names"] for a in paper["authors"]] == [
        "Howcroft", "Lowenberg", "Neild", "Krauskopf"]


def test_the_python_package_has_the_library_version():
    import mlgshimmy
    header = (ROOT / "c" / "mlg_version.h").read_text()
    parts = [re.search(rf"#define MLG_VERSION_{p} (\d+)", header).group(1)
             for p in ("MAJOR", "MINOR", "PATCH")]
    assert mlgshimmy.__version__ == ".".join(parts)
