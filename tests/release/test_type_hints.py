"""Every public function of drivers/mlgshimmy has type hints (#40): each
parameter (self and cls aside, *args and **kwargs included) and its return,
written so that Python 3.9 can evaluate them (typing's Optional and Union,
not `X | Y`).  The package's py.typed tells a type checker that they are
there.  Public: a module-level function, or a method of a module-level
class, whose name does not start with "_".  Read from the source (ast),
importing nothing.
Run: /usr/bin/python3 -m pytest -q tests/release/test_type_hints.py
"""
import ast
import os

import pytest

from helpers import ROOT

PACKAGE = os.path.join(ROOT, "drivers", "mlgshimmy")


def public_functions(tree: ast.Module):
    """(name, node) of the public functions and methods of a module."""
    for node in tree.body:
        if isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
            functions = [(f"{node.name}.", n) for n in node.body]
        else:
            functions = [("", node)]
        for prefix, fn in functions:
            if isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)) \
                    and not fn.name.startswith("_"):
                yield prefix + fn.name, fn


def parameters(fn: ast.FunctionDef) -> list:
    a = fn.args
    return a.posonlyargs + a.args + a.kwonlyargs + [p for p in (a.vararg, a.kwarg) if p]


def unhinted(source: str) -> list:
    """The public functions of a module's source lacking a hint: ["name",
    "Class.name"]."""
    return [name for name, fn in public_functions(ast.parse(source))
            if fn.returns is None or any(p.annotation is None for p in parameters(fn)
                                         if p.arg not in ("self", "cls"))]


def newer_than_39(source: str) -> list:
    """The public functions whose hints use `X | Y`, which Python 3.9
    cannot evaluate (typing.get_type_hints)."""
    out = []
    for name, fn in public_functions(ast.parse(source)):
        hints = [p.annotation for p in parameters(fn)] + [fn.returns]
        if any(isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr)
               for hint in hints if hint is not None for node in ast.walk(hint)):
            out.append(name)
    return out


def modules():
    for where, _, files in os.walk(PACKAGE):
        for name in sorted(files):
            if name.endswith(".py"):
                path = os.path.join(where, name)
                with open(path) as source:
                    yield os.path.relpath(path, PACKAGE).replace(os.sep, "/"), source.read()


def test_every_public_function_is_hinted():
    found = {name: unhinted(source) for name, source in modules()}
    assert len(found) > 100     # the walk found the package
    assert {name: missing for name, missing in found.items() if missing} == {}


def test_every_hint_reads_in_python_3_9():
    found = {name: newer_than_39(source) for name, source in modules()}
    assert {name: newer for name, newer in found.items() if newer} == {}


@pytest.mark.parametrize("source, expected", [
    ("def f(x: int) -> int:\n    return x\n", []),
    ("def f(x) -> int:\n    return x\n", ["f"]),
    ("def f(x: int):\n    return x\n", ["f"]),
    ("def f(*args, **kw: int) -> None:\n    pass\n", ["f"]),
    ("def f(*, key) -> None:\n    pass\n", ["f"]),
    ("def _f(x):\n    return x\n", []),
    ("class C:\n    def m(self, x: int) -> int:\n        return x\n"
     "    def n(self, x):\n        return x\n    def __eq__(self, o):\n        return True\n",
     ["C.n"]),
    ("class _C:\n    def m(self, x):\n        return x\n", []),
    ("def f(x: int) -> int:\n    def inner(y):\n        return y\n    return inner(x)\n", []),
])
def test_a_missing_hint_is_found(source, expected):
    assert unhinted(source) == expected


@pytest.mark.parametrize("source, expected", [
    ("def f(x: Optional[int]) -> Union[int, str]:\n    return x\n", []),
    ("def f(x: int | None) -> int:\n    return 1\n", ["f"]),
    ("def f(x: int) -> List[int | str]:\n    return []\n", ["f"]),
])
def test_a_hint_python_3_9_cannot_read_is_found(source, expected):
    assert newer_than_39(source) == expected


def test_the_package_says_it_is_typed():
    assert os.path.isfile(os.path.join(PACKAGE, "py.typed"))
