"""The one way the drivers replace a file: written beside it under an
unpredictable name, flushed, then renamed over it, so that a reader (or
make, after an interrupt) sees the old file or the new one, never a part.
New files and directories get the mode the umask gives (0644 and 0755 under
umask 022), as open() and mkdir would: outputs are for colleagues too."""
import json
import os
import secrets
from typing import Any, Callable, IO, TypeVar

T = TypeVar("T")


def _create_unique(directory: str, prefix: str, suffix: str, create: Callable[[str], T]) -> T:
    """create(path) on a new path directory/prefix<random>suffix; create must
    fail with FileExistsError if the path exists.  (tempfile.mkstemp and
    mkdtemp would force modes 0600 and 0700, whatever the umask.)"""
    for _ in range(100):
        path = os.path.join(directory, f"{prefix}{secrets.token_hex(8)}{suffix}")
        try:
            return create(path)
        except FileExistsError:
            continue
    raise FileExistsError(f"{directory}: no free name {prefix}...{suffix} in 100 tries")


def new_directory(directory: str, prefix: str) -> str:
    """A new empty directory under `directory`, named prefix<random>."""
    def create(path: str) -> str:
        os.mkdir(path, 0o777)
        return path
    return _create_unique(directory, prefix, "", create)


def write_atomic(path: str, write: Callable[[IO], Any], mode: str = "w") -> str:
    """Replace `path` by what write(file) writes; returns path.  The
    temporary file is removed if write() or the rename fails."""
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, exist_ok=True)
    fd, partial = _create_unique(
        directory, f".{os.path.basename(path)}.", ".part",
        lambda name: (os.open(name, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC,
                              0o666), name))
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
