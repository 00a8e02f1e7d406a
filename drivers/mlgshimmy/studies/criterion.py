"""The allowable-freeplay criterion, eq. (17), under each low-load reading
of the model: kappa* = min over F* in [0.1, 2] of the smallest y_fp/eps at
which straight rolling is unstable for some V <= 120 m/s (eps = 0.1 mm).

    criterion.py scan GROUP   # kappa* of every assumption of GROUP
    criterion.py auto         # kappa* again by AUTO, strut variants 0 and 1
    criterion.py report       # table (printed, build/tables/criterion.txt)
                              # and build/figures/criterion.png
    criterion.py custom NAME=VALUE ...   # kappa* of your own parameters,
                              # e.g. a strut: a_keta=... eta_stage=0.2

Straight rolling depends on the freeplay only through r = y_fp/eps (the
torque-link stiffness at y = 0 is k_tlk s(r), eq. 15), so kappa* is exact
in r.  Results are cached as parts of the result cache (shared.jobs,
with their provenance): $MLG_RUN_ROOT/criterion/parts/<GROUP>.json and
auto.json (default build/).
"""
from __future__ import annotations

import os
import sys
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import matplotlib.pyplot as plt
import numpy
from numpy.typing import ArrayLike

from mlgshimmy.shared import freeplay
from mlgshimmy.shared import runerror
from mlgshimmy.shared import draw
from mlgshimmy.shared import gear
from mlgshimmy.shared import jobs
from mlgshimmy.shared import kappa_criterion
from mlgshimmy.shared import yfp_runs
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import paths

# What make, make help, make submit and the report know of this study
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "criterion": {
        "help": "eq. (17): kappa* under each low-load assumption (use -j2)",
        "time": "3 min",
        "in_figures": True,
        "report": {
            "command": "make -j2 criterion",
            "text": ("kappa* of eq. (17) under each low-load assumption (strut readings, "
                     "stage-switch position, c_psi, tyre laws at light load)."),
            "tables": ["tables/criterion.txt"],
            "figures": ["figures/criterion.png"],
        },
    },
}

VARIANTS = (0, 1)
# The one-parameter family joining the strut variants: the stage-switch
# position eta_s of the monotone spring (docs/model.md 4.15).  0.34 m is the
# printed value (variant 0 itself); eta_s -> 0 removes the soft stage, so the
# gear hangs on the 188.5 kN preload at light load as the printed order does.
STAGE_SWITCHES = (0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.34)
C_PSI = (410.0, 567.0)               # table value and halfway to `figures`
TYRE_LOADS = (15e3, 30e3, 45e3, 60e3)  # F_tyre_min [N]; 0 is the paper's laws
LOADS = kappa_criterion.CRITERION_LOADS


def base_assumption() -> Dict[str, float]:
    """The `figures` set's values of the varied assumptions (the library's c_psi)."""
    return {"c_psi": mlgmodel.C_PSI_FIGURES, "F_tyre_min": 0.0, "eta_stage": 0.34}


def assumption(group: str, x: Optional[float], variant: int, **overrides: float) -> Dict[str, Any]:
    return {"group": group, "x": x, "variant": variant,
            "overrides": {"strut_variant": float(variant), **overrides}}


GROUPS = {
    "strut": [assumption("strut", v, v) for v in VARIANTS],
    "stage": [assumption("stage", e, 0, eta_stage=e) for e in STAGE_SWITCHES[:-1]],
    "c_psi": [assumption("c_psi", c, v, c_psi=c) for v in VARIANTS for c in C_PSI],
    "tyre": [assumption("tyre", F, v, F_tyre_min=F) for v in VARIANTS for F in TYRE_LOADS],
}
AXES = {"strut": "strut variant", "stage": r"stage switch $\eta_s$ [m] (variant 0)",
        "c_psi": r"$c_\psi$ [N m s/rad]", "tyre": r"$F_{tyre,min}$ [kN]"}


