"""The stationary states of the gear over a load range: straight rolling and
the yawed states on both sides, continued by AUTO in F*, with their
stability, folds (LP) and, at the symmetric gear, pitchforks (BP).

    found = states(rundir, "figures", (0.02, 3.5), V=50.0, yfp=1.0, eps_rel=0.1, **geometry)
    found.straight            # AUTO diagram: straight rolling from the lowest load
    found.yawed               # [AUTO diagram]: the yawed states, each branch once
    found.pitchforks          # [F*] of the BPs on straight rolling (symmetric gear only)
    found.folds()             # [(F*, psi_mean, diagram)] of every LP, in F*
    found.extents()           # [(F_lo, F_hi)] of each yawed diagram
    found.at(0.3)             # [(psi_mean, stable)] of every stationary state at F* = 0.3
    found.rolling_state(0.3)  # the straight-rolling state there ({name: value}), continued in F*

The states do not depend on V (the rates vanish and V cancels from the
tyre equations, docs/model.md 4.20); their stability does, so V is one of
`values`.

At the symmetric gear (rho = mu = 0) straight rolling is psi = 0 and the
yawed states branch off it at pitchforks: they are found by branch
switching at the first BP, on both sides of psi, up to the last BP.

With side-stay angles the mirror symmetry is broken and the pitchforks are
imperfect: straight rolling continues smoothly onto one yawed side (the
preferred one), and the other side, with the unstable near-straight states
between, becomes a separate branch with a fold (LP) at each end: an isola
(rho = mu = 10 deg, V = 50, y_fp = 1 mm, eps = 0.1 mm: F* = 0.082-0.156,
psi about -0.05 deg, against +-0.1 deg and pitchforks at 0.037 and 0.41 for
the symmetric gear), or a branch that runs out of the range.  Such a branch
touches straight rolling nowhere, so it is looked for by Newton: the
symmetric gear of the same V, freeplay and equations (the companion, runs
sym_eq, sym_yawp, sym_yawm) gives the loads (SEEDS of them around its
pitchforks) and the yaw scale; at each load Newton starts from FAN yaws
on both sides of psi (newton_states).  A state not on a branch already
found (psi_mean within SAME at its load) is continued by AUTO in F* (run
yaw<k>_up; a closed branch, an isola, comes back to its start and ends
there, else also yaw<k>_down), so every branch is kept once.  A branch
that exists only away from the companion's pitchforks, or with a yaw
beyond SPREAD times the companion's, is not looked for.
"""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import branches
from mlgshimmy.shared import continuation as ct
from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import rolling

ANGLES = ("rho", "mu")
SAME = 1e-5          # rad: a state this close in psi_mean to a branch at its load is on it
SEEDS = 40           # loads around the symmetric gear's pitchforks where Newton looks
FAN = 9              # starting yaws at each load, from -SPREAD to SPREAD times ...
SPREAD = 1.5         # ... the largest yaw of the symmetric gear's yawed states
LOCATED = 1e-4       # AUTO locates a UZ of F* this close (relative; 7e-6 seen)
STEP = {"DS": 0.001, "DSMAX": 0.005, "DSMIN": 1e-9, "NMX": 3000, "MXBF": 0}


class StationaryError(RuntimeError):
    """The stationary states could not be found as this module finds them."""


