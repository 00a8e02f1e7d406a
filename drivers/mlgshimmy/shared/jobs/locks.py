"""Exclusive locks on files beside what they guard (flock, held until
released or the process ends), opened so that they cannot be turned
against anyone: a symbolic link planted in their place is refused, never
followed, and an existing file is never truncated before it is ours."""
import fcntl
import os
import stat
import sys
import time
from typing import Callable, Optional


class LockRefused(RuntimeError):
    """The lock's path is a symbolic link or not a regular file."""


def open_lock(path: str) -> int:
    """A descriptor of the lock file at path, created if needed (mode 0644),
    never through a symbolic link."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    try:
        fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_CLOEXEC, 0o644)
    except OSError as exc:
        if os.path.islink(path):
            raise LockRefused(f"{path} is a symbolic link: refusing to use it as a lock "
                              "(remove it)") from None
        raise LockRefused(f"{path}: cannot open the lock ({exc.strerror})") from None
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        raise LockRefused(f"{path} is not a regular file: refusing to use it as a lock")
    return fd


def holder(fd: int) -> str:
    os.lseek(fd, 0, os.SEEK_SET)
    return os.read(fd, 400).decode(errors="replace").strip() or "another process"


def acquire(path: str, waiting: Optional[Callable[[str], None]] = None) -> int:
    """Lock path exclusively and return its descriptor (close it, or end the
    process, to release).  If another process holds it, waiting(holder) is
    called first and this blocks until it is free.  The holder's pid and
    command line are then written into the file, which is ours now."""
    fd = open_lock(path)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        if waiting:
            waiting(holder(fd))
        fcntl.flock(fd, fcntl.LOCK_EX)
    os.ftruncate(fd, 0)
    os.lseek(fd, 0, os.SEEK_SET)
    os.write(fd, f"process {os.getpid()} ({' '.join(sys.argv)[:200]})\n".encode())
    return fd


def say_waiting(what: str) -> Callable[[str], None]:
    """A waiting() for acquire that says on stderr who holds `what`."""
    def waiting(by: str) -> None:
        print(f"{what} is in use by {by}; waiting for it to finish", file=sys.stderr,
              flush=True)
    return waiting


def since(path: str, started_ns: int) -> bool:
    """Whether path was (re)written at or after started_ns (time.time_ns())."""
    try:
        return os.stat(path).st_mtime_ns >= started_ns
    except FileNotFoundError:
        return False


def now_ns() -> int:
    return time.time_ns()
