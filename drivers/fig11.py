"""Fig. 11: the (V, F*) plane with +-1 mm of freeplay (epsilon = 0.1 y_fp):
the Hopf curves of straight rolling, the curves of folds of periodic orbits,
the pitchfork lines, and the zero-freeplay Hopf curve; regions shaded by the
attractors that coexist there.

The curves are AUTO continuations started from the Fig. 10 special points
(F* = 1), the torus curve of the large-amplitude orbits (AUTO, from a
torus point at F* = 0.5625) and the edges of two tongues of instability
left of it (other Floquet pairs, from F* = 0.8125 and 0.9375; they bound no
region).  The
regions are bounded by those curves and by the edges of the straight-rolling stability grid (exact Jacobian
eigenvalues); they are labelled, not bounded, by the stable low- (< 8 Hz) and high-frequency orbits
of one-parameter diagrams in V (continuation.speed_diagram and the
large-amplitude family) on a set of loads (regionmap).  The wheel lift-off
region is bounded by its edge located by simulation (liftoff).  result.json
holds the map ("region_map": V, Fstar, code per F* row, names) and the
curves bounding it ("edge_curves") for the attractor atlas."""
import os

import numpy

import autoglue
import branches
import continuation as ct
import liftoff
import paths
import results
import spectrum
import torus

F_MIN, F_MAX = 0.02, 3.5
V_MIN, V_MAX = 0.5, 600.0
FREEPLAY = dict(yfp=1.0, eps_rel=0.1)
# loads of the diagrams in V: denser where the low-load structure is
SLICES = numpy.concatenate((numpy.arange(0.0625, 2.0, 0.125), numpy.arange(2.125, 3.5, 0.25)))
F_GRID = numpy.arange(F_MIN, F_MAX + 1e-9, 0.01)
V_GRID = numpy.arange(V_MIN, V_MAX + 1e-9, 0.5)
LOW_FREQUENCY_HZ = 8.0   # folds above it start the upper fold curves
# An orbit family is low-frequency if it is born at a Hopf point below this:
# the slices' Hopf frequencies fall in two groups, 1.7-8.3 Hz and 10.3-14.6
# Hz (the large family, 16-47 Hz, is not Hopf-born in range); a fixed split
# of each orbit's own frequency cut one family (5-14 Hz at F* > 2) in two.
FAMILY_SPLIT_HZ = 9.3
FOLD_TIME_LIMIT = 120  # s of CPU, guard for a fold-curve run (they take 20-40 s)
STOP = {"Fstar": [F_MIN, F_MAX], "V": [V_MIN, V_MAX]}
V_SCAN = numpy.linspace(V_MIN, V_MAX, 3000)
# The lift-off edge: bisected in V on these loads (from a speed without
# lift-off within liftoff.T_END up to V_MAX), its ends in F* on V = V_MAX.
LIFTOFF_LOADS = numpy.round(numpy.arange(0.1, 0.71, 0.1), 2)
LIFTOFF_FROM = 500.0   # m/s: the bisection's lower end (no lift-off there; liftoff.bisected)


def curves(rundir, parameter_set="figures"):
    """Hopf and fold curves continued from the F* = 1 points of Fig. 10, the
    pitchfork loads (at three speeds: they do not depend on V) and the
    zero-freeplay Hopf curve."""
    out = {"hopf": [], "fold": [], "zero": []}
    points = ct.hopf_points(rundir, "hb", parameter_set, "V", V_SCAN, Fstar=1.0, **FREEPLAY)
    for k, point in enumerate(points):
        for sign in (1, -1):
            out["hopf"].append(ct.hopf_curve(
                rundir, f"hopf{k + 1}{'+-'[sign < 0]}", point, ("Fstar", "V"), stop=STOP,
                overlay="stage_switch", DS=0.002 * sign, DSMAX=0.02, NMX=5000, allow_mx=True))
    # the fold S, located on an orbit run with the base step sizes (the fold
    # located on Fig. 10's finer-stepped run does not start the fold curve)
    high = ct.periodic_from(rundir, "po_fold", points[-1], stop={"V": [30.0, 200.0]},
                            NMX=400, expect=["LP"])
    for k, point in enumerate(high("LP")):
        for sign in (1, -1):
            out["fold"].append(ct.fold_curve(
                rundir, f"fold{k + 1}{'+-'[sign < 0]}", point, ("V", "Fstar"), stop=STOP,
                DS=0.05 * sign, DSMAX=1.0, NMX=400, allow_mx=True))
    zero, = ct.hopf_points(rundir, "hb_zero", parameter_set, "V", V_SCAN, Fstar=1.0, yfp=0.0)
    for sign in (1, -1):
        out["zero"].append(ct.hopf_curve(rundir, f"hopf_zero{'+-'[sign < 0]}", zero,
                                         ("Fstar", "V"), stop=STOP, DS=0.02 * sign,
                                         allow_mx=True))
    out["pitchfork"] = []
    for V in (5.0, 50.0, 300.0):
        loads = [f for f, kind, _ in spectrum.stability_changes(
            parameter_set, "Fstar", numpy.linspace(F_MIN, F_MAX, 800), V=V, **FREEPLAY)
            if kind == "BP"]
        print(f"fig11: pitchforks at V = {V:g}: F* = " + ", ".join(f"{f:.6f}" for f in loads))
        out["pitchfork"].append(loads)
    return out


