"""The cached result of a figure's compute step: one JSON file per figure,
$MLG_RUN_ROOT/<fig>/result.json (beside its runs, so `make regress`
starting a figure afresh starts its result afresh too), holding its
numbers, the curve arrays its plot needs and where they came from
(parameter set, git commit, AUTO version).  The plot step, the tables and
the reproduction numbers read it; no AUTO import, so a redraw needs none.

    cache.write("fig10", {"numbers": {...}, "eq": stored(eq, COLUMNS)}, "figures")
    result = cache.read("fig10")      # raises MissingResult naming `make fig10`
"""
from __future__ import annotations

import datetime
import hashlib
import json
import math
import os
import resource
import time
from typing import Any, Callable, Mapping, Optional, Sequence

import numpy

from mlgshimmy.shared import autosession, branches, gear, paths
from mlgshimmy.shared.jobs import locks
from mlgshimmy.shared.jobs.atomic import write_json
from mlgshimmy.shared.provenance import auto_version, git_commit


class MissingResult(RuntimeError):
    """No cached result for a figure (its compute step has not run)."""


def path(figure: str, part: Optional[str] = None, root: Optional[str] = None) -> str:
    """$MLG_RUN_ROOT/<fig>/result.json, or parts/<part>.json there (root:
    another run root, e.g. the baseline's beside a geometry's)."""
    if part is not None:
        return os.path.join(parts_dir(figure, root), f"{part}.json")
    return os.path.join(root, figure, "result.json") if root else \
        paths.under_root(figure, "result.json")


def parts_dir(figure: str, root: Optional[str] = None) -> str:
    """Where a figure's cached parts are: $MLG_RUN_ROOT/<fig>/parts (root: as path)."""
    return os.path.join(root, figure, "parts") if root else paths.under_root(figure, "parts")


def _sha256(path: str) -> Optional[str]:
    try:
        with open(path, "rb") as f:
            return hashlib.sha256(f.read()).hexdigest()
    except OSError:
        return None


