"""make sidestay RHO=<deg> MU=<deg>: the gear with side-stay angles (rho, mu).

For that geometry and for rho = mu = 0 (overlaid), at F* = 1 with the
`figures` set and the complete equations of motion (eom_terms = 2,
docs/model.md section 8; --eom-terms picks another level):
  (a, b) straight rolling in V, its Hopf points and the periodic orbits born
         there, for zero freeplay and for y_fp = 1 mm, eps = 0.1 mm
         (eps_rel = 0.1);
  (c)    the Hopf curves in (V, F*) continued from those Hopf points.
Runs go to build/sidestay_rho<deg>_mu<deg>/ (one AUTO run per b./s./d. file,
its log beside it); the numbers to build/tables/sidestay_rho<deg>_mu<deg>.txt;
the figure to build/figures/sidestay_rho<deg>_mu<deg>.png and .pdf.  The
rho = mu = 0 runs are reused while everything they depend on (eom_terms, the
model executable and library, the constants files, these drivers) is
unchanged (cache.json in their directory).  Angles outside the model's range
stop the driver before any AUTO run.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import sys
from typing import Any, Callable, Dict, List, Mapping, Optional

import matplotlib.pyplot as plt

from mlgshimmy.shared import diagrams, rundirs, runerror
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import draw
from mlgshimmy.shared import geometry
from mlgshimmy.shared import paths
from mlgshimmy.shared import jobs
from mlgshimmy.shared.jobs import depends

# What make, make help, make submit and the report know of this study
# (shared.jobs.catalogue reads it as text: literals only).
DECLARED = {
    "sidestay": {
        "usage": "sidestay RHO=10 MU=10",
        "help": "side-stay angles [deg] against rho = mu = 0 (EOM=0|1|2)",
        "time": "30 s",
        "report": {
            "command": "make sidestay RHO=10 MU=10",
            "text": "Side-stay angles against rho = mu = 0.",
            "tables": ["tables/sidestay_*.txt"],
            "figures": ["figures/sidestay_*.png"],
        },
    },
}

V_START, V_STOP = ct.V_MIN, ct.V_MAX
FSTAR_RANGE = [0.1, 3.5]
PSI_AMP_STOP = 0.2                 # rad: larger orbits approach wheel lift-off
# Orbits of the freeplay case live down to V ~ 1 m/s: small steps there.
ORBIT_STEPS = {"fp0": {}, "fp1": {"DS": 0.1, "DSMAX": 0.4, "NMX": 2000}}
# (plot label, text label, tag, parameter values)
CASES = (("zero freeplay", "zero freeplay", "fp0", {"yfp": 0.0}),
         ("$y_{fp}$ = 1 mm, $\\epsilon$ = 0.1 mm", "y_fp = 1 mm, eps = 0.1 mm", "fp1",
          {"yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.1}))
CACHE = "cache.json"
# What the rho = mu = 0 runs depend on besides eom_terms (cache key): the
# model, the constants and this driver's import closure, as make reads it.
INPUTS = [os.path.join(paths.BUILD, "models", "mlg.exe"),
          os.path.join(paths.BUILD, "lib", "libmlg.so"), ct.CONSTANTS,
          *sorted(os.path.join(ct.RUN_CONSTANTS, f) for f in os.listdir(ct.RUN_CONSTANTS)),
          *depends.closure(["mlgshimmy.studies.sidestay"])]


def name_of(rho_deg: float, mu_deg: float) -> str:
    return f"sidestay_rho{rho_deg:g}_mu{mu_deg:g}"


def case_values(rho_deg: float, mu_deg: float, eom_terms: int) -> Dict[str, Dict[str, float]]:
    """{case tag: parameter values}."""
    angles = geometry.model_angles(rho_deg, mu_deg, eom_terms)
    return {tag: {"Fstar": 1.0, **angles, **values} for _, _, tag, values in CASES}


def starts(rho_deg: float, mu_deg: float, eom_terms: int) -> Dict[str, Any]:
    """{case tag: Start}; validates every parameter set first (ValueError)."""
    return {tag: ct.Start("figures", V=V_START, **values)
            for tag, values in case_values(rho_deg, mu_deg, eom_terms).items()}


def hopf_points(rundir: str, tag: str, values: Mapping[str, float]) -> Any:
    """AUTO's HB points of straight rolling in V in [V_START, V_STOP]
    (continuation.hopf_points on a 0.2 m/s grid)."""
    return ct.hopf_points(rundir, f"hb_{tag}_", "figures", "V",
                          ct.SPEED_SCAN, **values)


def attempt(name: str, run: Callable[[], Any], notes: List[str]) -> Any:
    """run() -> diagram, run with allow_mx: a branch that ends without
    convergence (MX) is kept up to there; a run that fails gives None.  Either
    is noted."""
    try:
        bd = run()
    except runerror.RunError as exc:
        notes.append(exc.brief)
        return None
    if any(ty == "MX" for _, _, ty in diagrams.special_points(bd)):
        notes.append(f"run {name}: ends without convergence (MX), kept up to there")
    return bd


def cache_key(eom_terms: int) -> str:
    digest = hashlib.sha256(f"eom_terms={eom_terms}\n".encode())
    for path in INPUTS:
        with open(path, "rb") as f:
            digest.update(f.read())
    return digest.hexdigest()


def cached(rundir: str, key: str) -> bool:
    """True if rundir holds a complete result computed with this key."""
    try:
        with open(os.path.join(rundir, CACHE)) as f:
            return json.load(f)["key"] == key
    except (OSError, ValueError, KeyError):
        return False


def load(rundir: str) -> Dict[str, Any]:
    """compute()'s result read back from the run files cache.json lists."""
    with open(os.path.join(rundir, CACHE)) as f:
        index = json.load(f)["runs"]

    def diagram(name):
        return diagrams.read_diagram([os.path.join(rundir, f"{kind}.{name}") for kind in "bsd"],
                                     f"cached run {name} in {rundir}")
    return {tag: (diagram(entry["eq"]), [diagram(n)("HB1") for n in entry["hopf"]],
                  [diagram(n) for n in entry["orbits"]], [diagram(n) for n in entry["curves"]],
                  entry["notes"]) for tag, entry in index.items()}