def large_seed(rundir, parameter_set="figures"):
    """The large-amplitude shimmy orbit at F* = 1: the orbits born at the
    last Hopf point of straight rolling there, continued to V = 300 m/s
    (its UZ1 label), where they are stable."""
    hopf = spectrum.hopf_scan(parameter_set, "V", V_SCAN, Fstar=1.0, **FREEPLAY)
    point = ct.hopf_point(rundir, "large_hb", parameter_set, "V", hopf[-1][0], Fstar=1.0,
                          **FREEPLAY)
    return ct.periodic_from(rundir, "large_seed", point, stop={"V": [V_MIN, 300.0]})


def large_orbits(rundir, parameter_set="figures"):
    """{slice load: orbit diagrams in V} of the large-amplitude shimmy family.
    Away from F* = 1 it need not be connected to a Hopf point of straight
    rolling inside V <= 600, so it is followed from its stable orbit at
    F* = 1, V = 300 m/s (large_seed): continued both ways in F* to every
    slice load, then both ways in V (large_run)."""
    seed = large_seed(rundir, parameter_set)
    out = {}
    for sign in (1, -1):
        family = ct.periodic_from(rundir, f"large_F{'+-'[sign < 0]}", seed("UZ1"), "Fstar",
                                  stop={"Fstar": [F_MIN, F_MAX]}, UZR={"Fstar": list(SLICES)},
                                  DS=0.02 * sign, DSMAX=0.1, allow_mx=True)
        for start in family("UZ"):
            Fstar = min(SLICES, key=lambda f: abs(f - start["Fstar"]))
            if abs(Fstar - start["Fstar"]) > 1e-4 or Fstar in out:
                continue
            out[Fstar] = [ct.periodic_from(rundir, large_run(Fstar, d), start,
                                           stop={"V": [V_MIN, V_MAX]}, DS=2.0 * d, DSMAX=5.0,
                                           allow_mx=True) for d in (1, -1)]
    return out


def large_run(Fstar, direction):
    """The name of the large part's diagram in V at a slice load, upwards
    (direction 1) or downwards (-1)."""
    return f"large_{Fstar:.3f}{'+-'[direction < 0]}"


def large_upwards(Fstar):
    """(diagram, torus crossings) of the large part's diagram in V upwards
    at a slice load (it must reach V_MAX); its torus points are the
    crossings of a Floquet pair through |mu| = 1 (floquet.torus_crossings)."""
    if Fstar not in SLICES:
        raise ValueError(f"fig11: F* = {Fstar} is no slice load: the large part has no "
                         "diagram in V there")
    rundir, name = paths.rundir("fig11/large"), large_run(Fstar, 1)
    orbits = ct.load(rundir, name)
    if abs(orbits()[-1]["V"] - V_MAX) > 1e-3:   # AUTO's UZ stop: V_MAX to its tolerance
        raise autoglue.RunError(f"run {name} in {rundir} stops at V = {orbits()[-1]['V']:.6g}, "
                                f"not V = {V_MAX:g}: its torus points are not all found")
    return orbits, torus.crossings(rundir, name)


# the torus curve bounding the quasi-periodic region, continued from its
# point on this load; the loads whose other torus points (narrow tongues of
# instability below the curve, F* ~ 0.65-1.1) are marked; the tongue edges
# continued, {part: (load, index of the crossing on it, torus_curve's
# options)}: the two ends of the window at F* = 0.8125 (471.1, 483.3 m/s)
# and at 0.9375 (540.24, 542.28 m/s).  The first edge needs 300 steps down
# to where it meets the second (docs/reproduction.md).  The pair at 540.24
# (theta = 0.17) is ill-conditioned (eigenvalue condition number ~550,
# against ~140 at 542.28): the seeded first Newton solve fails on the
# orbit's mesh (NTST 80) and converges on a finer one.
TORUS_START = 0.5625
TORUS_POINT_LOADS = (0.6875, 0.8125, 0.9375)
TONGUE_EDGES = {"tongue": (0.8125, 0, {"steps": 300}), "tongue2": (0.8125, 1, {}),
                "tongue3": (0.9375, 0, {"ntst": 120}), "tongue4": (0.9375, 1, {})}
TORUS_COLUMNS = ("V", "Fstar", "freq", "PAR(12)")
TONGUE_TOL = 0.002     # on_curves distance of a point on the tongue edge (~1 m/s in V)


def first_torus_curve(rundir, name, found, index=0, **options):
    """A torus point of an orbit diagram in V (found: (diagram, crossings);
    the first, or crossings[index]) continued both ways by AUTO
    (torus.tr_point, torus.torus_curve with its options: steps, ntst)."""
    orbits, crossings = found
    tr = torus.tr_point(rundir, "tr", orbits, crossings[index]["value"],
                        crossings[index]["slope_per_unit"])
    return torus.torus_curve(rundir, name, tr, **options)


