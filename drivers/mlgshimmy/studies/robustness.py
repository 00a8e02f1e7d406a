"""Robustness of the answers to a changed model: one parameter at a time
at x0.8, x0.9, x1.1 and x1.2 of its value, every target made for that gear
(`make <target> SET='<name>=<value>'`, shared.gear), and kappa* (eq. 17,
kappa_criterion.criterion).  A job completes when every target does with every
named point reported (a point that no longer exists is reported as
vanished; one whose branch could not be followed is not).

Each job is one variation, $MLG_RUN_ROOT/robustness/<name>_x<factor>/
result.json, its make output in make.log there; the targets' results live
in each gear's own tree (build/gear/<tag>/), so a later `make fig10
SET=...` reuses them.  The job "baseline_x1" is the gear itself.

  check    [--parameters L --factors L]   validate every variation
  targets | jobs [--missing] | status      as every job grid (shared.jobs.grid)
  job NAME                                 one variation
  summary                                  the completion fraction and the
                                           sensitivity table tables/robustness.txt

`make -j2 robustness` runs check, every job, summary; `make robustness
ROBUST_PARAMETERS=k_tlk ROBUST_FACTORS=0.9,1.1` a part of it.
"""
from __future__ import annotations

import os
import subprocess
import time
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

from mlgshimmy.shared import children, gear, mlgmodel, overlay, paths
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared.jobs import grid as jobgrid
from mlgshimmy.shared.jobs.atomic import write_text

# What make, make help, make submit and the report know of this study
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "robustness": {
        "help": "each parameter x0.8-1.2: what moves, and does every figure complete (-j2)",
        "time": "45 min",
        "grid": "ROBUST_ARGS",
        "report": {
            "command": "make -j2 robustness",
            "text": ("Each parameter scaled by 0.8-1.2: what moves (H1-H3, S, V_crit, kappa*) "
                     "and whether every figure still completes."),
            "tables": ["tables/robustness.txt"],
            "figures": [],
        },
    },
}

PARAMETERS = ("k_tlk", "c_psi", "I_psi", "k_beta", "c_beta", "M", "I_0",
              "a4_F", "a3_M", "a4_M", "l_tlk", "a_tlk", "b_tlk")
FACTORS = "0.8,0.9,1.1,1.2"
TARGETS = ("fig07", "fig09", "fig10", "fig12")
BASELINE = "baseline"
# the named points of the sensitivity table: (target, quantity in its numbers)
SENSITIVITY = (("fig10", "V_crit (zero freeplay) [m/s]"), ("fig10", "H1 [m/s]"),
               ("fig10", "H2 [m/s]"), ("fig10", "H3 [m/s]"), ("fig10", "S1 [m/s]"),
               ("criterion", "kappa*"))
UNFOLLOWED = "stops (MX"


class Variations(jobgrid.Plane):
    """Jobs named <parameter>_x<factor> (BASELINE_x1: the gear itself)."""

    def name(self, a: str, b: float) -> str:
        return f"{a}_x{b:g}"

    def parse(self, name: str) -> Tuple[str, float]:
        a, sep, b = name.rpartition("_x")
        if not sep or (a not in PARAMETERS and a != BASELINE):
            raise ValueError(f"not a variation <parameter>_x<factor>: {name!r}")
        return a, float(b)


def settings() -> Dict[str, Any]:
    return {"targets": list(TARGETS), "gear": gear.current().record()}


JOBS = Variations("parameter", "factor", "robustness", "figures", settings, noun="variations")


def grid(args: Any) -> List[Tuple[str, float]]:
    names = [n for n in args.parameters.replace(",", " ").split()]
    for name in names:
        if name not in PARAMETERS:
            overlay.parse(f"{name}=1")       # "did you mean" for a misspelt name
            raise jobgrid.GridError(f"ROBUST_PARAMETERS: {name} is not varied by the suite "
                                    f"(it varies {', '.join(PARAMETERS)})")
        if name in dict(gear.current().overlay):
            raise jobgrid.GridError(f"ROBUST_PARAMETERS: {name} is set by SET already")
    factors = jobgrid.axis(args.factors, "ROBUST_FACTORS (--factors)", "factors")
    if any(f <= 0 for f in factors):
        raise jobgrid.GridError(f"ROBUST_FACTORS={args.factors!r}: factors must be > 0")
    return [(BASELINE, 1.0)] + [(n, f) for n in names for f in factors if f != 1.0]


def varied(name: str, factor: float) -> gear.Gear:
    """The gear of a variation: this process's, with name at factor times
    its value there ({} for the baseline)."""
    if name == BASELINE:
        return gear.current()
    value = factor * mlgmodel.Model("figures", **gear.parameters())[name]
    base = gear.current()
    return gear.Gear(base.geometry, base.overlay + ((name, value),))


def problem(point: Tuple[str, float]) -> Optional[str]:
    """Why the variation (parameter, factor) cannot be run, or None."""
    name, factor = point
    try:
        mlgmodel.Model("figures", **varied(name, factor).parameters()).check()
    except ValueError as exc:
        return f"{name} x{factor:g}: {exc}"
    return None


