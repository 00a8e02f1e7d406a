"""'did you mean' for a name that is not known (standard library only, so
shared.overlay can use it before anything is built)."""
import difflib
from typing import Iterable


def did_you_mean(name: str, known: Iterable[str]) -> str:
    """'; did you mean X?' for the known name closest to `name`, or ''."""
    close = difflib.get_close_matches(name, [k for k in known if k], n=1)
    return f"; did you mean {close[0]}?" if close else ""