def compute(rho_deg: float, mu_deg: float, eom_terms: int,
            key: Optional[str] = None) -> Dict[str, Any]:
    """{case tag: (equilibria, [HB points], [orbits], [Hopf curves], [notes])}.
    With a cache key: reuse the runs stored with that key, or compute and
    store them with it."""
    where = starts(rho_deg, mu_deg, eom_terms)
    values = case_values(rho_deg, mu_deg, eom_terms)
    path = os.path.join(paths.run_root(), name_of(rho_deg, mu_deg))
    rundir = rundirs.claim(path, keep=(lambda p: cached(p, key)) if key else None)
    if key and cached(rundir, key):
        print(f"sidestay: {name_of(rho_deg, mu_deg)}: reusing the runs in "
              f"{os.path.relpath(rundir)} (inputs unchanged)")
        return load(rundir)
    result, index = {}, {}
    for _, _, tag, _ in CASES:
        eq = ct.equilibria(rundir, f"eq_{tag}", where[tag], stop={"V": V_STOP})
        hopf = hopf_points(rundir, tag, values[tag])
        orbits, curves, notes = [], [], []
        entry = {"eq": f"eq_{tag}", "hopf": [f"hb_{tag}_{k}" for k in range(1, len(hopf) + 1)],
                 "orbits": [], "curves": []}
        for k, point in enumerate(hopf, 1):
            name = f"po_{tag}_{k}"
            orbits.append(attempt(name, lambda: ct.periodic_from(
                rundir, name, point, stop={"V": [V_START, V_STOP], "psi_amp": PSI_AMP_STOP},
                allow_mx=True, **ORBIT_STEPS[tag]), notes))
            entry["orbits"] += [name] if orbits[-1] is not None else []
            for direction, ds in (("up", 0.01), ("down", -0.01)):
                name = f"hopf_{tag}_{k}_{direction}"
                curves.append(attempt(name, lambda: ct.hopf_curve(
                    rundir, name, point, DS=ds, allow_mx=True,
                    stop={"Fstar": FSTAR_RANGE, "V": [V_START, V_STOP]}), notes))
                entry["curves"] += [name] if curves[-1] is not None else []
        result[tag] = (eq, hopf, [o for o in orbits if o is not None],
                       [c for c in curves if c is not None], notes)
        index[tag] = {**entry, "notes": notes}
    if key:  # written last, in one rename: present only beside complete runs
        jobs.write_json(os.path.join(rundir, CACHE),
                        {"key": key, "eom_terms": eom_terms, "runs": index}, indent=1)
    return result


