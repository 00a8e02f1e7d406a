"""The lowest floors of the shared layer, read from the imports (as make and
tests/jobs/test_rooms.py read them): AUTO's session imports no AUTO recipe,
so the cache can ask which AUTO without loading them; the cluster tool
imports nothing of the project but shared.paths, so it runs on a login node
that has no numpy."""
import os

import pytest

from mlgshimmy.shared.jobs import depends

SHARED = "mlgshimmy.shared"
BASE = {"mlgshimmy", SHARED}


def closure(module):
    """The project's modules that importing `module` runs."""
    root = os.path.dirname(depends.PACKAGE_DIR)
    return {os.path.relpath(path, root)[:-3].replace(os.sep, ".").removesuffix(".__init__")
            for path in depends.closure([module])}


@pytest.mark.parametrize("module, allowed", [
    ("autosession", {"autosession", "guards", "children", "paths"}),
    ("provenance", {"provenance", "autosession", "guards", "children", "paths"}),
])
def test_the_auto_session_is_a_lowest_floor(module, allowed):
    found = closure(f"{SHARED}.{module}") - BASE
    assert found == {f"{SHARED}.{m}" for m in allowed}, sorted(found)


def test_the_cache_runs_no_auto_recipe():
    found = closure(f"{SHARED}.jobs.cache")
    assert not found & {f"{SHARED}.{m}" for m in ("autoglue", "continuation", "diagrams")}, \
        sorted(found)


def test_the_cluster_tool_needs_only_paths():
    found = {m for m in closure(f"{SHARED}.cluster") - BASE
             if not m.startswith(f"{SHARED}.cluster")}
    assert found == {f"{SHARED}.paths"}, sorted(found)
