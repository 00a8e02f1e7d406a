"""The torus-curve seed (drivers/torus.py) on an orbit whose monodromy
matrix is known exactly: straight rolling held as a "periodic orbit" of
period T, so Phi(1) = expm(T J) and its eigenvalues are exp(T lambda), lambda
the eigenvalues of the library's exact Jacobian there (F* = 1, V = 200 m/s,
y_fp = 1 mm, epsilon = 0.1 mm).  Checked: the RK4 monodromy matrix against
them (rel. 1e-8), and the seeded eigenfunction against the boundary
condition AUTO's torus continuation imposes, v(1) = exp(i theta) v(0)
(BCTR), and its norm, the integral of |v|^2 = PAR(NPAR) = 1 (ICTR)."""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from check import check, check_close  # noqa: E402
from mlgshimmy.shared import mlgmodel  # noqa: E402
from mlgshimmy.shared import torus  # noqa: E402

VALUES = {"V": 200.0, "Fstar": 1.0, "yfp": 1.0, "eps_abs": 0.0, "eps_rel": 0.1}
PERIOD = 0.025          # s, about the large orbits' period
POINTS = 81             # stored points of the fake orbit


class Solution(dict):
    """The parts of an AUTO solution the seed reads and writes: columns by
    name ("t", the states, U(k)) and PAR by name."""

    def __init__(self, par, u):
        super().__init__(t=np.linspace(0.0, 1.0, POINTS))
        for name, value in u.items():
            self[name] = np.full(POINTS, value)
        self.PAR = Par(par)


class Par(dict):
    @property
    def coordnames(self):
        return list(self)


def main():
    model = mlgmodel.Model("figures", **VALUES)
    u = model.equilibrium()
    par = {name: model[name] for name in mlgmodel.PARNAMES
           if name and name != mlgmodel.CONSTANTS_FILE}
    par[mlgmodel.CONSTANTS_FILE] = 0
    par.update({"T": PERIOD, "PAR(12)": 0.0, "PAR(31)": 0.0})
    sol = Solution(par, u)
    lam = np.linalg.eigvals(np.array(model.jacobian(u)))
    exact = np.sort_complex(np.exp(PERIOD * lam))
    _, phi = torus.monodromy_path(sol)
    found = np.sort_complex(np.linalg.eigvals(phi[-1]))
    check("monodromy matrix of a constant orbit: eigenvalues exp(T lambda) to rel. 1e-8",
          np.max(np.abs(found - exact) / np.abs(exact).max()) < 1e-8,
          np.max(np.abs(found - exact)))

    # the complex multiplier nearest the unit circle plays the critical one;
    # the start's own PAR(12) is set off it: the seed follows the angle given
    # (the TR label's), as on a tongue, where the other pair must not be taken
    pair = exact[exact.imag > 1e-3]
    mu = pair[np.argmin(np.abs(np.abs(pair) - 1))]
    other = pair[np.argmax(np.abs(np.angle(pair) - np.angle(mu)))]    # 2.24 rad against 0.25
    sol.PAR["PAR(12)"] = float(abs(np.angle(other)))
    try:
        torus.seeded(sol, abs(np.angle(mu)) + 3 * torus.ANGLE_TOL)
        check("an angle with no pair within ANGLE_TOL is refused", False)
    except ValueError as exc:
        check("an angle with no pair within ANGLE_TOL is refused", "no Floquet pair" in str(exc))
    seeded = torus.seeded(sol, float(abs(np.angle(mu))))
    n = len(mlgmodel.UNAMES)
    v = np.array([seeded[f"U({n + i + 1})"] + 1j * seeded[f"U({2 * n + i + 1})"]
                  for i in range(n)])
    check_close("seed angle is the pair's argument", seeded.PAR["PAR(12)"],
                abs(np.angle(mu)), abs=1e-8)
    check("v(1) = mu v(0) (the pair's multiplier, |mu| = %.6f)" % abs(mu),
          np.max(np.abs(v[:, -1] - mu * v[:, 0])) < 1e-8 * np.max(np.abs(v)),
          np.max(np.abs(v[:, -1] - mu * v[:, 0])))
    norm = np.trapz(np.sum(np.abs(v) ** 2, axis=0), seeded["t"])
    check_close("integral of |v|^2 is the norm PAR(NPAR) = 1", norm, 1.0, rel=1e-12)
    check_close("PAR(NPAR) set to 1", seeded.PAR["PAR(31)"], 1.0, abs=0)


main()