def plot(name: str, title: str, result: Mapping[str, Any],
         reference: Optional[Mapping[str, Any]]) -> None:
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    fig.subplots_adjust(wspace=0.3)
    deg = 180.0 / math.pi
    for ax, (label, _, tag, _) in zip(axes[:2], CASES):
        for data, style in ((reference, {"color": "0.6", "lw": 1.0}), (result, {})):
            eq, hopf, orbits, _, _ = data[tag]
            draw.plot_branch(ax, eq, "V", "psi_amp", scale=deg, **style)
            for orbit in orbits:
                draw.plot_branch(ax, orbit, "V", "psi_amp", scale=deg, **style)
            for point in hopf:
                ax.plot(point["V"], 0.0, "o", ms=4, color=style.get("color", draw.NEUTRAL))
        ax.set_title(f"F* = 1, {label}")
        ax.set_xlabel("V [m/s]")
        ax.set_ylabel(r"$\psi$ amplitude [deg] (symlog)")
        ax.set_yscale("symlog", linthresh=0.05)
        ax.set_ylim(0, 20)
        ax.set_xlim(0, V_STOP)
    ax = axes[2]
    for data, width, dashes in ((reference, 1.0, "--"), (result, 1.6, "-")):
        for (label, _, tag, _), color in zip(CASES, draw.palette.CYCLE):
            for curve in data[tag][3]:
                for branch in curve:
                    ax.plot(branch["V"], branch["Fstar"], dashes, color=color, lw=width,
                            label=label if data is result else None)
                    label = None
    ax.set_xlim(0, V_STOP)
    ax.set_ylim(0, FSTAR_RANGE[1])
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel("$F_z^*$")
    ax.set_title("Hopf curves (dashed: rho = mu = 0)")
    ax.legend(fontsize=7, loc="upper right")
    draw.legend(axes[0], extra=[plt.Line2D([], [], color=draw.palette.GUIDE, lw=1.0,
                                           label="rho = mu = 0"),
                                plt.Line2D([], [], ls="", marker="o", ms=4, color=draw.NEUTRAL,
                                           label="H: Hopf point")], loc="upper left")
    draw.figure_title(fig, f"{title}; grey / dashed: rho = mu = 0")
    draw.save(fig, name)


def report(name: str, title: str, result: Mapping[str, Any],
           reference: Optional[Mapping[str, Any]]) -> None:
    """The numbers of both geometries, printed and stored as
    $MLG_RUN_ROOT/tables/<name>.txt (plain text)."""
    lines = [title]
    for tag_label, data in (("this geometry", result), ("rho = mu = 0", reference)):
        for _, label, tag, _ in CASES:
            _, hopf, orbits, curves, notes = data[tag]
            speeds = ", ".join(f"{p['V']:.3f}" for p in hopf) or "none"
            lines.append(f"{tag_label}, {label}: Hopf points at V = {speeds} m/s; "
                         f"{len(orbits)} orbit families, {len(curves)} Hopf-curve runs")
            lines += [f"  note: {note}" for note in notes]
    path = jobs.write_text(os.path.join(paths.tables_dir(), f"{name}.txt"),
                           "\n".join(lines) + "\n")
    print("\n".join(f"sidestay: {line}" for line in lines))
    print(f"sidestay: wrote {os.path.relpath(path, paths.ROOT)}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rho", type=float, required=True, help="rho [deg]")
    parser.add_argument("--mu", type=float, required=True, help="mu [deg]")
    parser.add_argument("--eom-terms", type=int, default=2, choices=(0, 1, 2),
                        help="0, 1 or 2 (default 2; make variable EOM)")
    args = parser.parse_args()
    name = name_of(args.rho, args.mu)
    title = (f"Side-stay angles rho = {args.rho:g} deg, mu = {args.mu:g} deg, "
             f"eom_terms = {args.eom_terms}")
    print(f"sidestay: {title}")
    try:
        starts(args.rho, args.mu, args.eom_terms)          # validate before any AUTO run
        key = cache_key(args.eom_terms)
        if (args.rho, args.mu) == (0.0, 0.0):
            result = reference = compute(0.0, 0.0, args.eom_terms, key)
        else:
            result = compute(args.rho, args.mu, args.eom_terms)
            reference = compute(0.0, 0.0, args.eom_terms, key)
    except ValueError as exc:
        sys.exit(f"sidestay: rho = {args.rho:g} deg, mu = {args.mu:g} deg, "
                 f"eom_terms = {args.eom_terms} rejected: {exc}")
    except (runerror.RunError, RuntimeError) as exc:
        sys.exit(f"sidestay: {exc}")
    report(name, title, result, reference)
    plot(name, title, result, reference)


if __name__ == "__main__":
    main()