def torus_curves():
    """A part, after the large part: the torus (Neimark-Sacker) curve of the
    large-amplitude family in (V, F*) and the torus points off it:
    {"curves": [[stored branches]], "points": [{"V", "Fstar", "angle",
    "direction"}]}: the curve from the first torus point on TORUS_START,
    the points of the TORUS_POINT_LOADS that it does not pass through (the
    large part's diagrams in V, large_upwards)."""
    found = {Fstar: large_upwards(Fstar) for Fstar in (TORUS_START,) + TORUS_POINT_LOADS}
    curve = first_torus_curve(paths.rundir("fig11/torus"), "torus", found[TORUS_START])
    points = [{"V": c["value"], "Fstar": Fstar, "angle": c["angle"],
               "direction": c["direction"]}
              for Fstar in TORUS_POINT_LOADS for c in found[Fstar][1]
              if not on_curves({"V": c["value"], "Fstar": Fstar}, curve)]
    return {"curves": [[branch for run in curve for branch in results.stored(run, TORUS_COLUMNS)]],
            "points": points}


def tongue_curve(part):
    """A part, after the large part: the torus curve of another Floquet
    pair, an edge of a tongue of instability left of the torus curve,
    continued from the torus point TONGUE_EDGES[part] of the large part's
    diagram in V on that load (large_upwards, first_torus_curve):
    {"curves": [[stored branches]]}."""
    Fstar, index, options = TONGUE_EDGES[part]
    curve = first_torus_curve(paths.rundir(f"fig11/{part}"), "tongue", large_upwards(Fstar),
                              index, **options)
    return {"curves": [[branch for run in curve for branch in results.stored(run, TORUS_COLUMNS)]]}


def straight_rolling_stable(parameter_set="figures"):
    """[F*, V] on F_GRID x V_GRID: True where straight rolling is stable."""
    return spectrum.stable_on_grid(parameter_set, "Fstar", F_GRID, "V", V_GRID, **FREEPLAY)


ORBIT_COLUMNS = ("V", "freq", "psi_amp")


def slice_rundir(Fstar):
    return paths.rundir(f"fig11/slice_{Fstar:.4f}")


def slice_diagram(Fstar, parameter_set="figures"):
    """The diagram in V at one slice load: its orbit branches (stored) and
    its folds of high-frequency orbits [(run name, label)] (to start fold
    curves from)."""
    print(f"fig11: slice F* = {Fstar:.4f}")
    diagram = ct.speed_diagram(slice_rundir(Fstar), parameter_set, {"Fstar": Fstar, **FREEPLAY},
                               V_SCAN, allow_failed=True, figure="fig11", DS=0.05, DSMAX=1.0,
                               NMX=2000)
    return {"branches": [b for run in diagram.branches
                         for b in results.stored(run, ORBIT_COLUMNS)],
            "folds": [(diagram.name_of(run), lab) for run, lab, _, _ in diagram.folds()
                      if run(lab)["freq"] >= LOW_FREQUENCY_HZ]}


def large_family(parameter_set="figures"):
    """large_orbits stored: {slice load as "%.4f": [stored branches]}."""
    return {f"{Fstar:.4f}": [b for run in runs for b in results.stored(run, ORBIT_COLUMNS)]
            for Fstar, runs in large_orbits(paths.rundir("fig11/large"), parameter_set).items()}


def stable_orbits(stored):
    """{"low"|"high": [(V0, V1), ...]}: the V-intervals of stable orbits on
    stored branches of one slice load, by family: a branch is low-frequency
    if its frequency where its amplitude is smallest (its Hopf point) is
    below FAMILY_SPLIT_HZ, whatever the frequency of its stable part."""
    found = {"low": [], "high": []}
    for branch in results.loaded(stored):
        V, amplitude = branch["V"], branch["psi_amp"]
        kind = "low" if branch["freq"][numpy.argmin(amplitude)] < FAMILY_SPLIT_HZ else "high"
        # stable orbits of non-zero amplitude
        keep = branches.stable_mask(branch) & (amplitude > ct.COLLAPSED)
        for run in branches.runs_of(keep, overlap=False):
            if keep[run.start]:
                found[kind].append((V[run].min(), V[run].max()))
    return found


def on_curves(point, curves, tol=0.01):
    """Whether the fold `point` lies on one of the computed fold curves
    (distance in V/V_MAX and F*/F_MAX below tol)."""
    return any(numpy.min(numpy.hypot((numpy.asarray(branch["V"]) - point["V"]) / V_MAX,
                                     (numpy.asarray(branch["Fstar"]) - point["Fstar"]) / F_MAX))
               < tol for curve in curves for branch in curve)


