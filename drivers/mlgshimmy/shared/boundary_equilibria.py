"""Boundary-equilibrium points of the non-smooth freeplay law (14)
(docs/model.md 9.7): where a branch of equilibria of one mode of eq. (14)
reaches a switching surface h = 0 (ctypes and numpy, no AUTO).

Eq. (14) is smooth in each mode (gap, contact+, contact-), so equilibria
are found per mode, each mode's field continued beyond its surfaces.  A
boundary-equilibrium point (BEP) solves

    f_m(u; p) = 0,   h(u) = 0,   p free

(Newton on the NX + 1 unknowns (u, p) with the exact Jacobian: df/du and
df/dp of the library in mode m, dh/du of mlg_switching).  The force of eq.
(14) vanishes on h = 0, so a BEP is an equilibrium of both modes the
surface separates.  Each mode's equilibria are admissible on one side of
the surface (the gap's where h+ < 0, contact+'s where h+ > 0); along each
mode's branch through the BEP, h changes with p at the rate dh . du/dp.
Admissible on opposite sides of the BEP's p, the two branches join into
one that crosses the surface (persistence); on the same side, they meet
and end there (a non-smooth fold) (di Bernardo, Budd, Champneys,
Kowalczyk, Piecewise-smooth Dynamical Systems, 2008, chapter 5).

Straight rolling of the symmetric gear lies in the gap, where eq. (14)
leaves no torsional stiffness; its pitchforks in F* (Fig. 12) are those
of the gap mode, and their yawed branches reach the contact surfaces at
BEPs (from_pitchforks).

    points = from_pitchforks(law14_values, "Fstar", numpy.linspace(0.02, 3.5, 175))
    points[2]["Fstar"], points[2]["kind"]     # 0.4405130557, "persistence" (P2's, on h+)
"""
from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy

from mlgshimmy.shared import mlgmodel, rolling, spectrum

SURFACES = ("freeplay_upper", "freeplay_lower")     # h+ and h- (c/mlg_model.h)
MODE_NAMES = {0: "gap", 1: "contact+", 2: "contact-"}  # enum mlg_freeplay_mode
NEWTON_STEPS = 30
CONVERGED = 1e-12      # the largest Newton correction of u (rad, m) and p at a solution
PSI = 0                # u[PSI] is psi (mlgmodel.UNAMES)
YAWED = 1e-3           # |psi| / the BEP's |psi| below which a state is straight rolling
# the continuation parameters h+- = r_tlk(eta) psi_s -+ y_fp does not contain
# (y_fp does; rho and mu through psi_s)
FREE_OF_H = ("V", "Fstar", "c_psi", "k_tlk", "M_fric")


def system(model: mlgmodel.Model, mode: int, surface: str, u: Sequence[float],
           parameter: str, psi: Optional[float] = None) -> tuple:
    """(G, DG) of the BEP's equations at (u, p = model's parameter):
    G = (f_mode(u; p), h_surface(u)), DG its exact Jacobian in (u, p), p
    one of FREE_OF_H; with `psi` given, psi held there instead of h = 0
    (the mode's branch through the BEP, branch_in_psi)."""
    if parameter not in FREE_OF_H:
        raise ValueError(f"boundary_equilibria: parameter {parameter!r} is not free: h "
                         f"contains it; free are {', '.join(FREE_OF_H)}")
    f, J, fp = model.derivatives_in_mode(u, mode, parameter)
    if psi is None:
        h, dh = model.switching(u)[surface]
    else:
        h, dh = u[PSI] - psi, numpy.eye(len(u))[PSI]
    G = numpy.r_[f, h]
    DG = numpy.vstack([numpy.c_[J, fp], numpy.r_[dh, 0.0]])
    return G, DG


def solve(model: mlgmodel.Model, mode: int, surface: str, u: Sequence[float],
          parameter: str, psi: Optional[float] = None) -> Dict[str, Any]:
    """The BEP on `surface` (with `psi`: the equilibrium of `mode` with psi
    held there) reached by Newton from the state u at the model's value of
    `parameter`, solved in `mode`: {"u", parameter, "surface", "mode",
    "steps"}; RuntimeError if Newton does not converge."""
    x = numpy.r_[numpy.asarray(u, dtype=float), model[parameter]]
    nx = len(x) - 1
    for step in range(1, NEWTON_STEPS + 1):
        G, DG = system(model.set(**{parameter: x[nx]}), mode, surface, x[:nx], parameter, psi)
        dx = -numpy.linalg.solve(DG, G)
        x = x + dx
        if numpy.max(numpy.abs(dx)) < CONVERGED:
            model.set(**{parameter: x[nx]})
            return {"u": x[:nx], parameter: float(x[nx]), "surface": surface,
                    "mode": MODE_NAMES[mode], "steps": step}
    raise RuntimeError(f"boundary_equilibria: Newton on {surface} in the {MODE_NAMES[mode]} "
                       f"mode from {parameter} = {model[parameter]:.10g} did not converge in "
                       f"{NEWTON_STEPS} steps")


def branch(model: mlgmodel.Model, mode: int, surface: str, u: Sequence[float],
           parameter: str) -> Dict[str, float]:
    """The equilibria of `mode` through u: {"rate": dh/dp along them, dh .
    du/dp with du/dp = -(df/du)^-1 df/dp in that mode; "growth": the
    largest real part of that mode's eigenvalues at u}."""
    _, J, fp = model.derivatives_in_mode(u, mode, parameter)
    return {"rate": float(model.switching(u)[surface][1] @ -numpy.linalg.solve(J, fp)),
            "growth": float(numpy.linalg.eigvals(J).real.max())}


