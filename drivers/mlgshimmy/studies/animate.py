"""The gear's motion at one (V, F*), animated: what a mode looks like.

    make animate V=300 FSTAR=1 [START=shimmy|rolling|yawed] [YFP=1] [RHO= MU= SET=]
    python3 -m mlgshimmy.studies.animate --V 300 --Fstar 1 [--start shimmy] [--plot]
    make fig11-motion     # one animation per kind of attractor of Fig. 11
    python3 -m mlgshimmy.studies.animate --fig11   # its cases: "V F* start" lines

Simulates from straight rolling with psi displaced by 1e-4 rad (START=rolling)
or 0.05 rad (shimmy), or from the yawed stationary state (yawed), with y_fp = YFP mm and eps = 0.1 y_fp,
at the gear of the run (RHO, MU, SET), and caches what it settled on
(shared.motion: its kind, the frames of its last periods).  Then draws
$MLG_RUN_ROOT/figures/animate_<case>.gif (and .mp4 where ffmpeg is
installed) and a contact sheet of eight frames, animate_<case>_frames.png:
the plan and front views of the strut, axle and both wheels with their
contact patches, the torque-link apex in its freeplay gap at true scale,
and psi over time.  The factors that scale the motion are printed on every
frame.

--fig11 chooses one case per kind of attractor in Fig. 11's cached region
map (straight rolling, low- and high-frequency shimmy, quasi-periodic
shimmy, yawed rolling: shared.regions.representatives, the point deepest
inside the region where it is alone, else where it coexists, with the start
that reaches it), prints them for make and lists them in
$MLG_RUN_ROOT/figures/fig11_motion.json, which the report links from Fig. 11.
"""
import argparse
import json
import os
import shutil
import sys
from typing import Dict, List, Optional, Sequence

import numpy

from mlgshimmy.shared import freeplay, gear, motion, paths, regions
from mlgshimmy.shared import jobs
from mlgshimmy.shared.overlay import value_text
from mlgshimmy.shared.suggest import did_you_mean

# What make help, make submit and the report know of it (shared.jobs.catalogue)
DECLARED = {
    "animate": {
        "usage": "animate V=300 FSTAR=1",
        "help": "the gear's motion there, animated (GIF; MP4 with ffmpeg); START, YFP",
        "time": "30 s",
        "carries": ["V", "FSTAR", "START", "YFP"],
        "report": {
            "command": "make animate V=300 FSTAR=1",
            "text": ("The gear's motion at one speed and load, animated from the time "
                     "simulator: one per `make animate` made (docs/motion.md)."),
            "tables": [],
            "figures": ["figures/animate_*.gif"],
        },
    },
}

T_END = 40.0            # s simulated (the atlas's first stage)
FPS = 15
FIG11_CASES = "fig11_motion.json"


def case(V: float, Fstar: float, start: str, yfp: float) -> str:
    """The cached result's and the files' name: what the case is."""
    return f"animate_V{value_text(V)}_F{value_text(Fstar)}_yfp{value_text(yfp)}_{start}"


def compute(V: float, Fstar: float, start: str, yfp: float) -> dict:
    rundir = paths.rundir(case(V, Fstar, start, yfp))
    case_freeplay = {**freeplay.NOMINAL, "yfp": yfp}
    result = motion.settle(V, Fstar, case_freeplay, start, T_END, rundir)
    result.update(V=V, Fstar=Fstar, start=start)
    return result


def title(result: dict) -> str:
    hz = result["frequency_hz"]
    what = result["about"] + (f", {hz:.3g} Hz" if hz and result["kind"] not in
                              ("straight", "yaw") else "")
    at = gear.suffix().strip()   # the gear on a line of its own: a frame of the contact
    return (f"{what}\nV = {result['V']:g} m/s, F* = {result['Fstar']:g}, "   # sheet is narrow
            f"y_fp = {1e3 * result['yfp_m']:g} mm (start: {result['start']})"
            + (f"\n{at}" if at else ""))


def plot(result: dict, name: str) -> None:
    import matplotlib.pyplot as plt
    from matplotlib import animation

    from mlgshimmy.shared.draw import gear_motion
    scale = motion.scales(result["frames"])
    count = len(result["frames"]["t"])
    span = result["frames"]["t"][-1] - result["frames"]["t"][0]
    slowed = (count / FPS) / span if span > 0 else None
    lines = title(result).split("\n")
    lines[1] += f", slowed ×{slowed:.3g}" if slowed else ""
    head = "\n".join(lines)
    out = paths.figures_dir()
    os.makedirs(out, exist_ok=True)
    fig, show = gear_motion.figure(result, scale, head)
    movie = animation.FuncAnimation(fig, show, frames=count, interval=1000 / FPS)
    written = []
    for ext, writer in (("gif", animation.PillowWriter(fps=FPS)),
                        ("mp4", animation.FFMpegWriter(fps=FPS) if shutil.which("ffmpeg")
                         else None)):
        if writer is None:
            continue
        target = os.path.join(out, f"{name}.{ext}")
        partial = f"{target}.partial.{ext}"
        movie.save(partial, writer=writer, dpi=64)
        os.replace(partial, target)
        written.append(target)
    plt.close(fig)
    sheet = os.path.join(out, f"{name}_frames.png")
    fig, show = gear_motion.figure(result, scale, head)
    fig.set_dpi(60)
    _contact_sheet(fig, show, count, sheet)
    written.append(sheet)
    print(f"{name}: {result['about']} (frequency {result['frequency_hz']:.4g} Hz, psi amplitude "
          f"{result['amplitude_rad']:.4g} rad); angles x{scale['angle']:g}, tyre deflections "
          f"x{scale['deflection']:g}; wrote "
          + ", ".join(os.path.relpath(p, paths.ROOT) for p in written)
          + ("" if shutil.which("ffmpeg") else " (no MP4: ffmpeg is not installed)"))


