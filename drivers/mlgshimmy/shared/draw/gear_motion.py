"""The gear drawn at one frame of its motion (shared.motion): a plan view
(strut, axle, both wheels and their contact patches, the patches' leading
points deflected by lambda_L, lambda_R), a front view (the strut bending
laterally by delta), the torque links' apex in true millimetres (the
freeplay gap +-y_fp shaded, the lower link's pin at y_tlk, orange when it
bears on the upper link) and psi over time with the frames' span.

    fig, show = figure(result, motion.scales(result["frames"]), title)
    show(k)        # move every artist to frame k (animations call it per frame)
"""
from __future__ import annotations

from typing import Callable, Dict, Mapping, Tuple

import matplotlib.pyplot as plt
import numpy
from matplotlib.patches import Polygon, Rectangle

from mlgshimmy.shared import draw
from mlgshimmy.shared.draw import palette

HALF_TRACK = 0.46        # m: a, the axle's half length (Table 1)
TYRE_RADIUS = 0.58       # m: r
TYRE_WIDTH = 0.36        # m: drawn only
L_DELTA0 = 1.266         # m: the lateral bending lever at eta = 0 (L_delta = L_delta0 - eta)
L_BETA0 = 2.915          # m: the longitudinal one
GROUND = palette.GUIDE


def _rectangle(centre, along, across, length, width):
    """Corners of a rectangle centred at `centre`, `length` along the unit
    vector `along`, `width` along `across`."""
    c, a, b = (numpy.asarray(v, dtype=float) for v in (centre, along, across))
    return [c + sa * 0.5 * length * a + sb * 0.5 * width * b
            for sa, sb in ((1, 1), (1, -1), (-1, -1), (-1, 1))]


def plan_state(f: Mapping[str, float], mean_beta: float,
               scale: Mapping[str, float]) -> Tuple[numpy.ndarray, numpy.ndarray, numpy.ndarray]:
    """Plan-view positions [m] (x lateral, y forward) at one frame: the
    axle's centre, its unit vector and the wheels' heading."""
    theta = scale["angle"] * f["psi"]
    lateral = (L_DELTA0 - f["eta"]) * numpy.sin(scale["angle"] * f["delta"])
    forward = (L_BETA0 - f["eta"]) * numpy.sin(scale["angle"] * (f["beta"] - mean_beta))
    axle = numpy.array([numpy.cos(theta), numpy.sin(theta)])
    heading = numpy.array([-numpy.sin(theta), numpy.cos(theta)])
    return numpy.array([lateral, forward]), axle, heading