def first_unstable(Fstar: float, **overrides: float) -> Dict[str, Any]:
    """At one load: the smallest y_fp [mm] with straight rolling unstable for
    some V <= V_LIMIT, that speed, and the static compression eta* [m]
    (kappa_criterion.least_unstable)."""
    return kappa_criterion.least_unstable(Fstar, **overrides)


def kappa_star(overrides: Mapping[str, float]) -> Dict[str, Any]:
    """{kappa, Fstar, V, eta, mode} at the minimum over the envelope's loads,
    for the run's gear (shared.gear) with the overrides."""
    return kappa_criterion.criterion({**overrides, **gear.parameters()})


def write(name: str, data: Any) -> None:
    """The cached part <name> (a group, or "auto") of the criterion."""
    jobs.write("criterion", data, "figures", part=name)


def read(name: str, root: Optional[str] = None, model: Any = None) -> Any:
    return jobs.read("criterion", name, root=root, model=model)


def baseline_parts() -> Dict[str, Any]:
    """{group: results} of the paper's geometry, to print beside a side-stay
    geometry's ({} at the baseline; a group not computed there is left out)."""
    if gear.current().baseline:
        return {}
    out = {}
    for group in GROUPS:
        try:
            out[group] = read(group, gear.base_root(), gear.Gear())
        except jobs.MissingResult:
            continue
    return out


def scan(group: str) -> None:
    results = []
    for item in GROUPS[group]:
        results.append({**item, **kappa_star(item["overrides"])})
        yfp_runs.progress("criterion", f"{group} {item['x']:g} (variant {item['variant']}): "
                                 f"kappa* = {results[-1]['kappa']:.4f} at F* = "
                                 f"{results[-1]['Fstar']:.3f}")
    write(group, results)


def parabola_minimum(xs: ArrayLike, ys: ArrayLike) -> Tuple[float, float]:
    """(x, y) at the vertex of the parabola through the lowest sample and its
    two neighbours (the sample itself if it is an end); xs distinct."""
    k = int(numpy.argmin(ys))
    if k == 0 or k == len(ys) - 1:
        return xs[k], ys[k]
    a, b, c = numpy.polyfit(xs[k - 1:k + 2], ys[k - 1:k + 2], 2)
    x = -b / (2 * a)
    return x, numpy.polyval([a, b, c], x)


AUTO_SPAN = 0.1   # the AUTO check's curve of a: F* this far either side of the scan's minimum


def auto_kappa(variant: int, scanned: Sequence[Mapping[str, Any]]) -> Dict[str, Any]:
    """kappa* by AUTO: the point a (a Hopf point at V = V_LIMIT) at the
    scan's least load, converged by AUTO, continued in (F*, y_fp) AUTO_SPAN
    either way, and the least y_fp along that curve (parabola_minimum).
    The curve stays off the oleo's stage switch (F* ~ 0.63-0.70), where at
    side-stay angles it stops (MX) with steps of 1e-10.  Only valid where
    the scan's minimum lies on V = V_LIMIT (checked by auto())."""
    low, high = kappa_criterion.ENVELOPE_LOADS[0], kappa_criterion.ENVELOPE_LOADS[-1]
    here = scanned["Fstar"]
    stop = (max(low, here - AUTO_SPAN), min(high, here + AUTO_SPAN))
    model = {"strut_variant": float(variant), **gear.parameters()}
    curve = yfp_runs.window_point_curve(paths.rundir(os.path.join("criterion", "auto")),
                                  f"a_v{variant}", scanned["kappa"] * freeplay.EPSILON, here, stop,
                                  dsmax=0.005, **model)
    pieces = {}
    for direction, run in curve.items():
        if isinstance(run, runerror.RunError):
            raise run
        end = stop[direction == "up"]
        if abs(run[0]["Fstar"][-1] - end) > 1e-4:   # UZ stops within AUTO's tolerance
            raise runerror.RunError(f"variant {variant}: the curve of a ended at F* = "
                                    f"{run[0]['Fstar'][-1]:.4f}, short of {end:g}")
        pieces[direction] = (numpy.asarray(run[0]["Fstar"]), numpy.asarray(run[0]["yfp"]))
    # one polyline in continuation order, from low F* to high
    F = numpy.r_[pieces["down"][0][:0:-1], pieces["up"][0]]
    y = numpy.r_[pieces["down"][1][:0:-1], pieces["up"][1]]
    Fmin, ymin = parabola_minimum(F, y)
    kappa = ymin / freeplay.EPSILON
    return {"variant": variant, "kappa": kappa, "Fstar": Fmin, "points": len(F),
            "scan": scanned["kappa"], "relative difference": kappa / scanned["kappa"] - 1}