def provenance(parameter_set: str) -> dict:
    """What a result was computed with: the parameter set, the gear (its
    geometry and overlay: shared.gear), the commit, the AUTO (its tree and
    version), the model executable as linked (sha256) and the AUTO runs'
    thread count."""
    return {"parameter_set": parameter_set, "model": gear.current().record(),
            "git_commit": git_commit(),
            "auto_version": auto_version(), "auto_dir": autosession.auto_dir(),
            "auto_threads": os.environ.get("MLG_AUTO_THREADS", "1"),
            "model_sha256": _sha256(os.path.join(paths.BUILD, "models", "mlg.exe")),
            "written": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")}


def _plain(value: Any) -> Any:
    """value with numpy arrays and numbers as lists and floats (JSON)."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, numpy.ndarray):
        return _plain(value.tolist())
    if isinstance(value, numpy.floating):
        return float(value)
    if isinstance(value, (numpy.integer, numpy.bool_)):
        return value.item()
    return value


class BadResult(RuntimeError):
    """A cached result that fails its checks (cut, edited, or another's)."""


def _not_a_number(value: Any, where: str = "data") -> Optional[str]:
    """Where in value a NaN sits (None if nowhere).  Infinity is allowed: the
    drivers store it for "none up to the end of the range" (a window point
    that no load reaches, e.g.)."""
    if isinstance(value, float):
        return where if math.isnan(value) else None
    if isinstance(value, dict):
        items = value.items()
    elif isinstance(value, list):
        items = enumerate(value)
    else:
        return None
    for key, item in items:
        found = _not_a_number(item, f"{where}[{key!r}]")
        if found:
            return found
    return None


def checksum(data: Any) -> str:
    """sha256 of the data as stored (canonical JSON: sorted keys)."""
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()


def cpu_seconds() -> float:
    """CPU seconds of this process and of its children waited for (AUTO's
    runs, the simulator)."""
    used = [resource.getrusage(who) for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)]
    return sum(u.ru_utime + u.ru_stime for u in used)


def write(figure: str, data: Any, parameter_set: str = "figures",
          part: Optional[str] = None, cost: Optional[dict] = None) -> str:
    """Store data (dicts, lists, arrays, numbers, strings, inf; a NaN is
    refused, naming where it is) with its provenance, the figure's and the
    part's names and a checksum, as the figure's result or one part of it,
    atomically; returns the path.  cost: what computing it took
    ({"wall_seconds", "cpu_seconds"}, compute_once), kept beside the
    provenance for `make profile-<fig>` (no check reads it)."""
    plain = _plain(data)
    nan = _not_a_number(plain)
    if nan:
        raise BadResult(f"{figure}: {'part ' + part if part else 'result'} not cached: "
                        f"{nan} is NaN")
    target = write_json(path(figure, part),
                        {"figure": figure, "part": part, "provenance": provenance(parameter_set),
                         "sha256": checksum(plain), "data": plain,
                         **({"cost": cost} if cost else {})})
    print(f"{figure}: {'part ' + part if part else 'result'} cached in "
          f"{os.path.relpath(target, paths.ROOT)}", flush=True)
    return target


def lock_path(figure: str, part: Optional[str] = None) -> str:
    """The lock that one computation of a result (or part) holds:
    $MLG_RUN_ROOT/.locks/<fig>[.<part>].lock, outside every run directory."""
    return paths.under_root(".locks", f"{figure}.{part}.lock" if part else f"{figure}.lock")


def compute_once(figure: str, compute: Callable[[], Any], parameter_set: str = "figures",
                 part: Optional[str] = None) -> bool:
    """Compute and cache a result (or part) unless another process is
    doing so: then wait for it and use what it wrote, so that two identical
    requests (two `make fig07`, or `make fig18` beside `make fig19`) make
    one computation and keep it.  True if computed here."""
    started = locks.now_ns()
    what = f"{figure}: {'part ' + part if part else 'the result'}"
    fd = locks.acquire(lock_path(figure, part), locks.say_waiting(what))
    try:
        if locks.since(path(figure, part), started):
            print(f"{what} was computed meanwhile by another process; using it", flush=True)
            return False
        wall, cpu = time.monotonic(), cpu_seconds()
        data = compute()
        write(figure, data, parameter_set, part=part,
              cost={"wall_seconds": round(time.monotonic() - wall, 2),
                    "cpu_seconds": round(cpu_seconds() - cpu, 2)})
        return True
    finally:
        os.close(fd)


def _made_for(stored: dict) -> Optional["gear.Gear"]:
    """The gear a stored result records (None: a result that records none)."""
    try:
        return gear.Gear.from_record(stored["provenance"]["model"])
    except (KeyError, TypeError, ValueError, AttributeError):
        return None


def read(figure: str, part: Optional[str] = None, root: Optional[str] = None,
         model: Optional["gear.Gear"] = None) -> Any:
    """The data of a figure's cached result (or of one part of it), checked:
    whole JSON, the figure's and the part's names, the checksum, no NaN, and the
    gear it was made for: this process's (gear.current()), or `model`
    (e.g. the paper's gear, gear.Gear(), for a result read from the
    baseline's root).  A file that fails raises BadResult naming it, both
    gears where they differ, and what to run.  root: as path."""
    where = path(figure, part, root)
    remedy = f"remove it and run `make {figure}`"
    try:
        with open(where) as source:
            stored = json.load(source)
    except FileNotFoundError:
        raise MissingResult(f"{figure}: no cached result {where} "
                            f"(run `make {figure}`)") from None
    except (ValueError, UnicodeDecodeError) as exc:
        raise BadResult(f"{figure}: {where} is not a whole result ({exc}); {remedy}") from None
    if not isinstance(stored, dict) or "data" not in stored:
        raise BadResult(f"{figure}: {where} holds no result; {remedy}")
    if stored.get("figure") != figure or stored.get("part") != part:
        raise BadResult(f"{figure}: {where} is the cached {stored.get('figure')!r} part "
                        f"{stored.get('part')!r}, not {figure!r} part {part!r}; {remedy}")
    if stored.get("sha256") != checksum(stored["data"]):
        raise BadResult(f"{figure}: {where} fails its checksum (edited or damaged); {remedy}")
    # write refuses a NaN; one here (a checksum recomputed by hand, an older
    # writer) would be drawn and printed as a number
    nan = _not_a_number(stored["data"])
    if nan:
        raise BadResult(f"{figure}: {where} holds a NaN at {nan}, which no result may; {remedy}")
    wanted, made = model or gear.current(), _made_for(stored)
    if made != wanted:
        def name(g):
            return "an unrecorded gear" if g is None else \
                (g.describe() or "the paper's gear")
        raise BadResult(f"{figure}: {where} was made for {name(made)}, not for {name(wanted)} "
                        f"as asked; {remedy} (with the RHO, MU, EOM and SET you want)")
    return stored["data"]


class Branch:
    """A stored AUTO branch read back: columns by name (numpy arrays), and
    stability() and labels as a parseB branch has them, so the helpers of
    `branches` and `draw` take either; at_mx {point index: number} as
    stored() kept it ({} if none)."""

    def __init__(self, record: dict):
        self.columns = {k: numpy.asarray(v, dtype=float) for k, v in record["columns"].items()}
        self.coordnames = list(self.columns)
        self._stable = numpy.asarray(record["stable"], dtype=bool)
        self.labels = _Labels(record["labels"])
        self.at_mx = {int(i): v for i, v in record.get("at_mx", {}).items()}

    def __getitem__(self, name: str) -> numpy.ndarray:
        return self.columns[name]

    def __len__(self) -> int:
        return len(self._stable)

    def __repr__(self) -> str:
        return f"Branch({len(self)} points, columns {self.coordnames})"

    def stability(self) -> list:
        """AUTO's encoding: the end index of each run of equal stability,
        negative for stable runs."""
        return [(-s.stop if self._stable[s.start] else s.stop)
                for s in branches.runs_of(self._stable, overlap=False)]


class _Labels:
    """branch.labels of parseB, as far as branches.labelled_points reads it."""

    def __init__(self, points):
        self._at = {}
        for index, label, kind in points:
            self._at.setdefault(index, {})[kind] = {"LAB": label}

    def getIndices(self):
        return sorted(self._at)

    def __getitem__(self, index):
        return self._at[index]


def stored(diagram: Any, columns: Sequence[str],
           at_mx: Optional[Callable[[Any], float]] = None) -> list:
    """The branches of an AUTO diagram (a bifDiag or a list of branches) as
    records of the given columns (those a branch lacks are left out).
    at_mx(solution): a number of the solution at each MX point, kept as
    "at_mx" {point index: number} (why a curve stopped there can depend on
    the orbit, not only on its place in the parameters)."""
    out = []
    for b in diagram:
        record = {"columns": {c: numpy.asarray(b[c]) for c in columns if c in b.coordnames},
                  "stable": branches.stable_mask(b),
                  "labels": [list(p) for p in branches.labelled_points(b)]}
        if at_mx is not None:
            record["at_mx"] = {str(i): at_mx(b(lab))
                               for i, lab, _ in branches.labelled_points(b, "MX")}
        out.append(record)
    return out


def loaded(records: Sequence[Mapping[str, Any]]) -> list:
    """Stored branches (stored()) back as Branch objects."""
    return [Branch(r) for r in records]