def make_target(target: str, model: gear.Gear, log: str) -> Tuple[int, float]:
    """`make <target>` for the gear `model` (its output appended to log):
    (exit status, seconds)."""
    g = model.geometry
    args = [f"SET={overlay.text(model.overlay)}"] if model.overlay else []
    if not g.baseline:
        args += [f"RHO={g.rho_deg!r}", f"MU={g.mu_deg!r}", f"EOM={g.eom_terms}"]
    env = {k: v for k, v in os.environ.items()
           if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL", "MLG_SET", "MLG_RHO_DEG",
                        "MLG_MU_DEG", "MLG_EOM")}
    env["MLG_RUN_ROOT"] = gear.base_root()
    children.stop_with_this_process()     # a stopped job stops its make too
    started = time.monotonic()
    with open(log, "a") as out:
        status = subprocess.run(["make", "--no-print-directory", target, *args], cwd=paths.ROOT,
                                env=env, stdout=out, stderr=subprocess.STDOUT).returncode
    return status, round(time.monotonic() - started, 1)


def numbers_of(target: str, model: gear.Gear) -> Optional[Dict[str, float]]:
    """The named points of a target's result made for `model` (None if none)."""
    from mlgshimmy.shared import jobs
    root = gear.tree(gear.base_root(), model)
    try:
        data = jobs.read(target, root=root, model=model)
    except (jobs.MissingResult, jobs.BadResult):
        return None
    numbers = data.get("numbers") if isinstance(data, dict) else None
    return {q: v for q, v in (numbers or {}).items() if isinstance(v, (int, float))}


def run_job(name: str) -> None:
    parameter, factor = JOBS.parse(name)
    model = varied(parameter, factor)
    where = paths.rundir(os.path.join("robustness", name))
    log = os.path.join(where, "make.log")
    write_text(log, f"robustness {name}: {model.describe() or 'the paper gear'}\n")
    out = {"parameter": parameter, "factor": factor, "gear": model.record(), "targets": {}}
    for target in TARGETS:
        status, seconds = make_target(target, model, log)
        numbers = numbers_of(target, model) if status == 0 else None
        lost = [q for q in numbers or {} if UNFOLLOWED in q]
        out["targets"][target] = {"status": status, "seconds": seconds, "numbers": numbers,
                                  "complete": status == 0 and numbers is not None and not lost}
        print(f"robustness: {name}: {target} "
              + ("complete" if out["targets"][target]["complete"] else
                 f"INCOMPLETE (exit {status}{'; not followed: ' + ', '.join(lost) if lost else ''}; "
                 f"{log})") + f" in {seconds:g} s", flush=True)
    started = time.monotonic()
    try:
        kappa = kappa_criterion.criterion(model.parameters())["kappa"]
        done = True
    except (RuntimeError, ValueError) as exc:
        kappa, done = None, False
        print(f"robustness: {name}: kappa* failed: {exc}", flush=True)
    out["targets"]["criterion"] = {"status": 0 if done else 1, "complete": done,
                                   "seconds": round(time.monotonic() - started, 1),
                                   "numbers": {"kappa*": kappa} if done else None}
    out["complete"] = all(t["complete"] for t in out["targets"].values())
    JOBS.write(parameter, factor, out)


def _cell(value, base):
    if value is None:
        return "vanished" if base is not None else "-"
    if base in (None, 0):
        return f"{value:.4g}"
    return f"{value:.4g} ({(value - base) / base:+.1%})"


def summary(points: Sequence[Tuple[str, float]], results: Sequence[Mapping[str, Any]],
            provenance: Optional[Mapping[str, Any]]) -> None:
    complete = sum(r["complete"] for r in results)
    runs = [t for r in results for t in r["targets"].values()]
    lines = [f"robustness: {complete} of {len(results)} variations complete with every named "
             f"point ({sum(t['complete'] for t in runs)} of {len(runs)} target runs)"]
    base = next(r for r in results if r["parameter"] == BASELINE)

    def value(result, target, quantity):
        numbers = result["targets"].get(target, {}).get("numbers") or {}
        return numbers.get(quantity)
    head = ["variation"] + [q.replace(" [m/s]", "").replace(" (zero freeplay)", "")
                            for _, q in SENSITIVITY]
    rows = [head]
    for result in results:
        label = BASELINE if result["parameter"] == BASELINE else \
            f"{result['parameter']} x{result['factor']:g}"
        rows.append([label] + [_cell(value(result, t, q), None if result is base
                                     else value(base, t, q)) for t, q in SENSITIVITY])
    widths = [max(len(row[k]) for row in rows) for k in range(len(head))]
    lines += ["  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip() for row in rows]
    lines.append("speeds in m/s; in brackets the change against the baseline row; kappa* "
                 "by eq. (17), kappa_criterion.criterion")
    for result in results:
        for target, t in result["targets"].items():
            if not t["complete"]:
                lines.append(f"incomplete: {result['parameter']} x{result['factor']:g}, "
                             f"{target} (exit {t['status']}): robustness/"
                             f"{JOBS.name(result['parameter'], result['factor'])}/make.log")
    text = "\n".join(lines) + "\n"
    write_text(os.path.join(paths.tables_dir(), "robustness.txt"), text)
    print(text, end="")


def main() -> None:
    jobgrid.main("robustness", __doc__.splitlines()[0], "job", JOBS,
                 [("--parameters", ",".join(PARAMETERS), "parameters varied, comma-separated"),
                  ("--factors", FACTORS, "factors of each, comma-separated")],
                 grid, run_job=run_job, problem=problem, summary=summary)


if __name__ == "__main__":
    main()