def auto() -> None:
    """AUTO's check of each strut variant's kappa* where it applies: the
    scan's minimum on V = V_LIMIT (a point a); elsewhere (a minimum below
    the speed limit, e.g. kappa* = 0 at side-stay angles) the reason."""
    results = []
    for item in read("strut"):
        if item["V"] != yfp_runs.V_LIMIT:
            results.append({"variant": item["variant"], "scan": item["kappa"],
                            "skipped": f"the scan's minimum lies at V = {item['V']:.3f} m/s, "
                                       f"not on V = {yfp_runs.V_LIMIT:g} (no point a to continue)"})
            yfp_runs.progress("criterion", f"AUTO, variant {item['variant']}: no check: "
                                     f"{results[-1]['skipped']}")
            continue
        results.append(auto_kappa(item["variant"], item))
        yfp_runs.progress("criterion", f"AUTO, variant {item['variant']}: kappa* = "
                                 f"{results[-1]['kappa']:.4f} at F* = {results[-1]['Fstar']:.3f} "
                                 f"(scan {item['kappa']:.4f})")
    write("auto", results)


def label(item: Mapping[str, Any]) -> str:
    if item["group"] == "strut":
        return f"strut variant {item['variant']}"
    unit = {"stage": " m", "c_psi": " N m s/rad", "tyre": " N"}[item["group"]]
    name = {"stage": "eta_s", "c_psi": "c_psi", "tyre": "F_tyre_min"}[item["group"]]
    return f"{name} = {item['x']:g}{unit}, variant {item['variant']}"


def lines(groups: Mapping[str, Any]) -> Dict[str, Dict[int, List[Tuple[float, Any]]]]:
    """{group: {variant: [(x, result)]}} sorted in x; the groups that vary
    one value of the base assumption get its point from the strut group."""
    base = {item["variant"]: item for item in groups["strut"]}
    varied = {"c_psi": "c_psi", "tyre": "F_tyre_min", "stage": "eta_stage"}
    out = {}
    for group, items in groups.items():
        by_variant = {}
        for item in items:
            by_variant.setdefault(item["variant"], []).append((item["x"], item))
        if group in varied:
            for v in by_variant:
                by_variant[v].append((base_assumption()[varied[group]], base[v]))
        out[group] = {v: sorted(pts, key=lambda t: t[0]) for v, pts in by_variant.items()}
    return out


def plot(groups: Mapping[str, Any]) -> None:
    # kappa* above, the strut compression at its minimum below: one quantity an axis
    fig, axes = plt.subplots(2, 4, figsize=(13, 6.2), sharex="col")
    colours = {0: draw.STABLE, 1: draw.UNSTABLE}
    for top, low, (group, by_variant) in zip(axes[0], axes[1], lines(groups).items()):
        for v, pts in by_variant.items():
            xs = [x / (1e3 if group == "tyre" else 1.0) for x, _ in pts]
            top.plot(xs, [p["kappa"] for _, p in pts], "o-", color=colours[v],
                     label=draw.STRUT_ORDER[v])
            low.plot(xs, [p["eta"] for _, p in pts], "s-", color=colours[v], ms=3)
        top.set(ylim=(0, 0.45))
        low.set(xlabel=AXES[group], ylim=(0, 0.45))
        if group == "strut":
            low.set(xticks=VARIANTS, xlim=(-0.5, 1.5))
    axes[0][0].set_ylabel(r"$\kappa^*$")
    axes[1][0].set_ylabel(r"$\eta^*$ at the minimum [m]")
    axes[0][0].legend(fontsize=7, loc="upper right")
    fig.suptitle(r"Allowable freeplay $y_{fp}/\epsilon < \kappa^*$ (eq. 17: $V \leq$ 120 m/s, "
                 r"$F^* \leq$ 2) under each low-load assumption")
    fig.tight_layout()
    draw.save(fig, "criterion")


