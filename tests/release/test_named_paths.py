"""Every file and module that the docs or a code comment name exists: a
path ending in .py, .mk, .c or .h (a suffix of a tracked file's path, so
`shared/naming.py` and `strut.h` count), a directory under
drivers/mlgshimmy/, and a dotted module name of the package
(`mlgshimmy.shared.jobs.cache`, `shared.paper.report`: the first name after
the longest module must be defined in that module).  A renamed or removed
module then fails here instead of leaving the reader a dead pointer.

Run: /usr/bin/python3 -m pytest -q tests/release/test_named_paths.py
"""
import ast
import functools
import io
import pathlib
import re
import subprocess
import tokenize

import helpers

ROOT = pathlib.Path(helpers.ROOT)
PACKAGE = ROOT / "drivers" / "mlgshimmy"
ROOMS = ("shared", "figures", "studies")

# a file name; placeholders (figNN, <fig>, *, {k}) are patterns, not names
FILE = re.compile(r"(?<![\w./<>*{}-])((?:[\w.-]+/)*[\w-]+\.(?:py|mk|c|h))(?![\w/*])")
PLACEHOLDER = re.compile(r"NN|XXX")
PACKAGE_PATH = re.compile(r"(?<![\w/])drivers/mlgshimmy[\w/.]*")
# files of AUTO-07p, of GCC, of the reader, or written into build/ (the demo's mlg.mk)
FOREIGN = {"auto_f2c.h", "runAUTO.py", "Points.py", "compile_options.c", "my.c", "mlg.mk"}
DOTTED = re.compile(r"(?<![\w./-])((?:mlgshimmy|shared|figures|studies)(?:\.[A-Za-z_]\w*)+)")
# `continuation.hopf_point`: a module by its last name, in backticks
SHORT = re.compile(r"`([a-z_]\w*)((?:\.[A-Za-z_]\w*)+)")
# the last word of a file name, not an attribute
EXTENSIONS = {"py", "mk", "c", "h", "md", "json", "txt", "png", "pdf", "sh", "cff", "toml", "d",
              "auto", "exe", "so", "a", "html", "log", "conf"}


@functools.lru_cache(maxsize=None)
def tracked():
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout
    return [p for p in out.splitlines() if (ROOT / p).exists()]


@functools.lru_cache(maxsize=None)
def suffixes():
    found = set()
    for path in tracked():
        parts = path.split("/")
        found.update("/".join(parts[k:]) for k in range(len(parts)))
    return found


def module_file(parts):
    base = PACKAGE.joinpath(*parts)
    if (base / "__init__.py").exists():
        return base / "__init__.py"
    if base.with_suffix(".py").exists():
        return base.with_suffix(".py")
    return None


@functools.lru_cache(maxsize=None)
def defined(path):
    """The names a module defines or imports at its top level."""
    tree = ast.parse(path.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            for target in targets:
                names.update(n.id for n in ast.walk(target) if isinstance(n, ast.Name))
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            names.update((a.asname or a.name).split(".")[0] for a in node.names)
    return names


@functools.lru_cache(maxsize=None)
def by_last_name():
    """The package's modules by their last name, those whose name is unique."""
    modules = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(PACKAGE).with_suffix("").parts
        parts = parts[:-1] if parts[-1] == "__init__" else parts
        if parts and parts[-1] != "__main__":
            modules.setdefault(parts[-1], []).append(".".join(parts))
    return {name: found[0] for name, found in modules.items() if len(found) == 1}


def dotted_problem(name):
    """Why the dotted name names nothing, or None."""
    parts = name.split(".")
    if parts[0] == "mlgshimmy":
        parts = parts[1:]
    if parts[-1] in EXTENSIONS:
        return None
    k = len(parts)
    while k and module_file(parts[:k]) is None:
        k -= 1
    if k == 0:
        return "no such module"
    if k == len(parts):
        return None
    if parts[k] in defined(module_file(parts[:k])):
        return None
    return f"{'.'.join(parts[:k])} has no {parts[k]}"


def problems(text):
    found = []
    for match in FILE.finditer(text):
        name = match.group(1).lstrip("./")
        if name.startswith("build/") or PLACEHOLDER.search(name) or \
                name.rpartition("/")[2] in FOREIGN:
            continue
        if name not in suffixes():
            found.append(f"{match.group(1)}: no such file")
    for match in PACKAGE_PATH.finditer(text):
        path = match.group(0).rstrip(".")
        if not FILE.fullmatch(path) and not (ROOT / path).is_dir():
            found.append(f"{path}: no such directory")
    for match in DOTTED.finditer(text):
        why = dotted_problem(match.group(1))
        if why:
            found.append(f"{match.group(1)}: {why}")
    for match in SHORT.finditer(text):
        first, rest = match.groups()
        if first in ROOMS or first == "mlgshimmy" or rest.rpartition(".")[2] in EXTENSIONS:
            continue
        if first.startswith("atlas_") or first in by_last_name():
            why = dotted_problem(by_last_name().get(first, first) + rest)
            if why:
                found.append(f"{first}{rest}: {why}")
    return found


def python_comments(source):
    """The comments and docstrings of a Python file."""
    out = []
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        if tok.type == tokenize.COMMENT:
            out.append(tok.string)
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            doc = ast.get_docstring(node, clean=False)
            if doc:
                out.append(doc)
    return "\n".join(out)


def c_comments(source):
    return "\n".join(m.group(0) for m in re.finditer(r"/\*.*?\*/|//[^\n]*", source, re.S))


def hash_comments(source):
    return "\n".join(m.group(0) for m in re.finditer(r"#[^\n]*", source))


def texts():
    """(path, text a reader reads as prose) of the docs and the code's comments."""
    for path in tracked():
        if path.startswith("tests/reference/"):
            continue
        source = (ROOT / path).read_text(errors="replace")
        if path.endswith(".md"):
            yield path, source
        elif path.endswith(".py"):
            yield path, python_comments(source)
        elif path.endswith((".c", ".h")):
            yield path, c_comments(source)
        elif path.endswith((".mk", ".sh")) or path == "Makefile":
            yield path, hash_comments(source)


def test_every_named_file_and_module_exists():
    dead = [f"{path}: {why}" for path, text in texts() for why in problems(text)]
    assert not dead, "names that point nowhere:\n  " + "\n  ".join(dead)


def test_the_check_finds_dead_names():
    text = ("see drivers/fig08.py, mk/geometry.mk, shared.report, "
            "mlgshimmy.shared.paper.no_such_name and drivers/mlgshimmy/nowhere/")
    assert problems(text) == [
        "drivers/fig08.py: no such file", "mk/geometry.mk: no such file",
        "drivers/mlgshimmy/nowhere/: no such directory", "shared.report: shared has no report",
        "mlgshimmy.shared.paper.no_such_name: shared.paper has no no_such_name"]
    text = ("shared/naming.py, strut.h, mk/figures.mk, drivers/mlgshimmy/shared/jobs/, "
            "shared.paper.report, mlgshimmy.figures.fig11.plot, figures.mk, figNN.py, <fig>.py")
    assert problems(text) == []
