"""The Python files a driver's result depends on, for make (as `gcc -MMD`
does for C): the static import closure of a module inside the mlgshimmy
package, imports inside functions included.  Nothing is imported, and
this file needs only the standard library, so it works before anything is
built or installed; make runs it as a file (`-m` would run the package's
__init__s, which import numpy):

    python3 drivers/mlgshimmy/shared/jobs/depends.py VAR x.d MODULE [MODULE...] > x.d

writes `VAR := <files>`, `x.d: $(VAR)` (so make regenerates it when one of
them changes) and an empty rule per file (a deleted module then does not
stop make)."""
import ast
import os
import sys
from typing import List, Set

PACKAGE = "mlgshimmy"
PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def module_file(module: str, root: str = os.path.dirname(PACKAGE_DIR)) -> str:
    """The file of a module of the package under root (default: this one's
    drivers/; a package: its __init__.py)."""
    parts = module.split(".")
    if parts[0] != PACKAGE:
        raise ValueError(f"{module} is not a module of {PACKAGE}")
    base = os.path.join(root, *parts)
    if os.path.isdir(base):
        return os.path.join(base, "__init__.py")
    if os.path.exists(base + ".py"):
        return base + ".py"
    raise ValueError(f"no module {module} (no {base}.py)")


def _is_module(module: str, root: str = os.path.dirname(PACKAGE_DIR)) -> bool:
    try:
        module_file(module, root)
        return True
    except ValueError:
        return False


def imported(path: str, module: str, root: str = os.path.dirname(PACKAGE_DIR)) -> Set[str]:
    """The package's modules (under root) that the file imports, anywhere in it."""
    with open(path) as source:
        tree = ast.parse(source.read(), path)
    package = module if path.endswith("__init__.py") else module.rpartition(".")[0]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")
                anchor = anchor[:len(anchor) - node.level + 1]
                base = ".".join(anchor + ([base] if base else []))
            names = [base] + [f"{base}.{a.name}" for a in node.names]
        else:
            continue
        for name in names:
            if name.split(".")[0] != PACKAGE:
                continue
            # every package on the way is imported too (its __init__ runs)
            parts = name.split(".")
            for k in range(1, len(parts) + 1):
                if _is_module(".".join(parts[:k]), root):
                    found.add(".".join(parts[:k]))
    return found


def closure(modules: List[str]) -> List[str]:
    """The files of the modules and of everything they import, sorted (a
    package run with `python -m` runs its __main__ too)."""
    seen, todo = set(), list(modules)
    todo += [f"{m}.__main__" for m in modules
             if module_file(m).endswith("__init__.py") and _is_module(f"{m}.__main__")]
    for module in modules:   # the packages the entry modules sit in run too
        parts = module.split(".")
        todo += [".".join(parts[:k]) for k in range(1, len(parts))]
    while todo:
        module = todo.pop()
        if module in seen:
            continue
        seen.add(module)
        todo += sorted(imported(module_file(module), module) - seen)
    return sorted({module_file(m) for m in seen})


def main(argv: List[str]) -> int:
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    variable, dfile, modules = argv[0], argv[1], argv[2:]
    try:
        files = [os.path.relpath(f) for f in closure(modules)]
    except (ValueError, SyntaxError) as exc:
        print(f"depends: {exc}", file=sys.stderr)
        return 2
    print(f"{variable} := " + " \\\n  ".join(files))
    print(f"{dfile}: $({variable})")
    print("".join(f"\n{f}:" for f in files))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