class States:
    """What states() found (see the module's text)."""

    def __init__(self, straight, yawed, pitchforks, values, parameter_set):
        self.straight, self.yawed, self.pitchforks = straight, yawed, pitchforks
        self.values, self.parameter_set = dict(values), parameter_set
        # the states solved from the lowest and from the highest load
        self._paths: Dict[str, List[Tuple[float, numpy.ndarray]]] = {"lowest": [],
                                                                       "highest": []}
        self._fold: Optional[rolling.NoRollingState] = None   # where "lowest" ends

    def folds(self) -> List[Tuple[float, float, object]]:
        """[(F*, psi_mean, diagram)] of every fold (LP) of the stationary
        states, straight rolling included, in increasing F*."""
        found = [(float(branch["Fstar"][i]), float(branch["psi_mean"][i]), d)
                 for d in [self.straight] + list(self.yawed) for branch in d
                 for i, _, _ in branches.labelled_points(branch, "LP")]
        return sorted(found, key=lambda f: f[0])

    def extents(self) -> List[Tuple[float, float]]:
        """[(lowest, highest F*)] of each yawed diagram."""
        return [(min(numpy.min(b["Fstar"]) for b in d), max(numpy.max(b["Fstar"]) for b in d))
                for d in self.yawed]

    def at(self, Fstar: float) -> List[Tuple[float, bool]]:
        """[(psi_mean [rad], stable)] of every stationary state at the load
        F* (straight rolling and yawed), from the branches by linear
        interpolation between the two points either side."""
        return sorted(x for d in [self.straight] + list(self.yawed)
                      for x in interpolated(d, Fstar))

    def rolling_state(self, Fstar: float) -> Dict[str, float]:
        """The straight-rolling state at F* on this branch (the one connected
        to the lowest load), continued in F* (rolling.follow) from the
        nearest state solved before.  Newton from psi = 0 (mlg_equilibrium)
        is no substitute with side-stay angles: near the fold of the other
        branch its iterates stall (F* = 0.042-0.082 at rho = mu = 10 deg)
        and beyond it they land on that branch.  Above a fold in F* of the
        branch (an S where eta crosses the printed strut's stage switch:
        F* = 0.7012 at rho = 20, mu = 5 deg, which AUTO's steps pass over)
        it has come back on the sheet of the highest load: the state there,
        continued down from the highest load."""
        if self._fold is None or self._fold.at is None or Fstar <= self._fold.at:
            try:
                return self._continued("lowest", Fstar)
            except rolling.NoRollingState as e:
                self._fold = e
                if e.at is None or Fstar <= e.at:
                    raise StationaryError(f"stationary: {e}") from None
        try:
            return self._continued("highest", Fstar)
        except rolling.NoRollingState as above:
            raise StationaryError(f"stationary: {self._fold}; {above}") from None

    def _continued(self, end: str, Fstar: float) -> Dict[str, float]:
        """The state at F* continued from the lowest or highest load (`end`)
        of the straight branch, from the nearest state solved before on
        that side."""
        path = self._paths[end]
        if not path:
            loads = self.straight[0]["Fstar"]
            F0 = float(loads[0] if end == "lowest" else loads[-1])
            u = self._model(F0).equilibrium()
            path.append((F0, numpy.array([u[n] for n in mlgmodel.UNAMES])))
        F0, u = min(path, key=lambda p: abs(p[0] - Fstar))
        if F0 != Fstar:
            found = rolling.follow(self._model, "Fstar", F0, u, float(Fstar),
                                   f"straight rolling from the {end} load")
            path.extend(found)
            u = found[-1][1]
        return dict(zip(mlgmodel.UNAMES, u))

    def _model(self, Fstar):
        return mlgmodel.Model(self.parameter_set, **{**self.values, "Fstar": Fstar})


def symmetric(values: Dict[str, float]) -> bool:
    return all(values.get(a, 0.0) == 0.0 for a in ANGLES)


def states(rundir: str, parameter_set: str, loads: Tuple[float, float],
           steps: Optional[Mapping[str, Any]] = None, **values: float) -> States:
    """All stationary states for F* in `loads` = (lowest, highest) at
    `values` (V, freeplay, geometry; see the module's text); `steps`: AUTO
    constants of the straight-rolling run (e.g. an overlay)."""
    if not (0 < loads[0] < loads[1]):
        raise ValueError(f"stationary: loads {loads} must be 0 < lowest < highest F*")
    if symmetric(values):
        straight, pitchforks, yawed = _symmetric(rundir, "", parameter_set, loads, values,
                                                 steps or {})
        return States(straight, yawed, pitchforks, values, parameter_set)
    return _imperfect(rundir, parameter_set, loads, values, steps or {})


def _symmetric(rundir, prefix, parameter_set, loads, values, steps):
    """Straight rolling in F* and its pitchforks; the yawed states from the
    first pitchfork, both signs of psi, up to the last."""
    start = ct.Start(parameter_set, Fstar=loads[0], **values)
    # MXBF = 0: the yawed states are computed explicitly below
    eq = ct.equilibria(rundir, f"{prefix}eq", start, "Fstar", stop={"Fstar": loads[1]},
                       DS=0.002, DSMAX=0.01, MXBF=0, NMX=5000, **steps)
    pitchforks = [p["Fstar"] for p in eq("BP")]
    yawed = []
    for point in eq("BP")[:1]:
        for sign in (1, -1):
            yawed.append(ct.run(rundir, f"{prefix}yaw{'pm'[sign < 0]}", "equilibria", data=point,
                                ISW=-1, ICP=["Fstar"] + mlgmodel.MEASURES, DS=0.001 * sign,
                                DSMAX=0.005, NMX=3000, MXBF=0,
                                UZSTOP={"Fstar": [loads[0], loads[1], pitchforks[-1] + 1e-3]}))
    return eq, pitchforks, yawed


