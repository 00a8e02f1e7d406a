"""One labelled point of any diagram, looked at: its orbit profile, its
phase portrait, its Floquet multipliers (an equilibrium's eigenvalues) and
a time series from it.

    make point RUN=build/fig10/po3 LABEL=5        # any run directory's b-, s-, d-files
    python3 -m mlgshimmy.studies.point_view build/fig10/po3 5 [--plot]

Reads the solution of the label (AUTO's s-file) and its multipliers as AUTO
computed them (the d-file, shared.floquet), then simulates from it
(shared.simulator, its PAR and its run's constants file): PERIODS periods
of an orbit started on it, or EQUILIBRIUM_SPAN seconds of an equilibrium
with psi displaced by KICK, so that the time series shows whether the
point attracts.  Cached as point_<run>_<label> (the run's path under the
run root), drawn to $MLG_RUN_ROOT/figures/point_<run>_<label>.png.
"""
from __future__ import annotations

import argparse
import os
import sys
from typing import Any, List, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import diagrams, floquet, jobs, mlgmodel, paths, simulator

# What make help and make submit know of it (shared.jobs.catalogue)
DECLARED = {
    "point": {
        "usage": "point RUN=<dir>/<run> LABEL=<n>",
        "help": "one labelled point: orbit profile, phase portrait, multipliers, simulation",
        "time": "5 s",
        "carries": ["RUN", "LABEL"],
    },
}

PERIODS = 40            # periods of an orbit simulated from its first point
EQUILIBRIUM_SPAN = 5.0  # s simulated from an equilibrium
KICK = 1e-4             # rad added to an equilibrium's psi
SAMPLES_PER_PERIOD = 60


def run_files(run: str) -> Tuple[str, str, List[str]]:
    """(run directory, run name, [b, s, d] paths); ValueError naming RUN."""
    where, name = os.path.split(os.path.abspath(run))
    files = [os.path.join(where, f"{kind}.{name}") for kind in "bsd"]
    missing = [f for f in files if not os.path.isfile(f)]
    if missing:
        raise ValueError(f"RUN={run}: no {os.path.relpath(missing[0], paths.ROOT)} (a run "
                         "directory and run name, e.g. RUN=build/fig10/po3 after make fig10)")
    return where, name, files


def parameters(sol: Any, where: str) -> dict:
    """The model parameters of a solution: its PAR and the constants of its
    run's file mlg.constants.<k> (PAR(15) = k; shared.mlgmodel)."""
    names = [n for n in mlgmodel.PARNAMES if n and n != mlgmodel.CONSTANTS_FILE]
    values = {n: float(sol.PAR[n]) for n in names}
    k = int(sol.PAR[mlgmodel.CONSTANTS_FILE])
    if k:
        with open(os.path.join(where, f"mlg.constants.{k}")) as f:
            values.update((n, float(v)) for n, v in (line.split() for line in f
                                                     if line.strip() and not line.startswith("#")))
    return values


def compute(run: str, label: int) -> dict:
    where, name, files = run_files(run)
    diagram = diagrams.read_diagram(files, f"point: {run}")
    labels = [int(s["LAB"]) for s in diagram()]
    if label not in labels:
        raise ValueError(f"LABEL={label} is not a label of {run} (its labels: "
                         f"{', '.join(map(str, labels))})")
    sol = diagram(label)
    values = parameters(sol, where)
    t = numpy.asarray(sol["t"], dtype=float)
    states = {n: numpy.asarray(sol[n], dtype=float).tolist() for n in mlgmodel.UNAMES}
    orbit = len(t) > 1
    if orbit:
        period = float(sol.PAR["T"])
        mults = floquet.read_points(files[2]).get(abs(int(sol["PT"])), (None, numpy.array([])))[1]
        span, dt, psi0 = PERIODS * period, period / SAMPLES_PER_PERIOD, 0.0
    else:
        period = 0.0
        model = mlgmodel.Model("figures", **values)
        mults = numpy.linalg.eigvals(model.jacobian({n: states[n][0] for n in mlgmodel.UNAMES}))
        span, dt, psi0 = EQUILIBRIUM_SPAN, 1e-3, KICK
    csv = os.path.join(paths.rundir(f"point_{name}_{label}"), "series.csv")
    start = {n: states[n][0] for n in mlgmodel.UNAMES}
    proc = simulator.run(csv, "--set", "figures", "--t-end", span, "--dt-out", dt,
                         "--psi0", psi0, *simulator.state_args(start),
                         params={n: repr(v) for n, v in values.items()})
    if proc.returncode != 0 and simulator.left_domain(proc) is None:
        raise simulator.SimulationError(f"mlg_simulate failed: {proc.stderr.strip()}")
    series = numpy.genfromtxt(csv, delimiter=",", names=True)
    return {"run": os.path.relpath(os.path.join(where, name), paths.ROOT), "label": label,
            "type": str(sol["TY name"]), "V": values["V"], "Fstar": values["Fstar"],
            "yfp": values["yfp"], "period": period, "t": t.tolist(), "states": states,
            "multipliers": {"re": numpy.real(mults).tolist(), "im": numpy.imag(mults).tolist()},
            "series": {"t": series["t"].tolist(), "psi": series["psi"].tolist(),
                       "delta": series["delta"].tolist()},
            "left_domain": simulator.left_domain(proc)}


