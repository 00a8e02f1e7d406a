"""Which AUTO, which version, which commit: read here only, for the cache's
record of each result (jobs.cache.provenance) and the report's (report.tools)."""
import os
import subprocess
from typing import Optional

from mlgshimmy.shared import autosession, paths

# what a result depends on in the tree: a change here marks the commit dirty
SOURCES = ("drivers", "constants", "c", "models")


def auto_version() -> Optional[str]:
    """The first line of the AUTO tree's CHANGELOG (a source build), else
    the Debian package's version (an installed AUTO ships none)."""
    where = autosession.auto_dir()
    try:
        with open(os.path.join(where, "CHANGELOG")) as log:
            return log.readline().strip().rstrip(":")
    except OSError:
        pass
    proc = subprocess.run(["dpkg-query", "-S", where], capture_output=True, text=True)
    package = proc.stdout.split(":")[0].strip() if proc.returncode == 0 else ""
    if not package:
        return None
    version = subprocess.run(["dpkg-query", "-W", "-f=${Version}", package],
                             capture_output=True, text=True).stdout.strip()
    return f"{package} {version}" if version else None


def git_commit() -> Optional[str]:
    """HEAD, with "+dirty" if the drivers, constants, C sources or models
    differ from it; None outside a git checkout."""
    def git(*args):
        try:
            return subprocess.run(["git", "-C", paths.ROOT, *args], capture_output=True,
                                  text=True).stdout.strip()
        except OSError:
            return ""
    head = git("rev-parse", "HEAD")
    dirty = git("status", "--porcelain", "--", *SOURCES)
    return (head + ("+dirty" if dirty else "")) or None
