"""The three rooms of drivers/mlgshimmy: figures and studies import the
shared layer, never each other (a figure package or a study package may
import its own modules); the shared layer imports neither.  Checked on the
imports written anywhere in a file (inside functions too), and shown to
fail on a tree with each kind of bad import."""
import os
import shutil

import pytest

from mlgshimmy.shared.jobs import depends

PACKAGE = os.path.dirname(depends.PACKAGE_DIR)   # drivers/


def room(module):
    """(room, unit): the room of a module and the figure/study it belongs
    to (a module of a package such as figures.fig11 belongs to fig11)."""
    parts = module.split(".")
    return (parts[1] if len(parts) > 1 else None), (parts[2] if len(parts) > 2 else None)


def violations(root):
    """Every import that breaks the rule in the package under root."""
    found = []
    for directory, _, files in os.walk(os.path.join(root, "mlgshimmy")):
        for name in sorted(files):
            if not name.endswith(".py"):
                continue
            path = os.path.join(directory, name)
            module = os.path.relpath(path, root)[:-3].replace(os.sep, ".")
            if module.endswith(".__init__"):
                module = module[:-len(".__init__")]
            here, unit = room(module)
            for other in sorted(depends.imported(path, module, root=root)):
                there, other_unit = room(other)
                if there in (None, "shared") and here is not None:
                    continue          # the package's own index, the shared layer
                if here == "shared" and there in ("figures", "studies"):
                    found.append(f"{module} (shared layer) imports {other}")
                elif here in ("figures", "studies") and there in ("figures", "studies") \
                        and (there, other_unit) != (here, unit) and other_unit is not None:
                    found.append(f"{module} ({here}) imports {other} ({there})")
    return found


def test_the_rooms_hold():
    assert violations(PACKAGE) == []


def test_every_room_has_its_modules():
    rooms = {d: sorted(os.listdir(os.path.join(PACKAGE, "mlgshimmy", d)))
             for d in ("shared", "figures", "studies")}
    assert "continuation.py" in rooms["shared"] and "jobs" in rooms["shared"]
    assert "fig07.py" in rooms["figures"] and "fig11" in rooms["figures"]
    assert "atlas" in rooms["studies"] and "sweep.py" in rooms["studies"]


@pytest.mark.parametrize("where, line, expected", [
    ("figures/fig07.py", "from mlgshimmy.figures import fig09", "figures.fig07 (figures) imports"),
    ("figures/fig07.py", "from mlgshimmy.studies import sweep", "figures.fig07 (figures) imports"),
    ("studies/sweep.py", "from mlgshimmy.figures.fig11 import plane",
     "studies.sweep (studies) imports"),
    ("shared/spectrum.py", "from mlgshimmy.studies.atlas import cell",
     "shared.spectrum (shared layer) imports"),
    ("figures/fig11/plot.py", "    from mlgshimmy.figures import fig10",
     "figures.fig11.plot (figures) imports"),
])
def test_a_bad_import_is_found(tmp_path, where, line, expected):
    shutil.copytree(os.path.join(PACKAGE, "mlgshimmy"), tmp_path / "mlgshimmy")
    path = tmp_path / "mlgshimmy" / where
    text = path.read_text()
    if line.startswith(" "):   # inside a function: the first def's body
        head, rest = text.split("\ndef ", 1)
        signature, body = rest.split("\n", 1)
        text = f"{head}\ndef {signature}\n{line}\n{body}"
    else:
        text += f"\n{line}\n"
    path.write_text(text)
    found = violations(str(tmp_path))
    assert found and all(f.startswith("mlgshimmy." + expected) for f in found), found


def test_own_package_imports_are_allowed():
    """fig11's modules import each other, the atlas's too: not a violation."""
    imported = depends.imported(os.path.join(PACKAGE, "mlgshimmy", "figures", "fig11", "plot.py"),
                                "mlgshimmy.figures.fig11.plot")
    assert any(m.startswith("mlgshimmy.figures.fig11.") for m in imported)