def figure(result: Mapping[str, object], scale: Mapping[str, float],
           title: str) -> Tuple[plt.Figure, Callable[[int], None]]:
    """The figure of result (motion.settle's) and show(k), which moves every
    artist to frame k."""
    frames: Dict[str, list] = result["frames"]
    n = len(frames["t"])
    mean_beta = float(numpy.mean(frames["beta"]))
    # the strut's top so that the axle sits at the tyre's radius at the mean compression
    top = TYRE_RADIUS + L_DELTA0 - float(numpy.mean(frames["eta"]))
    fig = plt.figure(figsize=(9.6, 6.4))
    grid = fig.add_gridspec(2, 3, width_ratios=[1.5, 1.0, 1.0], height_ratios=[1.0, 0.55])
    plan = fig.add_subplot(grid[0, 0])
    front = fig.add_subplot(grid[0, 1])
    link = fig.add_subplot(grid[0, 2])
    trace = fig.add_subplot(grid[1, :])

    reach = HALF_TRACK + TYRE_WIDTH + 0.35
    plan.set(xlim=(-reach, reach), ylim=(-reach, reach), aspect="equal",
             title="plan view (forward is up)", xlabel="lateral [m]", ylabel="forward [m]")
    front.set(xlim=(-reach, reach), ylim=(-0.1, top + 0.15), aspect="equal",
              title="front view", xlabel="lateral [m]", ylabel="height [m]")
    front.axhline(0.0, color=GROUND, lw=2)
    plan.plot([0], [0], "o", color=draw.NEUTRAL, ms=9, mfc=palette.OPEN, zorder=4)
    wheels = [plan.add_patch(Polygon(numpy.zeros((4, 2)), closed=True, fc=palette.BAND,
                                     ec=draw.NEUTRAL,
                                     lw=1.0)) for _ in "LR"]
    axle_line, = plan.plot([], [], color=draw.STABLE, lw=3)
    strut_plan, = plan.plot([], [], color=draw.STABLE, lw=2, ls=":")
    patches = [plan.plot([], [], color=palette.TYRE, lw=3, solid_capstyle="round")[0]
               for _ in "LR"]
    leading = [plan.plot([], [], "o", color=palette.TYRE, ms=4)[0] for _ in "LR"]
    strut_front, = front.plot([], [], color=draw.STABLE, lw=4, solid_capstyle="round")
    axle_front, = front.plot([], [], color=draw.STABLE, lw=3)
    wheels_front = [front.add_patch(Rectangle((0, 0), TYRE_WIDTH, 2 * TYRE_RADIUS,
                                              fc=palette.BAND, ec=draw.NEUTRAL, lw=1.0))
                    for _ in "LR"]
    contacts_front = [front.plot([], [], "o", color=palette.TYRE, ms=5)[0] for _ in "LR"]

    yfp_mm = 1e3 * float(result["yfp_m"])
    y_tlk_mm = 1e3 * numpy.asarray(frames["y_tlk"])
    span = max(2.0 * yfp_mm, 1.3 * float(numpy.max(numpy.abs(y_tlk_mm))), 0.5)
    link.set(xlim=(-span, span), ylim=(-1, 1), yticks=[],
             xlabel=f"lateral [mm], true scale\n(grey: the freeplay gap ±{yfp_mm:g} mm)",
             title="torque-link apex")
    if yfp_mm > 0:
        link.axvspan(-yfp_mm, yfp_mm, color=palette.BAND, zorder=0)
    for side in (-1, 1):
        link.axvline(side * yfp_mm, color=draw.NEUTRAL, lw=1.5)
    pin, = link.plot([], [], "o", ms=12, mec=draw.NEUTRAL)

    trace_t = numpy.asarray(result["trace"]["t"])
    trace.plot(trace_t, draw.DEG * numpy.asarray(result["trace"]["psi"]), color=draw.STABLE,
               lw=0.6)
    trace.axvspan(frames["t"][0], frames["t"][-1] + 1e-9, color=draw.UNSTABLE, alpha=0.25)
    trace.set(xlabel="t [s]", ylabel=r"$\psi$ [deg]", xlim=(trace_t[0], trace_t[-1]))
    trace.ticklabel_format(axis="y", useOffset=False)
    psi_deg = draw.DEG * numpy.asarray(result["trace"]["psi"])
    if numpy.ptp(psi_deg) < 1e-6:       # a stationary state: its value, not its rounding
        middle = float(numpy.mean(psi_deg))
        trace.set_ylim(middle - 0.5, middle + 0.5)
    trace.grid(alpha=0.3)
    now, = trace.plot([], [], "o", color=draw.UNSTABLE, mec=draw.NEUTRAL, ms=6)
    fig.suptitle(title, fontsize="medium")
    fig.text(0.5, 0.005, f"motion scaled for visibility: angles ×{scale['angle']:g}, tyre "
             f"deflections ×{scale['deflection']:g}; the torque-link apex at true scale",
             ha="center", va="bottom", fontsize="small")
    fig.tight_layout(rect=(0, 0.03, 1, 1))

    def show(k: int) -> None:
        f = {name: values[k % n] for name, values in frames.items()}
        centre, axle, heading = plan_state(f, mean_beta, scale)
        ends = [centre - HALF_TRACK * axle, centre + HALF_TRACK * axle]
        axle_line.set_data(*numpy.array(ends).T)
        strut_plan.set_data([0, centre[0]], [0, centre[1]])
        for side, (wheel, patch, lead, end) in enumerate(zip(wheels, patches, leading, ends)):
            outward = axle * (1 if side else -1) * 0.5 * TYRE_WIDTH
            wheel.set_xy(_rectangle(end + outward, heading, axle, 2 * TYRE_RADIUS, TYRE_WIDTH))
            h = f["h_R" if side else "h_L"]
            lam = scale["deflection"] * f["lambda_R" if side else "lambda_L"]
            back = end + outward - 0.5 * h * heading
            tip = end + outward + 0.5 * h * heading + lam * axle
            patch.set_data([back[0], tip[0]], [back[1], tip[1]])
            lead.set_data([tip[0]], [tip[1]])
        length = L_DELTA0 - f["eta"]
        foot = numpy.array([length * numpy.sin(scale["angle"] * f["delta"]),
                            top - length * numpy.cos(scale["angle"] * f["delta"])])
        strut_front.set_data([0, foot[0]], [top, foot[1]])
        half = HALF_TRACK * numpy.cos(scale["angle"] * f["psi"])
        axle_front.set_data([foot[0] - half, foot[0] + half], [foot[1], foot[1]])
        for side, (wheel, contact) in enumerate(zip(wheels_front, contacts_front)):
            x = foot[0] + (half if side else -half)
            wheel.set_xy((x - (0 if side else TYRE_WIDTH), foot[1] - TYRE_RADIUS))
            lam = scale["deflection"] * f["lambda_R" if side else "lambda_L"]
            contact.set_data([x + (1 if side else -1) * 0.5 * TYRE_WIDTH + lam], [0.0])
        y = 1e3 * f["y_tlk"]
        engaged = abs(y) > yfp_mm
        pin.set_data([y], [0.0])
        pin.set_color(draw.UNSTABLE if engaged else draw.STABLE)
        pin.set_markeredgecolor(draw.NEUTRAL)
        now.set_data([f["t"]], [draw.DEG * f["psi"]])
    show(0)
    return fig, show