def _imperfect(rundir, parameter_set, loads, values, steps):
    companion = {**values, **{a: 0.0 for a in ANGLES}}
    _, pitchforks, sym_yawed = _symmetric(rundir, "sym_", parameter_set, loads, companion, steps)
    start = ct.Start(parameter_set, Fstar=loads[0], **values)
    straight = ct.equilibria(rundir, "eq", start, "Fstar", stop={"Fstar": loads[1]},
                             DS=0.002, DSMAX=0.01, MXBF=0, NMX=5000, **steps)
    found = States(straight, [], [], values, parameter_set)
    if not pitchforks:
        print(f"stationary: the symmetric gear has no pitchfork in F* = {loads}: "
              "no yawed states to look for", flush=True)
        return found
    reach = SPREAD * max(numpy.max(numpy.abs(b["psi_mean"])) for d in sym_yawed for b in d)
    for F, u in newton_states(parameter_set, seed_loads(pitchforks, loads), reach, values):
        if any(abs(psi - u["psi"]) <= SAME for d in [straight] + found.yawed
               for psi, _ in interpolated(d, F)):
            continue
        seed = ct.Start(parameter_set, near=u, **{**values, "Fstar": F})
        found.yawed.append(_follow(rundir, f"yaw{len(found.yawed) + 1}", seed, loads))
    return found


def seed_loads(pitchforks: Sequence[float], loads: Tuple[float, float]) -> List[float]:
    """SEEDS loads from half a pitchfork interval below the symmetric gear's
    first pitchfork to half above its last, within the range: where the
    yawed states of the gear with side-stay angles are looked for."""
    half = 0.5 * (pitchforks[-1] - pitchforks[0]) if len(pitchforks) > 1 else 0.1
    return list(numpy.linspace(max(loads[0], pitchforks[0] - half),
                               min(loads[1], pitchforks[-1] + half), SEEDS))


def newton_states(parameter_set: str, at_loads: Sequence[float], reach: float,
                  values: Mapping[str, float]) -> List[Tuple[float, Dict[str, float]]]:
    """[(F*, state)]: the distinct stationary states Newton (rolling.solve)
    converges to at each load from FAN starting yaws psi in [-reach, reach],
    the other states those of straight rolling of the symmetric gear."""
    companion = {**values, **{a: 0.0 for a in ANGLES}}
    out = []
    for F in at_loads:
        model = mlgmodel.Model(parameter_set, **{**values, "Fstar": F})
        base = mlgmodel.Model(parameter_set, **{**companion, "Fstar": F}).equilibrium()
        found = rolling.fan_states(model, [base[n] for n in mlgmodel.UNAMES],
                                   numpy.linspace(-reach, reach, FAN), SAME, iterations=60)
        out += [(F, dict(zip(mlgmodel.UNAMES, u))) for u in found]
    return out


def _follow(rundir, name, seed, loads):
    """The stationary states through `seed` (a ct.Start) in F*: up, and down
    unless the branch closed (an isola: back at its start, its second UZ
    at its load)."""
    F, psi = seed.PAR["Fstar"], seed.U["psi"]
    kw = dict(PAR=seed.PAR, U=seed.U, ICP=["Fstar"] + mlgmodel.MEASURES, UZR={"Fstar": [F]},
              UZSTOP={"Fstar": [loads[0], loads[1]]}, STOP=["UZ2"], **STEP)
    up = ct.run(rundir, f"{name}_up", "equilibria", **kw)
    back = [p for p in up("UZ") if abs(p["Fstar"] - F) <= LOCATED * max(1.0, F)]
    if len(back) >= 2 and abs(back[-1]["psi_mean"] - psi) <= SAME:
        return up
    down = ct.run(rundir, f"{name}_down", "equilibria", **{**kw, "DS": -STEP["DS"]})
    return Joined([b for d in (up, down) for b in d], (up, down))


def interpolated(diagram: Any, Fstar: float) -> List[Tuple[float, bool]]:
    """[(psi_mean, stable)] where the branches of a diagram cross the load
    F*, by linear interpolation between the two points either side."""
    out = []
    for branch in diagram:
        F, psi = numpy.asarray(branch["Fstar"]), numpy.asarray(branch["psi_mean"])
        stable = branches.stable_mask(branch)
        for i in numpy.flatnonzero((F[:-1] - Fstar) * (F[1:] - Fstar) <= 0):
            if F[i] == F[i + 1] or (i > 0 and F[i] == Fstar):
                continue   # a point on the load is counted once
            t = (Fstar - F[i]) / (F[i + 1] - F[i])
            out.append((float(psi[i] + t * (psi[i + 1] - psi[i])), bool(stable[i])))
    return out


class Joined(list):
    """The branches of several AUTO runs as one diagram: iterate them;
    d("LP") lists the special points of a type over all runs."""

    def __init__(self, branch_list, runs):
        super().__init__(branch_list)
        self.runs = runs

    def __call__(self, label):
        return [p for r in self.runs for p in r(label)]