def classify(model: mlgmodel.Model, point: Mapping[str, Any], parameter: str) -> Dict[str, Any]:
    """What the BEP `point` is (model at its parameter value): {"sides":
    {mode name: +1 or -1, the side of p on which that mode's equilibria
    are admissible}, "rates": {mode name: dh/dp along its branch},
    "stable": {mode name: its equilibrium's stability there}, "kind":
    "persistence" or "non-smooth fold"}."""
    below, above = mlgmodel.SWITCHING[point["surface"]]
    out: Dict[str, Any] = {"sides": {}, "rates": {}, "stable": {}}
    for mode, sign in ((below, -1.0), (above, 1.0)):   # admissible where sign(h) = sign
        name = MODE_NAMES[mode]
        found = branch(model, mode, point["surface"], point["u"], parameter)
        if found["rate"] == 0.0:
            raise RuntimeError(f"boundary_equilibria: the {name} branch is tangent to "
                               f"{point['surface']} at {parameter} = {point[parameter]:.10g} "
                               "(a degenerate BEP)")
        out["rates"][name] = found["rate"]
        out["sides"][name] = int(numpy.sign(sign * found["rate"]))
        out["stable"][name] = found["growth"] < 0.0
    out["kind"] = "persistence" if len(set(out["sides"].values())) == 2 else "non-smooth fold"
    return out


def from_pitchforks(values: Mapping[str, float], parameter: str,
                    grid: Sequence[float]) -> List[Dict[str, Any]]:
    """The BEPs the yawed branches of straight rolling's pitchforks along
    `grid` of `parameter` reach, on both surfaces: [{"pitchfork" (its
    value), "u", parameter, "surface", "psi", and classify's}] in
    the order of the pitchforks.  Each from Newton in the gap mode, started
    at the pitchfork's state with psi moved onto the surface (h is affine
    in psi: one exact step).  `values` must select eq. (14)."""
    if values.get("freeplay_law") != mlgmodel.LAWS.index("nonsmooth"):
        raise ValueError("boundary_equilibria: freeplay_law must be nonsmooth (eq. 14), not "
                         f"{values.get('freeplay_law')!r}")
    gap = 0
    points = []
    changes = spectrum.stability_changes("figures", parameter, grid, **values)
    for at in [v for v, kind, _ in changes if kind == "BP"]:
        model = mlgmodel.Model("figures", **{**values, parameter: at})
        base = model.equilibrium()
        for surface in SURFACES:
            u = numpy.array([base[n] for n in mlgmodel.UNAMES])
            h, dh = model.switching(u)[surface]
            u[PSI] -= h / dh[PSI]
            point = solve(model, gap, surface, u, parameter)
            points.append({"pitchfork": at, **point, "psi": float(point["u"][0]),
                           **classify(model, point, parameter)})
    return points



def smoothed_approach(values: Mapping[str, float], point: Mapping[str, Any], parameter: str,
                      ratios: Sequence[float]) -> List[Dict[str, float]]:
    """How close the smoothed law's yawed state comes to the BEP `point`:
    at the BEP's value of `parameter`, for eps / y_fp = each of `ratios`
    (ascending; `values` with the smoothed law), the yawed state by Newton
    (rolling.solve) from the one before (the first from the BEP's state):
    [{"ratio", "gap": 1 - |y_tlk| / y_fp}], up to the first ratio with no
    yawed state there (its pitchfork has moved past the BEP)."""
    out = []
    u = numpy.array(point["u"], dtype=float)
    for ratio in ratios:
        model = mlgmodel.Model("figures", **{**values, parameter: point[parameter],
                                             "eps_abs": 0.0, "eps_rel": ratio})
        found = rolling.solve(model, u)
        if found is None or abs(found[PSI]) <= YAWED * abs(point["u"][PSI]):
            break
        u = found
        h, _ = model.switching(u)[point["surface"]]
        out.append({"ratio": ratio, "gap": abs(h) / (1e-3 * values["yfp"])})
    return out


def equilibrium_in_mode(model: mlgmodel.Model, mode: int, u: Sequence[float]) -> numpy.ndarray:
    """The equilibrium of `mode` by Newton from u at the model's parameters
    (corrections below CONVERGED); RuntimeError if it does not converge."""
    x = numpy.array(u, dtype=float)
    for _ in range(NEWTON_STEPS):
        f, J = model.jacobian_in_mode(x, mode)
        dx = -numpy.linalg.solve(J, f)
        x += dx
        if numpy.max(numpy.abs(dx)) < CONVERGED:
            return x
    raise RuntimeError(f"boundary_equilibria: no equilibrium of the {MODE_NAMES[mode]} mode "
                       f"by Newton from psi = {u[PSI]:.6g}")


def branch_in_psi(model: mlgmodel.Model, point: Mapping[str, Any], parameter: str,
                  psis: Sequence[float], mode: int = 0) -> List[Tuple[float, float]]:
    """The equilibria of `mode` (the gap's) through the BEP `point` at the
    held values `psis` of psi, each by Newton from the one before (p
    free): [(p, y_tlk / y_fp)]: the gap's yawed branch from the BEP back
    towards its pitchfork."""
    out, u = [], numpy.array(point["u"], dtype=float)
    model.set(**{parameter: point[parameter]})
    for psi in psis:
        found = solve(model, mode, point["surface"], u, parameter, psi)
        u = found["u"]
        out.append((found[parameter], tlk_ratio(model, u, point["surface"])))
    return out


def tlk_ratio(model: mlgmodel.Model, u: Sequence[float], surface: str) -> float:
    """y_tlk / y_fp at the state u, from h+- = y_tlk -+ y_fp."""
    h, _ = model.switching(u)[surface]
    yfp = 1e-3 * model["yfp"]
    return (h + yfp) / yfp if surface == "freeplay_upper" else (h - yfp) / yfp
