"""The console and the logs of AUTO runs: one console line per run, and
AUTO's own output sent to <rundir>/<name>.log."""
import atexit
import os
import sys
import time

from mlgshimmy.shared import paths
from mlgshimmy.shared.rundirs import figure_of


class _Progress:
    """One console line per AUTO run: figure, run, its number and, where
    known, the total: the number of runs the same figure, or the same part
    of it (paths.PART_ENV), made last time under any run root
    (build/.runs/<figure>[.<part>].count); the first time, no total."""

    def __init__(self):
        self.started = time.monotonic()
        self.done = {}

    def count_file(self, figure):
        part = os.environ.get(paths.PART_ENV)
        return os.path.join(paths.BUILD, ".runs", f"{figure}.{part}.count" if part else
                            f"{figure}.count")

    def previous(self, figure):
        try:
            with open(self.count_file(figure)) as f:
                return int(f.read())
        except (OSError, ValueError):
            return None

    def step(self, rundir, name, seconds, status="done"):
        figure = figure_of(rundir)
        if figure not in self.done:
            self.done[figure] = [0, self.previous(figure)]
        self.done[figure][0] += 1
        done, total = self.done[figure]
        count = f"run {done}" if total is None or total < done else f"{done}/{total}"
        where = os.path.relpath(os.path.join(os.path.abspath(rundir), name),
                                os.path.join(paths.run_root(), figure))
        print(f"{figure}: {where} {status} ({count}) in {seconds:.1f} s, "
              f"{time.monotonic() - self.started:.0f} s elapsed", flush=True)

    def save(self):
        """At exit: remember each figure's run count as next time's total."""
        for figure, (done, _) in self.done.items():
            try:
                os.makedirs(os.path.dirname(self.count_file(figure)), exist_ok=True)
                with open(self.count_file(figure), "w") as f:
                    f.write(f"{done}\n")
            except OSError:
                pass


PROGRESS = _Progress()
atexit.register(PROGRESS.save)


class LogTo:
    """Send this process's stdout and stderr (its own and AUTO's child
    processes') to a file, at the descriptor level.  A sys.stdout or
    sys.stderr that something replaced (pytest's capture, IPython) writes
    elsewhere than descriptor 1 or 2: it is replaced by one on the
    descriptor meanwhile, so that AUTO's own messages reach the log too."""

    def __init__(self, path):
        self.path = path

    def __enter__(self):
        sys.stdout.flush()
        sys.stderr.flush()
        self.saved = [os.dup(1), os.dup(2)]
        log = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        os.dup2(log, 1)
        os.dup2(log, 2)
        os.close(log)
        self.streams = [sys.stdout, sys.stderr]
        if sys.stdout is not sys.__stdout__:
            sys.stdout = open(1, "w", closefd=False)
        if sys.stderr is not sys.__stderr__:
            sys.stderr = open(2, "w", closefd=False)

    def __exit__(self, *exc):
        sys.stdout.flush()
        sys.stderr.flush()
        for stream, saved in zip((sys.stdout, sys.stderr), self.streams):
            if stream is not saved:
                stream.close()   # the descriptor stays open (closefd=False)
        sys.stdout, sys.stderr = self.streams
        for fd, saved in zip((1, 2), self.saved):
            os.dup2(saved, fd)
            os.close(saved)
