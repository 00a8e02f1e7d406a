"""Smoke test of the whole chain: Makefile-built model with a static library,
run by AUTO-07p through drivers/autoglue.py.

The model (tests/smoke/smoke.c) is a Hopf normal form whose Hopf point
p = sqrt(2) comes from tests/smoke/shift.c, linked as a static library. Past
it the orbits are circles of radius sqrt(p - sqrt(2)) with period 2 pi.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from mlgshimmy.shared import autoglue  # noqa: E402
from check import check, check_close  # noqa: E402

MODEL = os.path.join(autoglue.BUILD, "tests", "smoke", "smoke")
CONSTANTS = os.path.join(HERE, "smoke", "c.smoke")
RUNDIR = os.path.join(autoglue.BUILD, "tests", "smoke-run")
HOPF = math.sqrt(2.0)


def raises_run_error(func):
    try:
        func()
    except autoglue.RunError as exc:
        return str(exc)
    return None


def check_failure_detection(eq):
    """autoglue flags MX points and missing special points."""
    message = raises_run_error(lambda: autoglue.check_diagram(eq, "eq", ["LP"]))
    check("autoglue: missing LP detected", message and "LP" in message,
          f"RunError message: {message!r}")

    # b.eq with the UZ point (label 3) retyped as MX (type -9).
    lines = []
    with open(os.path.join(RUNDIR, "b.eq")) as f:
        for line in f:
            fields = line.split()
            if len(fields) > 4 and fields[0] != "0" and fields[3] == "3":
                fields[2] = "-9"
                line = " ".join(fields) + "\n"
            lines.append(line)
    doctored = os.path.join(RUNDIR, "b.eq-mx")
    with open(doctored, "w") as f:
        f.writelines(lines)
    bd = autoglue.init().bifDiag.bifDiag(doctored)
    message = raises_run_error(lambda: autoglue.check_diagram(bd, "eq-mx"))
    check("autoglue: MX detected", message and "MX" in message and
          "label 3" in message, f"RunError message: {message!r}")


def main():
    built = os.stat(MODEL + ".exe").st_mtime_ns
    try:
        eq = autoglue.run(RUNDIR, "eq", constants=CONSTANTS, e=MODEL,
                          expect=["HB"])
    except autoglue.RunError as exc:
        check("equilibria: run without MX, HB found", False, str(exc))
        return
    check("equilibria: run without MX, HB found", True)
    hb = eq("HB1")
    check_close("equilibria: HB at p = sqrt(2)", hb["p"], HOPF, abs=1e-6)
    check("AUTO used the Makefile-built executable",
          os.stat(MODEL + ".exe").st_mtime_ns == built,
          f"{MODEL}.exe was rebuilt by AUTO")
    check_failure_detection(eq)

    try:
        po = autoglue.run(RUNDIR, "po", data=hb, constants=CONSTANTS, e=MODEL,
                          expect=["UZ"], IRS=hb["LAB"], IPS=2,
                          ICP=["p", "period", "xmax"],
                          UZSTOP={"p": HOPF + 1.0})
    except autoglue.RunError as exc:
        check("orbits: run without MX, UZ found", False, str(exc))
        return
    check("orbits: run without MX, UZ found", True)
    uz = po("UZ1")
    check_close("orbits: p at UZ", uz["p"], HOPF + 1.0, abs=1e-6)
    # On the circle of radius 1 the L2 norm is exactly the radius; PAR(21)
    # (getp MAX, PVLS) is a maximum over mesh points, so slightly below 1.
    check_close("orbits: radius 1 at p = sqrt(2) + 1", uz["L2-NORM"], 1.0,
                abs=1e-6)
    check_close("orbits: PVLS measure max x", uz["xmax"], 1.0, abs=1e-3)
    check_close("orbits: period 2 pi", uz["period"], 2 * math.pi, abs=1e-5)


if __name__ == "__main__":
    main()