def upper_folds(rundir, first, folds):
    """Curves of folds of high-frequency orbits that the fold S curve
    (`first`, stored) does not reach: continued both ways from each fold on
    the lowest slice above its top load (folds: {slice load: [(run name,
    label)]}) that no curve computed so far passes through.  A direction
    that fails (or stalls: FOLD_TIME_LIMIT) is reported and left out.  The
    folds of the higher slices that no curve passes through start curves
    too (a curve can stop in MX before it reaches them)."""
    top = max(numpy.max(branch["Fstar"]) for diagram in first
              for branch in results.loaded(diagram))
    above = [f for f in SLICES if f > top and folds[f]]
    if not above:
        return []
    out, k = [], 0
    points = [ct.load(slice_rundir(Fstar), name)(lab) for Fstar in above
              for name, lab in folds[Fstar]]
    for point in points:
        if on_curves(point, out):
            continue
        k += 1
        for sign in (1, -1):
            name = f"fold_upper{k}{'+-'[sign < 0]}"
            try:
                out.append(ct.fold_curve(rundir, name, point, ("V", "Fstar"), stop=STOP,
                                         DS=0.05 * sign, DSMAX=1.0, NMX=400, allow_mx=True,
                                         time_limit=FOLD_TIME_LIMIT))
            except autoglue.RunError as exc:
                print(f"REPORTED: {name} left out: {exc.brief}")
    # every fold of the slices above must lie on a curve (a curve started
    # from a spurious point, or stopped short, shows here)
    missed = [p for p in points if not on_curves(p, out)]
    for p in missed:
        print(f"REPORTED: fig11 slice fold at V = {p['V']:.4g}, F* = {p['Fstar']:.4g} "
              "lies on no upper fold curve")
    print(f"fig11: {len(points) - len(missed)} of {len(points)} slice folds above "
          f"F* = {top:.4g} lie on the upper fold curves")
    return out


# bits of a code; "liftoff" is the atlas's "domain" (atlas_compare.CODES)
ATTRACTORS = {"straight": 1, "low": 2, "high": 4, "yaw": 8, "quasi": 16, "liftoff": 32}
NAMES = {1: "straight rolling", 2: "low-frequency shimmy", 4: "high-frequency shimmy",
         8: "off-centre yaw equilibria", 16: "quasi-periodic shimmy",
         32: "wheel lift-off (the model's domain ends)"}
BAND = "; between the pitchforks: off-centre yaw equilibria (their stability not computed)"
PIECE_DISAGREEMENT = 0.05   # a piece whose samples disagree more than this is reported


def code(kinds):
    """The attractor map code of a set of attractors."""
    return sum(ATTRACTORS[kind] for kind in kinds)


def slice_codes(orbits):
    """The orbit bits ("low", "high") along V_GRID on one slice, from its
    stable V-intervals (stable_orbits)."""
    out = numpy.zeros(len(V_GRID), dtype=int)
    for kind, intervals in orbits.items():
        for lo, hi in intervals:
            out[(V_GRID >= lo) & (V_GRID <= hi)] |= ATTRACTORS[kind]
    return out


def slice_row(Fstar):
    return int(numpy.argmin(numpy.abs(F_GRID - Fstar)))


BEYOND = 1.1 * V_MAX   # a slice that no torus curve crosses below V_MAX


def torus_speed(edge_curves, Fstar):
    """The lowest speed at which a torus curve crosses the load Fstar (where
    the last stable large-amplitude orbit is lost, at the lightest loads),
    BEYOND if none does."""
    speeds = [BEYOND]
    for curve in edge_curves:
        if curve["kind"] != "torus":
            continue
        V, F = numpy.asarray(curve["V"]), numpy.asarray(curve["Fstar"])
        for k in numpy.flatnonzero((F[:-1] - Fstar) * (F[1:] - Fstar) <= 0):
            if F[k + 1] != F[k]:
                speeds.append(V[k] + (Fstar - F[k]) / (F[k + 1] - F[k]) * (V[k + 1] - V[k]))
    return min(speeds)


def liftoff_rundir():
    return paths.rundir("fig11/liftoff")


def liftoff_speed(Fstar):
    """A part: the lowest speed (to liftoff.TOL_V) at which a wheel lifts
    off at load F*, bisected from LIFTOFF_FROM up to V_MAX; None if none
    does at V_MAX."""
    csv = os.path.join(liftoff_rundir(), f"F{Fstar:.2f}.csv")
    V = liftoff.edge_speed(csv, Fstar, LIFTOFF_FROM, V_MAX, **FREEPLAY)
    print(f"fig11: lift-off at F* = {Fstar:.2f}: "
          + (f"from V = {V:.1f} m/s" if V else f"none up to V = {V_MAX:g} m/s"), flush=True)
    return {"Fstar": float(Fstar), "V": V}


def liftoff_loads(speeds):
    """The indices of the loads with lift-off in the parts' speeds [{"Fstar",
    "V" or None}] (they must be contiguous)."""
    found = [k for k, s in enumerate(speeds) if s["V"] is not None]
    if found != list(range(found[0], found[-1] + 1) if found else []):
        raise RuntimeError("fig11: the loads with lift-off are not contiguous: "
                           f"{[s['Fstar'] for s in speeds if s['V'] is not None]}")
    return found