def plot(result: dict, name: str) -> None:
    import matplotlib.pyplot as plt

    from mlgshimmy.shared import draw
    deg = draw.DEG
    orbit = result["period"] > 0
    s = {k: numpy.asarray(v) for k, v in result["states"].items()}
    fig, ((profile, phase), (spectrum, series)) = plt.subplots(2, 2, figsize=(10, 7.5))
    if orbit:
        for key, style in (("psi", draw.STABLE_STYLE), ("delta", {"color": draw.NEUTRAL})):
            profile.plot(result["t"], deg * s[key], lw=1.4, label=rf"$\{key}$", **style)
        profile.set(xlabel="t / T", ylabel="[deg]",
                    title=f"(a) orbit profile over one period, T = {1e3 * result['period']:.4g} ms")
        profile.legend(loc="upper right")
        phase.plot(deg * s["psi"], deg * s["psi_dot"], **draw.STABLE_STYLE)
        phase.set(xlabel=r"$\psi$ [deg]", ylabel=r"$\dot\psi$ [deg/s]",
                  title="(b) phase portrait")
    else:
        profile.text(0.5, 0.5, "an equilibrium: no profile", ha="center", va="center",
                     transform=profile.transAxes)
        profile.set(xticks=[], yticks=[], title="(a) orbit profile")
        phase.plot(deg * s["psi"], deg * s["delta"], "o", color=draw.STABLE)
        phase.set(xlabel=r"$\psi$ [deg]", ylabel=r"$\delta$ [deg]", title="(b) the state")
    mult = numpy.asarray(result["multipliers"]["re"]) + 1j * numpy.asarray(
        result["multipliers"]["im"])
    if orbit:
        circle = numpy.exp(1j * numpy.linspace(0, 2 * numpy.pi, 361))
        spectrum.plot(circle.real, circle.imag, color=draw.NEUTRAL, lw=0.8)
        spectrum.set(aspect="equal", title="(c) Floquet multipliers (AUTO's d-file)",
                     xlabel="Re", ylabel="Im")
        outside = numpy.abs(mult) > 1 + 1e-5
    else:
        spectrum.axvline(0.0, color=draw.NEUTRAL, lw=0.8)
        spectrum.set(title="(c) eigenvalues of the Jacobian", xlabel="Re [1/s]",
                     ylabel="Im [1/s]")
        outside = mult.real > 0
    spectrum.plot(mult.real[~outside], mult.imag[~outside], "o", color=draw.STABLE,
                  label="stable")
    spectrum.plot(mult.real[outside], mult.imag[outside], "s", color=draw.UNSTABLE,
                  label="unstable")
    spectrum.legend(loc="upper left", fontsize="small")
    t = numpy.asarray(result["series"]["t"])
    series.plot(t, deg * numpy.asarray(result["series"]["psi"]), color=draw.STABLE, lw=0.6)
    if orbit:
        for edge in (s["psi"].min(), s["psi"].max()):
            series.axhline(deg * edge, color=draw.UNSTABLE, ls="--", lw=0.9)
    what = "the orbit's ψ range dashed" if orbit else f"ψ displaced by {KICK:g} rad"
    series.set(xlabel="t [s]", ylabel=r"$\psi$ [deg]",
               title="(d) simulated from it (" + what + ")"
               + (" - a wheel lifts off" if result["left_domain"] else ""))
    for ax in (profile, phase, spectrum, series):
        ax.grid(alpha=0.3)
    draw.figure_title(fig, f"{result['run']}, label {result['label']} ({result['type']}): "
                           f"V = {result['V']:.6g} m/s, F* = {result['Fstar']:.4g}, "
                           f"y_fp = {result['yfp']:g} mm")
    fig.tight_layout()
    draw.save(fig, name)


def main(argv: Optional[Sequence[str]] = None) -> None:
    parser = argparse.ArgumentParser(prog="python3 -m mlgshimmy.studies.point_view",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("run", help="<run directory>/<run name>, e.g. build/fig10/po3")
    parser.add_argument("label", help="a label of the run's b-file")
    parser.error = lambda message: sys.exit(f"point: {message}")    # one line
    args, rest = parser.parse_known_args(argv)
    try:
        label = int(args.label)
        where, run_name, _ = run_files(args.run)
    except ValueError as exc:
        sys.exit(f"point: {exc}" if "RUN=" in str(exc) else
                 f"point: LABEL={args.label} is not a whole number")
    tag = os.path.relpath(os.path.join(where, run_name), paths.run_root()).replace(os.sep, "_")
    name = f"point_{tag}_{label}"
    jobs.run_figure(name, lambda: compute(args.run, label), lambda result: plot(result, name),
                    argv=rest, module="mlgshimmy.studies.point_view")


if __name__ == "__main__":
    main()
