"""Why an AUTO run of periodic orbits stopped without convergence (MX):
at the edge of the model's domain, where a tyre load of the orbit reaches
zero (wheel lift-off, c/mlg_model.h MLG_WHEEL_LIFT_OFF), or short of it
(a numerical stop), or where the orbits approach a connection of saddle
equilibria (shared.saddle_connection: their period grows without bound;
the branch ends there too).  With side-stay angles the large-amplitude shimmy
orbits reach lift-off below V = 600 m/s (rho = mu = 10 deg: F* = 1 at
582.8 m/s, F* = 0.2 at 472.4 m/s), where at rho = mu = 0 they do not.

    reason = stop_reason(run("MX")[0])   # LIFT_OFF, SADDLES or "numerical"
"""
import ctypes
from typing import Dict, Tuple

from mlgshimmy.shared import mlgmodel
from mlgshimmy.shared import saddle_connection

LIFT_OFF_LOAD = 1e-4         # of the static tyre load: "zero" at an MX stop
LIFT_OFF, SADDLES = "wheel lift-off", "saddle connection"   # the ends of a branch


def solution_model(sol: object) -> mlgmodel.Model:
    """The model of an AUTO solution: its PAR and its constants file's constants."""
    names = [n for n in mlgmodel.PARNAMES if n and n != mlgmodel.CONSTANTS_FILE]
    return mlgmodel.Model("figures", **{n: sol.PAR[n] for n in names},
                          **mlgmodel.registered_constants(sol.PAR[mlgmodel.CONSTANTS_FILE]))


def diagnose(model: mlgmodel.Model, u: Dict[str, float]) -> Dict[str, object]:
    """mlg_diagnose at the state u ({name: value}): {field: value, or a
    (left, right) pair}; RuntimeError if u is outside the model's domain."""
    lib = mlgmodel.library()
    fields = mlgmodel.DIAGNOSTICS          # the layout of mlg_diagnostics, from the library
    count = sum(n for _, n in fields)

    class Out(ctypes.Structure):
        _fields_ = [("values", ctypes.c_double * count)]
    x = (ctypes.c_double * mlgmodel.NX)(*[u[n] for n in mlgmodel.UNAMES])
    out = Out()
    status = lib.mlg_diagnose(ctypes.byref(model._p), x, ctypes.byref(out))
    values, k, found = list(out.values), 0, {}
    for name, n in fields:
        found[name] = values[k] if n == 1 else tuple(values[k:k + n])
        k += n
    found["status"] = status
    return found


def tyre_loads(model: mlgmodel.Model, u: Dict[str, float]) -> Tuple[float, float]:
    """(F_L, F_R) [N] at the state u."""
    return diagnose(model, u)["F"]


def least_tyre_load(sol: object) -> float:
    """The least tyre load [N] over the stored points of an orbit (an AUTO
    solution), relative to nothing: see stop_reason."""
    model = solution_model(sol)
    return min(min(tyre_loads(model, {n: sol[n][k] for n in mlgmodel.UNAMES}))
               for k in range(len(sol["t"])))


def stop_reason(sol: object) -> str:
    """LIFT_OFF if the orbit `sol` (an MX solution) has a tyre load below
    LIFT_OFF_LOAD of the static one, SADDLES if it is close to a connection
    of saddles (saddle_connection.connects), else "numerical"."""
    model = solution_model(sol)
    static = min(tyre_loads(model, model.equilibrium()))
    if least_tyre_load(sol) < LIFT_OFF_LOAD * static:
        return LIFT_OFF
    return SADDLES if saddle_connection.connects(model, sol) else "numerical"
