"""How the tool refuses: the two exceptions and its one voice on stderr."""
from __future__ import annotations

import sys

TOOL = "submit"


class Refused(Exception):
    """A request that cannot be carried out, with the reason."""


class NothingToDo(Exception):
    """--allow-empty: no stage has a line and there is no assembly."""


def say(message: str) -> None:
    print(f"{TOOL}: {message}", file=sys.stderr)