# the two ends of the lift-off edge on V = V_MAX: {part: the outermost load
# with lift-off on that side (index into the loads with lift-off)}
LIFTOFF_ENDS = {"liftoff_end_light": 0, "liftoff_end_heavy": -1}


def liftoff_end(parts, part):
    """A part: the load on V = V_MAX where lift-off starts beyond the
    outermost load with lift-off (LIFTOFF_ENDS), bisected in F* towards
    its neighbour without ({"Fstar": ..., or None if no load lifts a wheel
    off}).  The bracket's ends are not run again: the liftoff_<F*> parts
    ran both at V_MAX."""
    speeds = [parts[f"liftoff_{Fstar:.2f}"] for Fstar in LIFTOFF_LOADS]
    found = liftoff_loads(speeds)
    if not found:
        return {"Fstar": None}
    end = LIFTOFF_ENDS[part]
    inside = found[end]
    outside = inside + (-1 if end == 0 else 1)
    if not 0 <= outside < len(speeds):
        raise RuntimeError(f"fig11: a wheel lifts off at F* = {speeds[inside]['Fstar']}, "
                           "the outermost lift-off load: extend LIFTOFF_LOADS")
    csv = os.path.join(liftoff_rundir(), f"{part}.csv")
    Fstar = liftoff.edge_load(csv, V_MAX, speeds[outside]["Fstar"], speeds[inside]["Fstar"],
                              checked=True, **FREEPLAY)
    print(f"fig11: lift-off on V = {V_MAX:g} from F* = {Fstar:.4f}", flush=True)
    return {"Fstar": Fstar}


def liftoff_edge(speeds, ends):
    """The lift-off edge from the parts' speeds [{"Fstar", "V" or None}] and
    its two ends' loads on V = V_MAX (liftoff_end): {"points": [(V, F*)],
    "V", "Fstar": a smooth curve through them (PCHIP in F*)}, or None if no
    load lifts a wheel off."""
    from scipy.interpolate import PchipInterpolator   # 0.3 s to load: not in every part job
    found = liftoff_loads(speeds)
    if not found:
        return None
    points = [(V_MAX, ends[0])] + [(speeds[k]["V"], speeds[k]["Fstar"]) for k in found] \
        + [(V_MAX, ends[1])]
    V, F = numpy.array(points).T
    Fs = numpy.linspace(F[0], F[-1], 200)
    return {"points": points, "V": numpy.minimum(PchipInterpolator(F, V)(Fs), V_MAX),
            "Fstar": Fs}


def curve_list(drawn, pitchforks, lift=None):
    """Every curve that bounds a region: [{"name", "kind", "V", "Fstar"}]
    (the pitchfork lines as two points each; the lift-off edge if any), and
    the tongue's torus curve (kind "tongue": it bounds no region of the map,
    region_map leaves it out; the tongue is a few m/s wide)."""
    out = []
    for kind in ("hopf", "fold", "torus", "tongue"):
        for n, diagram in enumerate(drawn.get(kind, [])):
            for m, branch in enumerate(results.loaded(diagram)):
                out.append({"name": f"{kind}{n + 1}.{m + 1}", "kind": kind,
                            "V": branch["V"], "Fstar": branch["Fstar"]})
    out += [{"name": f"pitchfork{n + 1}", "kind": "pitchfork", "V": [V_MIN, V_MAX],
             "Fstar": [f, f]} for n, f in enumerate(pitchforks)]
    if lift:
        out.append({"name": "liftoff", "kind": "liftoff", "V": lift["V"],
                    "Fstar": lift["Fstar"]})
    return out


def region_map(sr_stable, orbits, edge_curves, pitchforks, lift=None):
    """(code [F*, V] on F_GRID x V_GRID, check): the regions bounded by the
    edge curves (and by the edges of the straight-rolling stability grid,
    which are the Hopf curves and pitchforks again, closing them where AUTO
    stopped), each labelled by the attractors the slices find inside it
    (regionmap.paint).  Straight rolling and the yaw band are exact (grid,
    pitchfork loads); where a slice finds no stable orbit nor straight
    rolling beyond its first torus curve (torus_speed), the attractor is
    quasi-periodic shimmy (simulations, docs/reproduction.md).  orbits:
    [(slice load, its orbit bits along V_GRID)].  Right of the lift-off
    edge (lift, liftoff_edge) the samples of the slices and of the edge's
    loads say lift-off: the shimmy there grows until a wheel lifts off."""
    import regionmap   # loads scipy.ndimage (0.1-0.2 s): not in every part job
    samples = numpy.full(sr_stable.shape, -1, dtype=int)
    for Fstar, row in orbits:
        samples[slice_row(Fstar)] = numpy.where(
            (V_GRID >= torus_speed(edge_curves, Fstar)) & (row == 0), ATTRACTORS["quasi"], row)
    if lift:
        F_edge = [f for _, f in lift["points"]]
        for Fstar in [f for f, _ in orbits] + list(F_edge[1:-1]):
            if F_edge[0] <= Fstar <= F_edge[-1]:
                beyond = V_GRID >= numpy.interp(Fstar, lift["Fstar"], lift["V"])
                samples[slice_row(Fstar), beyond] = ATTRACTORS["liftoff"]
    edges = regionmap.curve_pixels(V_GRID, F_GRID, [(c["V"], c["Fstar"]) for c in edge_curves
                                                    if c["kind"] != "tongue"])
    edges |= regionmap.boundary_pixels(sr_stable.astype(int))
    painted, check = regionmap.paint(edges, samples)
    lo, hi = min(pitchforks), max(pitchforks)
    yaw = ((F_GRID >= lo) & (F_GRID <= hi))[:, None] & numpy.ones(len(V_GRID), dtype=bool)
    found = painted | numpy.where(sr_stable, ATTRACTORS["straight"], 0) \
        | numpy.where(yaw, ATTRACTORS["yaw"], 0)
    return found, check


