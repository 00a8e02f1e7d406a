"""drivers/liftoff.py: the bisection on a known step (no simulation), and
two simulations of the `figures` set with y_fp = 1 mm, epsilon = 0.1 mm:
at V = 600 m/s, F* = 0.3 the shimmy grown from straight rolling lifts a
wheel off after about 19 s (docs/reproduction.md, Fig. 11); at V = 100 m/s,
F* = 1 straight rolling is stable (the Hopf point lies at 130 m/s) and no
wheel lifts off."""
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from check import check, check_close  # noqa: E402
from mlgshimmy.shared import liftoff  # noqa: E402


def raises(error, call):
    try:
        call()
    except error as exc:
        return str(exc)
    return None


def main():
    def step(at):
        return lambda x: x >= at
    found = liftoff.bisected(step(573.3), 450.0, 600.0, 2.0, "V")
    check_close("bisection in V: the step located to half the tolerance", found, 573.3, abs=1.0)
    found = liftoff.bisected(lambda f: f <= 0.537, 0.6, 0.5, 0.005, "F*")
    check_close("bisection with the bracket reversed (lift-off below 0.537)", found, 0.537,
                abs=0.0025)
    check("no lift-off at the top of the bracket: None",
          liftoff.bisected(step(700.0), 450.0, 600.0, 2.0, "V") is None)
    tried = []
    found = liftoff.bisected(lambda x: tried.append(x) or x >= 573.3, 450.0, 600.0, 2.0, "V",
                             checked=True)
    check("bracket checked by the caller: its ends are not run again, the step is found",
          450.0 not in tried and 600.0 not in tried and abs(found - 573.3) <= 1.0, tried)
    check("bracket checked: 7 halvings from 150 to 2 m/s, one run each", len(tried) == 7, tried)
    tried = []
    liftoff.bisected(lambda x: tried.append(x) or x >= 573.3, 450.0, 600.0, 2.0, "V")
    check("bracket not checked: the top end and the halvings are run, not the bottom end "
          "(the edge lies far from it)", tried[0] == 600.0 and 450.0 not in tried
          and len(tried) == 8, tried)
    message = raises(ValueError, lambda: liftoff.bisected(step(400.0), 450.0, 600.0, 2.0, "V"))
    check("lift-off already at the bottom of the bracket is an error naming it",
          message is not None and "V = 450" in message, message)
    message = raises(ValueError, lambda: liftoff.lifts_off("x.csv", -5.0, 0.3))
    check("a negative speed is refused, naming V", message is not None and "V = -5" in message,
          message)

    with tempfile.TemporaryDirectory() as tmp:
        csv = os.path.join(tmp, "run.csv")
        check("V = 600 m/s, F* = 0.3: a wheel lifts off within 60 s",
              liftoff.lifts_off(csv, 600.0, 0.3, t_end=60.0))
        check("V = 100 m/s, F* = 1: no lift-off in 5 s (straight rolling stable)",
              not liftoff.lifts_off(csv, 100.0, 1.0, t_end=5.0))
        check("no simulator output left behind", os.listdir(tmp) == [], os.listdir(tmp))


main()
