"""The design answers for "my gear", from cached results: what the report
shows first at a changed gear (`make gear RHO=20 MU=5 [SET=...]`), with the
paper's gear beside every number.

Fig. 10's named Hopf points with their criticality, its fold S and the
zero-freeplay critical speed; Fig. 18's kappa* (the allowed freeplay is
kappa* x eps, eps = 0.1 mm).  A figure not made shows as such.
"""
import html
from typing import Dict, Optional

from mlgshimmy.shared import freeplay, gear, jobs

FIGURES = ("fig10", "fig18")      # what the answers are read from
NOT_MADE = "not made (make gear)"


def cached(figure: str, root: Optional[str] = None) -> Optional[dict]:
    """A cached result's data at this gear (root None) or at the paper's
    gear (root: the base run root), or None where it is not made."""
    try:
        return jobs.read(figure, root=root, model=None if root is None else gear.Gear())
    except (jobs.MissingResult, jobs.BadResult):
        return None


def answers(fig10: Optional[dict], fig18: Optional[dict]) -> Dict[str, object]:
    """{"made", "critical_V", "hopf": {name: point}, "S", "bistable" (S, H3),
    "allowed_mm", "kappa", "limit" (F*, V) where kappa* is set, "switch" the
    oleo's stage-switch window of loads (Fig. 18's "stage_switch") if the
    limit lies in it} (None where not known)."""
    out: Dict[str, object] = {"made": fig10 is not None, "critical_V": None, "hopf": {},
                              "S": None, "bistable": None, "allowed_mm": None, "kappa": None,
                              "limit": None, "switch": None}
    if fig10:
        numbers = fig10["numbers"]
        out["critical_V"] = numbers.get("V_crit (zero freeplay) [m/s]")
        out["hopf"] = {p["name"]: p for p in fig10.get("hopf_points", [])}
        out["S"] = numbers.get("S1 [m/s]")
        H3 = out["hopf"].get("H3", {}).get("V")
        if out["S"] is not None and H3 is not None and out["S"] < H3:
            out["bistable"] = (out["S"], H3)
    if fig18:
        out["kappa"] = fig18["kappa_star"]
        out["allowed_mm"] = fig18["kappa_star"] * freeplay.EPSILON
        at = fig18.get("numbers", {})
        if "kappa*: at F*" in at and "kappa*: at V [m/s]" in at:
            out["limit"] = (at["kappa*: at F*"], at["kappa*: at V [m/s]"])
            switch = fig18.get("stage_switch")
            if switch and switch[0] <= out["limit"][0] <= switch[1]:
                out["switch"] = tuple(switch)
    return out


def _value(found: dict, key: str, unit: str) -> str:
    value = found[key]
    if value is None:
        return "none" if found["made"] and key == "bistable" else NOT_MADE
    if isinstance(value, tuple):
        return f"{value[0]:.4g} to {value[1]:.4g} {unit}"
    if key == "allowed_mm" and found["limit"]:
        where = (f"; inside the oleo's stage switch, F* {found['switch'][0]:.3g}-"
                 f"{found['switch'][1]:.3g}" if found["switch"] else "")
        return (f"{value:.4g} {unit} (set at F* = {found['limit'][0]:.3g}, "
                f"V = {found['limit'][1]:.4g} m/s{where})")
    return f"{value:.4g} {unit}"


def _hopf(found: dict, name: str) -> str:
    point = found["hopf"].get(name)
    if point is None:
        return "vanished" if found["made"] else NOT_MADE
    return (f"{point['V']:.4g} m/s, {point['freq_hz']:.3g} Hz: {point['band']}-frequency "
            f"{point['dof']}, {'loses' if point['loses'] else 'regains'} stability, "
            f"<b>{point['criticality']}</b>")


def section(root: Optional[str] = None) -> str:
    """The report's first section at a changed gear ("" at the paper's)."""
    if gear.current().baseline:
        return ""
    ours = answers(*(cached(f) for f in FIGURES))
    theirs = answers(*(cached(f, gear.base_root()) for f in FIGURES))
    rows = [("critical speed without freeplay, F* = 1", "critical_V", "m/s"),
            ("bistable band [S, H3]: straight rolling and large shimmy both stable",
             "bistable", "m/s"),
            ("allowed freeplay y_fp (eq. 17: V ≤ 120 m/s, F* ≤ 2, ε = 0.1 mm)",
             "allowed_mm", "mm")]
    cells = [(html.escape(q), _value(ours, k, u), _value(theirs, k, u)) for q, k, u in rows]
    for name in sorted(set(ours["hopf"]) | set(theirs["hopf"])):
        cells.append((f"Hopf point {name} (y_fp = 1 mm, F* = 1)", _hopf(ours, name),
                      _hopf(theirs, name)))
    body = "".join(f"<tr><th>{q}</th><td>{a}</td><td>{b}</td></tr>" for q, a, b in cells)
    return (f'<h2 id="gear">Your gear: {html.escape(gear.describe())}</h2>'
            '<p>The design answers, with the paper\'s gear beside them; the gear\'s motion is '
            'in <a href="#study-animate">its animations</a>, every figure made at it below.</p>'
            '<table class="numbers"><thead><tr><th></th><th>your gear</th>'
            f"<th>the paper's gear</th></tr></thead><tbody>{body}</tbody></table>")