COLOURS = {  # by region_key; white: straight rolling only
    1: "white", 5: "tab:orange", 3: "tab:olive", 6: "tab:purple", 7: "tab:brown",
    2: "tab:cyan", 4: "tab:red", 16: "tab:gray", 32: "tab:blue", 8: "0.85", 0: "k"}


def region_key(found):
    """The code without the yaw bit (hatched on top), except where off-centre
    yaw is all there is."""
    return numpy.where(found == ATTRACTORS["yaw"], found, found & ~ATTRACTORS["yaw"])


def region_name(value):
    """The legend text of a region_key."""
    names = [NAMES[bit] for bit in sorted(NAMES) if value & bit]
    if not names:
        return "no stable state found"
    return ("" if len(names) == 1 else "coexisting: ") + " / ".join(names)


def shade(ax, found):
    """Paint the map (regions by colour, the yaw band hatched); returns the
    legend patches of the regions present."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch
    key = region_key(found)
    values = numpy.unique(key).tolist()
    colours = [COLOURS.get(v, "k") for v in values]
    half_V, half_F = 0.5 * (V_GRID[1] - V_GRID[0]), 0.5 * (F_GRID[1] - F_GRID[0])
    ax.imshow(numpy.searchsorted(values, key), cmap=ListedColormap(colours), vmin=-0.5,
              vmax=len(values) - 0.5, alpha=0.45, origin="lower", aspect="auto",
              interpolation="nearest", extent=(V_GRID[0] - half_V, V_GRID[-1] + half_V,
                                               F_GRID[0] - half_F, F_GRID[-1] + half_F))
    band = F_GRID[((found & ATTRACTORS["yaw"]) != 0).any(axis=1)]
    ax.fill_between([0, V_MAX], band.min(), band.max(), facecolor="none", edgecolor="0.3",
                    hatch="///", lw=0)
    handles = [Patch(facecolor=c, edgecolor="0.4", alpha=0.45, label=region_name(v))
               for v, c in zip(values, colours)]
    return handles + [Patch(facecolor="none", edgecolor="0.3", hatch="///",
                            label="between the pitchforks: off-centre yaw equilibria\n"
                                  "(straight rolling unstable; their stability\n"
                                  "in V not computed)")]


def stored_curves():
    out = curves(paths.rundir("fig11/curves"))
    return {**{kind: [results.stored(d, ("V", "Fstar")) for d in out[kind]]
               for kind in ("hopf", "fold", "zero")}, "pitchfork": out["pitchfork"]}


def upper_fold_curves(parts):
    """A part: the upper fold curves (upper_folds) from the slices' folds,
    stored: {"curves": [stored diagrams]}."""
    upper = upper_folds(paths.rundir("fig11/upper_folds"), parts["curves"]["fold"],
                        {Fstar: parts[f"slice_{Fstar:.4f}"]["folds"] for Fstar in SLICES})
    return {"curves": [results.stored(d, ("V", "Fstar")) for d in upper]}


def parts():
    """The large-amplitude family, the curves from F* = 1, the lift-off
    speeds, the eigenvalue grid and one diagram in V per slice load:
    independent jobs, about the longest first (so that the last jobs under
    make -jN are short); the torus curve and the tongue edges after the
    large part (from its diagrams in V), the upper fold curves after the
    slices (from their folds) and the lift-off edge's ends after the
    speeds."""
    jobs = {"large": large_family, "torus": results.Needs(["large"], lambda _: torus_curves())}
    jobs.update({part: results.Needs(["large"], lambda _, part=part: tongue_curve(part))
                 for part in TONGUE_EDGES})
    jobs["curves"] = stored_curves
    liftoff_parts = [f"liftoff_{Fstar:.2f}" for Fstar in LIFTOFF_LOADS]
    jobs.update({part: lambda Fstar=Fstar: liftoff_speed(Fstar)
                 for part, Fstar in zip(liftoff_parts, LIFTOFF_LOADS)})
    jobs["grid"] = straight_rolling_stable
    slice_parts = [f"slice_{Fstar:.4f}" for Fstar in SLICES]
    jobs.update({part: lambda Fstar=Fstar: slice_diagram(Fstar)
                 for part, Fstar in zip(slice_parts, SLICES)})
    jobs["upper_folds"] = results.Needs(["curves"] + slice_parts, upper_fold_curves)
    jobs.update({part: results.Needs(liftoff_parts, lambda p, part=part: liftoff_end(p, part))
                 for part in LIFTOFF_ENDS})
    return jobs


# MX ends of two curves of one kind closer than this (in V/V_MAX and
# F*/F_MAX) are one point where they meet: the Hopf curves from H1 and H2
# reach their common turning point inside the oleo stage switch from both
# sides (3e-4 m/s apart); a tongue's two edges stop short of where they
# meet (2.5 m/s apart at F* = 0.863)
JOIN_TOL = {"hopf": 1e-3, "tongue": 5e-3}
JOIN_LABELS = {"hopf": "Hopf curves from H1 and H2 meet: turning point\n"
                       "inside the oleo stage switch (AUTO stops both)",
               "tongue": "a tongue's two edges meet: its tip\n"
                         "(AUTO stops both there)"}


def mx_ends(drawn):
    """(joins, open): the MX ends of the drawn curves, those where two
    curves of one kind meet (JOIN_TOL) as [{"V", "Fstar", "kind",
    "curves"}], and the others [{"V", "Fstar", "curve"}]."""
    ends = [{"V": branch["V"][i], "Fstar": branch["Fstar"][i], "kind": kind,
             "curve": f"{kind}{n + 1}"}
            for kind in ("hopf", "fold", "torus", "tongue")
            for n, diagram in enumerate(drawn.get(kind, []))
            for branch in results.loaded(diagram)
            for i, _, _ in branches.labelled_points(branch, "MX")]
    joins, used = [], set()
    for a, p in enumerate(ends):
        for b in range(a + 1, len(ends)):
            q = ends[b]
            if a not in used and b not in used and p["kind"] == q["kind"] in JOIN_TOL \
                    and numpy.hypot((p["V"] - q["V"]) / V_MAX,
                                    (p["Fstar"] - q["Fstar"]) / F_MAX) < JOIN_TOL[p["kind"]]:
                used |= {a, b}
                joins.append({"V": 0.5 * (p["V"] + q["V"]), "Fstar": 0.5 * (p["Fstar"] + q["Fstar"]),
                              "kind": p["kind"], "curves": [p["curve"], q["curve"]]})
    return joins, [{k: e[k] for k in ("V", "Fstar", "curve")}
                   for n, e in enumerate(ends) if n not in used]


def compute(parts):
    """The parts assembled: the curves, the torus points on the slices, the
    lift-off edge, and the region map bounded by the curves (region_map)."""
    stored = parts["curves"]
    slices = {Fstar: parts[f"slice_{Fstar:.4f}"] for Fstar in SLICES}
    large = parts["large"]
    orbits = [(Fstar, slice_codes(stable_orbits(part["branches"]
                                                + large.get(f"{Fstar:.4f}", []))))
              for Fstar, part in slices.items()]
    drawn = {kind: stored[kind] for kind in ("hopf", "fold", "zero")}
    drawn["fold"] += parts["upper_folds"]["curves"]
    drawn["torus"] = parts["torus"]["curves"]
    drawn["tongue"] = [curve for part in TONGUE_EDGES for curve in parts[part]["curves"]]
    pitchforks = stored["pitchfork"][1]
    lift = liftoff_edge([parts[f"liftoff_{Fstar:.2f}"] for Fstar in LIFTOFF_LOADS],
                        [parts[part]["Fstar"] for part in LIFTOFF_ENDS])
    edges = curve_list(drawn, pitchforks, lift)
    found, check = region_map(numpy.asarray(parts["grid"], dtype=bool), orbits, edges,
                              pitchforks, lift)
    for row, col, n, votes in check["pieces"]:
        if n - max(votes.values()) > PIECE_DISAGREEMENT * n:
            print(f"REPORTED: fig11 region near V = {V_GRID[col]:.1f}, F* = {F_GRID[row]:.2f}: "
                  f"slice samples {votes} (labelled by the majority)")
    print(f"fig11: {check['disagree']} of {check['samples']} slice samples disagree with "
          "their region's label")
    joins, stops = mx_ends(drawn)
    for stop in stops:
        print(f"REPORTED: fig11 {stop['curve']} stops (MX) at V = {stop['V']:.4g}, "
              f"F* = {stop['Fstar']:.4g}")
    names = {str(v): ((region_name(v & ~ATTRACTORS["yaw"]) if v & ~ATTRACTORS["yaw"] else "")
                      + (BAND if v & ATTRACTORS["yaw"] else "")).lstrip("; ")
             for v in numpy.unique(found).tolist()}
    # the tongue points that its continued edge passes through are drawn by
    # it (a tighter tolerance: the edge is nearly flat, dV/dF* ~ 850 m/s)
    tongue = [results.loaded(d) for d in drawn["tongue"]]
    points = [p for p in parts["torus"]["points"] if not on_curves(p, tongue, TONGUE_TOL)]
    return {"curves": drawn, "torus_points": points,
            "pitchfork": stored["pitchfork"], "mx_joins": joins,
            "mx_stops": stops, "edge_curves": edges, "region_check": check,
            "liftoff": lift and {"points": lift["points"], "t_end": liftoff.T_END,
                                 "psi0": liftoff.PSI0},
            "region_map": {"V": V_GRID, "Fstar": F_GRID, "code": found, "names": names}}


STYLES = {"hopf": ("k-", "Hopf (y_fp = 1 mm)"), "fold": ("b--", "fold of periodic orbits"),
          "zero": ("k:", "Hopf, zero freeplay")}


def plot(result):
    # matplotlib is loaded here only: each of the ~40 part jobs would spend
    # 0.5 s loading it
    import matplotlib.pyplot as plt
    import plotting
    region = result["region_map"]
    found = numpy.asarray(region["code"])
    fig, ax = plt.subplots(figsize=(8, 6.5))
    handles = []
    for kind, (style, label) in STYLES.items():
        for diagram in result["curves"][kind]:
            for branch in results.loaded(diagram):
                ax.plot(branch["V"], branch["Fstar"], style, lw=1.4)
        handles.append(plt.Line2D([], [], color=style[0], ls=style[1:], label=label))
    for f in result["pitchfork"][1]:
        ax.axhline(f, color="g", lw=1.4, ls="-.")
    handles.append(plt.Line2D([], [], color="g", ls="-.", label="pitchfork"))
    for diagram in result["curves"]["torus"]:
        for branch in results.loaded(diagram):
            ax.plot(branch["V"], branch["Fstar"], color="m", lw=1.4)
    handles.append(plt.Line2D([], [], color="m", label="torus (Neimark-Sacker) curve:\n"
                              "large orbit loses stability, quasi-periodic\nshimmy beyond "
                              "(AUTO, ISW = 2)"))
    for diagram in result["curves"].get("tongue", []):
        for branch in results.loaded(diagram):
            ax.plot(branch["V"], branch["Fstar"], color="m", lw=1.2, ls="--")
    if result["curves"].get("tongue"):
        handles.append(plt.Line2D([], [], color="m", ls="--", label=(
            "torus curve of another Floquet pair: edge of a\n"
            "tongue where the large orbit is unstable (AUTO)")))
    for point in result["torus_points"]:
        ax.plot(point["V"], point["Fstar"], "o", mfc="none", mec="m", ms=5)
    if result["torus_points"]:
        handles.append(plt.Line2D([], [], color="m", marker="o", mfc="none", ls="",
                                  label="tongue torus points on no continued\n"
                                        "curve (located on diagrams in V)"))
    lift = [c for c in result["edge_curves"] if c["kind"] == "liftoff"]
    if lift:
        V, F = numpy.array(result["liftoff"]["points"]).T
        ax.plot(lift[0]["V"], lift[0]["Fstar"], color="navy", lw=1.4)
        ax.plot(V, F, "o", color="navy", ms=3)
        handles.append(plt.Line2D([], [], color="navy", marker="o", ms=3, label=(
            f"wheel lift-off within {result['liftoff']['t_end']:g} s from straight\n"
            "rolling (bisection in V and on V = 600 in F*)")))
    for kind, colour in (("hopf", "k"), ("tongue", "m")):
        joins = [j for j in result["mx_joins"] if j["kind"] == kind]
        for join in joins:
            ax.plot(join["V"], join["Fstar"], "o", color=colour, ms=4)
        if joins:
            handles.append(plt.Line2D([], [], color=colour, marker="o", ms=4, ls="",
                                      label=JOIN_LABELS[kind]))
    for stop in result["mx_stops"]:
        ax.plot(stop["V"], stop["Fstar"], "rx", ms=8)
    if result["mx_stops"]:
        handles.append(plt.Line2D([], [], color="r", marker="x", ls="",
                                  label="continuation stopped (MX)"))
    regions = shade(ax, found)
    ax.legend(handles=handles + regions, fontsize=7, loc="upper left",
              bbox_to_anchor=(1.01, 1.0), framealpha=0.9)
    ax.set_xlim(0, V_MAX)
    ax.set_ylim(0, F_MAX)
    ax.set_xlabel("V [m/s]")
    ax.set_ylabel(r"$F_z^*$")
    ax.set_title(r"Fig. 11: $y_{fp}$ = 1 mm, $\epsilon$ = 0.1 mm; regions bounded by the "
                 "curves, labelled from diagrams in V at "
                 f"F* = {SLICES[0]:g}, {SLICES[1]:g}, ..., {SLICES[-1]:g}", fontsize=8)
    plotting.save(fig, "fig11")


if __name__ == "__main__":
    results.run_figure("fig11", compute, plot, parts)
