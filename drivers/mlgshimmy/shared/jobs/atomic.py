"""The one way the drivers replace a file: written beside it under an
unpredictable name, flushed, then renamed over it, so that a reader (or
make, after an interrupt) sees the old file or the new one, never a part."""
import json
import os
import tempfile
from typing import Any, Callable, IO


def write_atomic(path: str, write: Callable[[IO], Any], mode: str = "w") -> str:
    """Replace `path` by what write(file) writes; returns path.  The
    temporary file is removed if write() or the rename fails."""
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, exist_ok=True)
    fd, partial = tempfile.mkstemp(dir=directory, prefix=f".{os.path.basename(path)}.",
                                   suffix=".part")
    try:
        with os.fdopen(fd, mode) as out:
            write(out)
            out.flush()
            os.fsync(out.fileno())
        os.replace(partial, path)
    except BaseException:
        try:
            os.remove(partial)
        except FileNotFoundError:
            pass
        raise
    return path


def write_text(path: str, text: str) -> str:
    return write_atomic(path, lambda out: out.write(text))


def write_json(path: str, data: Any, **options: Any) -> str:
    return write_atomic(path, lambda out: json.dump(data, out, **options))
