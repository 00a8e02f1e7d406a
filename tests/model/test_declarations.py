"""One declaration of every name of the model: the X-macro tables of
c/mlg_parameters.h.  What is derived from them (the built library,
mlgmodel, overlay, the constants AUTO reads, build/models/c.mlg) and what
must still be written by hand (mlgmodel's constants of the PAR layout,
docs/model.md 2.1, docs/units.md) agree with the tables entry by entry, and
constants/c.mlg holds no copy of them; each failure names the entry and
the place it is wrong or missing in.

Run: /usr/bin/python3 -m pytest -q tests/model/test_declarations.py
"""
import os
import re

from mlgshimmy.shared import autosession, mlgmodel, overlay
from mlgshimmy.shared import continuation as ct

import helpers

HEADER = os.path.join(helpers.ROOT, "c", "mlg_parameters.h")
CONTINUATION = overlay.entries("MLG_CONTINUATION_PARAMETERS")   # [(name, unit)], PAR order


def header_define(name: str) -> int:
    with open(HEADER) as f:
        return int(re.search(rf"#define {name} (\d+)", f.read()).group(1))


def constants(path: str) -> dict:
    return autosession.init().parseC.parseC(path)


def doc(name: str) -> str:
    with open(os.path.join(helpers.ROOT, "docs", name)) as f:
        return f.read()


def test_every_continuation_parameter_is_its_par_in_the_library():
    """PAR(k) of the table is PAR(k) of the library (mlgmodel.PARNAMES), and
    the library has no continuation parameter the table lacks."""
    wrong = [f"PAR({k + 1}) {name}: the library has {mlgmodel.PARNAMES[k]!r}"
             for k, (name, _) in enumerate(CONTINUATION) if mlgmodel.PARNAMES[k] != name]
    assert not wrong, "\n".join(wrong)
    assert mlgmodel.PARNAMES[len(CONTINUATION)] is None, \
        f"the library has PAR({len(CONTINUATION) + 1}) {mlgmodel.PARNAMES[len(CONTINUATION)]}"


def test_python_copies_of_the_par_layout():
    """mlgmodel's own constants of the PAR layout are the header's."""
    slot = header_define("MLG_PAR_CONSTANTS_FILE")
    assert mlgmodel.PARNAMES[slot - 1] == mlgmodel.CONSTANTS_FILE, \
        f"PAR({slot}) is {mlgmodel.PARNAMES[slot - 1]!r}, mlgmodel.CONSTANTS_FILE " \
        f"{mlgmodel.CONSTANTS_FILE!r}"
    assert mlgmodel.MEASURES_FIRST_PAR == header_define("MLG_MEASURES_FIRST_PAR")


def test_auto_constants_name_every_par_slot_of_the_library():
    """The constants AUTO reads (build/models/c.mlg) name every PAR slot of
    the library, the period and the measures of MLG_MEASURES from
    MLG_MEASURES_FIRST_PAR on, and nothing else."""
    parnames = {int(k): v for k, v in constants(ct.CONSTANTS)["parnames"]}
    ours = {k + 1: name for k, name in enumerate(mlgmodel.PARNAMES) if name is not None}
    ours[11] = "T"
    ours.update({mlgmodel.MEASURES_FIRST_PAR + k: name
                 for k, name in enumerate(mlgmodel.MEASURES)})
    wrong = {f"PAR({k})": (name, parnames.get(k)) for k, name in sorted(ours.items())
             if parnames.get(k) != name}
    assert not wrong, f"c.mlg parnames differ from the library (library, c.mlg): {wrong}"
    extra = {k: v for k, v in parnames.items() if k not in ours}
    assert not extra, f"c.mlg parnames names what the library does not: {extra}"


def test_auto_constants_unames_follow_the_librarys_states():
    unames = {int(k): v for k, v in constants(ct.CONSTANTS)["unames"]}
    assert [unames.get(i + 1) for i in range(mlgmodel.NX)] == mlgmodel.UNAMES, \
        f"c.mlg {unames}, library {mlgmodel.UNAMES}"


def test_constants_template_names_nothing():
    """constants/c.mlg holds no copy of the names: make appends the
    library's (models/auto_names.c), so a new parameter is named once."""
    c = constants(os.path.join(helpers.ROOT, "constants", "c.mlg"))
    copied = {key: c[key] for key in ("parnames", "unames") if key in c and c[key]}
    assert not copied, f"constants/c.mlg names {copied}: remove them, make generates them"


def test_diagnostics_are_the_tables():
    """mlg_diagnostics as the drivers read it (name, doubles) is the table,
    in its order."""
    with open(HEADER) as f:
        text = f.read()
    table = text[text.index("#define MLG_DIAGNOSTICS(X)"):]
    table = table[:table.index("\n\n")]
    declared = [(name, int(n)) for name, n in re.findall(r"X\((\w+), ([12])\)", table)]
    assert mlgmodel.DIAGNOSTICS == declared


def test_docs_name_every_continuation_parameter_with_its_unit():
    """docs/model.md 2.1 has a row `| k | `name` | ... | unit | ...` and
    docs/units.md a cell `PAR(k) `name` [unit]` for each PAR(k) of the table."""
    model, units = doc("model.md"), doc("units.md")
    missing = []
    for k, (name, unit) in enumerate(CONTINUATION, start=1):
        shown = "–" if unit == "-" else unit
        if not re.search(rf"^\| {k} \| `{name}` \|.*\| {re.escape(shown)} \|", model, re.M):
            missing.append(f"docs/model.md 2.1: no row | {k} | `{name}` | ... | {shown} | ...")
        if f"PAR({k}) `{name}` [{shown}]" not in units:
            missing.append(f"docs/units.md: no cell PAR({k}) `{name}` [{shown}]")
    assert not missing, "\n".join(missing)