def report() -> None:
    groups = {group: read(group) for group in GROUPS}
    checks = read("auto")
    base = baseline_parts()
    rows = [f"{'assumption':44s} {'kappa*':>8s} {'at F*':>7s} {'V [m/s]':>8s} {'eta* [m]':>9s}"
            f"  mode" + ("      baseline kappa*" if not gear.current().baseline else "")]
    for group, items in groups.items():
        for k, item in enumerate(items):
            beside = ""
            if not gear.current().baseline:
                there = base.get(group)
                beside = f"  {there[k]['kappa']:19.4f}" if there else f"  {'-':>19s}"
            rows.append(f"{label(item):44s} {item['kappa']:8.4f} {item['Fstar']:7.3f} "
                        f"{item['V']:8.2f} {item['eta']:9.5f}  {str(item['mode']):4s}{beside}")
    if any(item["kappa"] == 0 for items in groups.values() for item in items):
        rows.append("kappa* = 0: straight rolling is unstable there without freeplay (the "
                    "mode, at that load and speed): no freeplay is allowable")
    rows.append("")
    rows.append("two methods (eigenvalue scan in r; AUTO's curve of a in F* at V = 120):")
    for c in checks:
        if "skipped" in c:
            rows.append(f"  variant {c['variant']}: scan {c['scan']:.5f}, no AUTO check: "
                        f"{c['skipped']}")
            continue
        rows.append(f"  variant {c['variant']}: scan {c['scan']:.5f}, AUTO {c['kappa']:.5f} "
                    f"at F* = {c['Fstar']:.4f} ({c['points']} points), relative difference "
                    f"{c['relative difference']:+.2e}")
    if not gear.current().baseline:
        rows.insert(0, f"at {gear.describe()}")
    text = "\n".join(rows)
    print(text)
    jobs.write_text(os.path.join(paths.tables_dir(), "criterion.txt"), text + "\n")
    plot(groups)
    worst = max((abs(c["relative difference"]) for c in checks if "skipped" not in c),
                default=0.0)
    if worst > 0.01:
        sys.exit(f"criterion: the two methods differ by {worst:.2%} (more than 1 %)")


def custom(assignments: Sequence[str]) -> None:
    """kappa* with parameters or constants set by name (NAME=VALUE)."""
    overrides = {}
    for text in assignments:
        name, sep, value = text.partition("=")
        try:
            overrides[name] = float(value) if sep else None
        except ValueError:
            overrides[name] = None
        if overrides[name] is None:
            raise ValueError(f"{text!r}: expected NAME=VALUE with a number")
    try:
        mlgmodel.Model("figures", **overrides, **gear.parameters()).check()
    except KeyError as exc:
        raise ValueError(f"unknown parameter: {exc}") from exc
    result = kappa_star(overrides)
    print(f"kappa* = {result['kappa']:.4f} at F* = {result['Fstar']:.3f}, V = {result['V']:.2f} "
          f"m/s, eta* = {result['eta']:.5f} m, mode {result['mode']}")


def main(argv: Sequence[str]) -> None:
    try:
        if argv[:1] == ["scan"] and len(argv) == 2 and argv[1] in GROUPS:
            scan(argv[1])
        elif argv == ["auto"]:
            auto()
        elif argv == ["report"]:
            report()
        elif argv[:1] == ["custom"]:
            custom(argv[1:])
        else:
            sys.exit(f"usage: criterion.py scan {{{','.join(GROUPS)}}} | auto | report | "
                     "custom NAME=VALUE ...")
    except (runerror.RunError, ValueError, RuntimeError) as exc:
        sys.exit(f"criterion: {exc}")


if __name__ == "__main__":
    main(sys.argv[1:])