def _contact_sheet(fig, show, count: int, target: str, across: int = 4, down: int = 2) -> None:
    """across x down frames of the animation, evenly spaced, as one PNG."""
    import matplotlib.pyplot as plt
    import numpy
    shots = []
    for k in numpy.linspace(0, count, across * down, endpoint=False).astype(int):
        show(int(k))
        fig.canvas.draw()
        shots.append(numpy.array(fig.canvas.buffer_rgba())[..., :3])   # a copy: the
        # canvas's buffer is drawn over by the next frame
    plt.close(fig)
    rows = [numpy.concatenate(shots[r * across:(r + 1) * across], axis=1) for r in range(down)]
    sheet = numpy.concatenate(rows, axis=0)
    partial = f"{target}.partial.png"
    plt.imsave(partial, sheet)
    os.replace(partial, target)


def fig11_cases(yfp: float = freeplay.NOMINAL["yfp"]) -> List[Dict[str, object]]:
    """[{"kind", "V", "Fstar", "start", "alone", "name"}]: one case per kind
    of attractor in Fig. 11's cached region map (regions.representatives),
    "name" the animation's (case())."""
    region = jobs.read("fig11")["region_map"]
    chosen = regions.representatives(numpy.asarray(region["V"]), numpy.asarray(region["Fstar"]),
                                     numpy.asarray(region["code"]))
    return [{"kind": kind, "V": c["x"], "Fstar": c["y"], "start": c["start"],
             "alone": c["alone"], "name": case(c["x"], c["y"], c["start"], yfp)}
            for kind, c in chosen.items()]


def write_fig11_cases() -> None:
    """Print fig11_cases() as "V F* start" lines (for make) and list them in
    figures/fig11_motion.json."""
    cases = fig11_cases()
    jobs.write_json(os.path.join(paths.figures_dir(), FIG11_CASES), cases, indent=1)
    for c in cases:
        print(f"{c['V']:g} {c['Fstar']:g} {c['start']}")


def main(argv: Optional[Sequence[str]] = None) -> None:
    parser = argparse.ArgumentParser(prog="python3 -m mlgshimmy.studies.animate",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--V", type=float, help="forward speed [m/s]")
    parser.add_argument("--Fstar", type=float, help="load F*")
    parser.add_argument("--fig11", action="store_true",
                        help="print one case per kind of attractor of Fig. 11's regions")
    parser.add_argument("--start", default="shimmy",
                        help="straight rolling with psi + 1e-4 rad (rolling) or + 0.05 rad "
                             "(shimmy), or the yawed stationary state (yawed)")
    parser.add_argument("--yfp", type=float, default=freeplay.NOMINAL["yfp"],
                        help="torque-link freeplay [mm] (eps = 0.1 y_fp)")
    parser.add_argument("--near", action="store_true",
                        help="with --start yawed: at the load nearest FSTAR that has a yawed "
                             "state (make gear: a gear has them at its own loads)")
    parser.error = lambda message: sys.exit(f"animate: {message}")     # one line
    args, rest = parser.parse_known_args(argv)
    if args.fig11:
        try:
            write_fig11_cases()
        except (jobs.MissingResult, jobs.BadResult) as exc:
            sys.exit(f"animate: --fig11 needs Fig. 11's cached result: {exc}")
        return
    if args.V is None or args.Fstar is None:
        parser.error("give V and FSTAR (--V, --Fstar), or --fig11")
    for option, value in (("V", args.V), ("FSTAR", args.Fstar), ("YFP", args.yfp)):
        if not value >= 0 or value == float("inf"):
            sys.exit(f"animate: {option}={value:g} must be a finite number >= 0")
    if args.start not in motion.STARTS:
        sys.exit(f"animate: START={args.start!r} is not one of {', '.join(motion.STARTS)}"
                 f"{did_you_mean(args.start, motion.STARTS)}")
    if args.near and args.start == "yawed":
        load = motion.yawed_load(args.Fstar, {**freeplay.NOMINAL, "yfp": args.yfp})
        if load is None:
            print(f"animate: this gear has no yawed stationary state at any load "
                  f"{motion.YAWED_LOADS[0]:g}-{motion.YAWED_LOADS[-1]:g}: no yawed motion to "
                  "animate", flush=True)
            return
        if load != args.Fstar:
            print(f"animate: no yawed state at F* = {args.Fstar:g}; the nearest load with one "
                  f"is {load:g}", flush=True)
        args.Fstar = load
    name = case(args.V, args.Fstar, args.start, args.yfp)
    jobs.run_figure(name, lambda: compute(args.V, args.Fstar, args.start, args.yfp),
                    lambda result: plot(result, name), argv=rest,
                    module="mlgshimmy.studies.animate")


if __name__ == "__main__":
    main()
