"""The jobs of a figure's compute step (parts), each cached on its own, so
that make (mk/parts.mk), GNU parallel or a Slurm array run them side by
side, one stage after another: a part of stage 1 needs no other, one of
stage k + 1 needs parts of stage k at most."""
import os
import time
from typing import Any, Callable, Dict, Iterable, List, Union

from mlgshimmy.shared import paths
from mlgshimmy.shared.jobs import cache


class Needs:
    """A part that reads other parts: function(parts), run once the parts
    named in `names` are cached (make runs it after them).  `after`: parts
    it waits for without reading them (make's order-only prerequisites, a
    later stage): a short part that waits for the inputs of a long chain
    leaves the cores to that chain's next part.  GNU make goes over the
    part list in order, waiting for a free core at each part it can start,
    and comes back to a part whose prerequisites were still running only
    on its next pass; the short parts it meets first would run before it."""

    def __init__(self, names: Iterable[str], function: Callable[[Any], Any],
                 after: Iterable[str] = ()):
        self.names, self.function, self.after = tuple(names), function, tuple(after)

    def __repr__(self) -> str:
        return f"Needs({list(self.names)}" + (f", after={list(self.after)})" if self.after
                                              else ")")


Job = Union[Callable[[], Any], Needs]


class Parts:
    """{name: function or Needs} of one figure.  parts[name] is the cached
    part, computed here if it is missing; a part computed on its own
    (compute(name, alone=True), `--part NAME`) instead refuses to compute a
    part it needs, which a parallel job may be writing."""

    def __init__(self, figure: str, jobs: Dict[str, Job], parameter_set: str):
        self.figure, self.jobs, self.parameter_set = figure, jobs, parameter_set
        for name in jobs:
            self.stage(name)   # every needed part exists, no cycle

    def __repr__(self) -> str:
        return f"Parts({self.figure!r}, {len(self.jobs)} parts, {self.stages()} stages)"

    def stage(self, name: str, seen: tuple = ()) -> int:
        if name not in self.jobs:
            raise ValueError(f"{self.figure}: no part named {name!r} "
                             f"(parts: {' '.join(self.jobs)})")
        if name in seen:
            raise ValueError(f"{self.figure}: part {name} needs itself")
        job = self.jobs[name]
        if not isinstance(job, Needs):
            return 1
        return 1 + max((self.stage(n, seen + (name,)) for n in job.names + job.after),
                       default=0)

    def stages(self) -> int:
        return max(self.stage(name) for name in self.jobs)

    def of_stage(self, stage: int) -> List[str]:
        if not 1 <= stage <= self.stages():
            raise ValueError(f"{self.figure}: --stage {stage}: its parts have stages "
                             f"1 to {self.stages()}")
        return [name for name in self.jobs if self.stage(name) == stage]

    def compute(self, name: str, alone: bool = False) -> None:
        """Compute and cache one part; alone: a missing part it needs is an
        error (a parallel job may be writing it), not computed here."""
        self.stage(name)   # a part of this figure (the error names the parts)
        job = self.jobs[name]
        started = time.monotonic()
        if alone:   # its AUTO runs are counted as this part's (autoglue's progress)
            os.environ[paths.PART_ENV] = name
        if cache.compute_once(self.figure, lambda: job.function(_Reader(self, alone))
                              if isinstance(job, Needs) else job(), self.parameter_set, name):
            cached = sum(os.path.exists(cache.path(self.figure, n)) for n in self.jobs)
            print(f"{self.figure}: part {name} computed in {time.monotonic() - started:.0f} s "
                  f"({cached} of {len(self.jobs)} parts cached)", flush=True)

    def __getitem__(self, name: str) -> Any:
        return _Reader(self, False)[name]

    def all(self) -> Dict[str, Any]:
        """{name: data} of every part, in order."""
        return {name: self[name] for name in self.jobs}

    def make_rules(self) -> str:
        """mk/parts.mk's rules: PARTS, and each part's needs as the
        prerequisites of its file (those it waits for only as order-only
        ones)."""
        def files(names):
            return " ".join(cache.path(self.figure, n) for n in names)
        lines = [f"PARTS := {' '.join(self.jobs)}"]
        lines += [f"{cache.path(self.figure, name)}:"
                  + (f" {files(job.names)}" if job.names else "")
                  + (f" | {files(job.after)}" if job.after else "")
                  for name, job in self.jobs.items() if isinstance(job, Needs)]
        return "\n".join(lines) + "\n"


class _Reader:
    """What a Needs function reads its parts through."""

    def __init__(self, parts: Parts, alone: bool):
        self.parts, self.alone = parts, alone

    def __getitem__(self, name: str) -> Any:
        parts = self.parts
        if not os.path.exists(cache.path(parts.figure, name)):
            if self.alone:
                raise cache.MissingResult(f"{parts.figure}: part {name} is not cached yet; run "
                                          f"the parts of stage {parts.stage(name)} first")
            parts.compute(name)
        return cache.read(parts.figure, name)


def rules_path(figure: str) -> str:
    return paths.under_root(figure, "parts.mk")
