"""torus.tr_point places AUTO's TR label at a torus crossing by running back
along the orbit branch from its end.  A branch that stopped short (MX) is
run back from that MX point, which lies past every crossing on it: a
labelled orbit before it (a fold at lower speed) lies before the crossing,
and the run back from there never reaches it (at rho = -20, mu = -10 deg,
F* = 0.1875: folds at 131.7 and 44.0 m/s, the crossing at 304.6, the MX
point at 467.7).  The run back is not sent up the retry ladder: it
follows a branch already computed."""
import pytest

from mlgshimmy.shared import runerror
from mlgshimmy.shared import torus


class Point(dict):
    pass


def point(kind, V):
    p = Point(V=V)
    p["TY name"] = kind
    return p


class Diagram:
    """An AUTO diagram as tr_point reads it: bd() its labelled points in
    branch order, bd(kind) those of a kind."""

    def __init__(self, labelled):
        self.labelled = labelled

    def __call__(self, kind=None):
        return [p for p in self.labelled if kind is None or p["TY name"] == kind]


@pytest.fixture
def runs(monkeypatch):
    calls = []

    def run(rundir, name, kind, data, **kw):
        calls.append({"name": name, "data": data, **kw})
        if "_back" in name:     # reaches its stop
            return Diagram([point("UZ", kw["UZSTOP"]["V"])])
        return Diagram([point("TR", 304.6)])   # the fixed steps across it
    monkeypatch.setattr(torus.ct, "run", run)
    return calls


def test_a_branch_that_stopped_short_is_run_back_from_its_mx_point(runs):
    mx = point("MX", 467.7)
    branch = Diagram([point("LP", 131.7), point("LP", 44.0), mx])
    found = torus.tr_point("rundir", "tr4", branch, 304.6, 1e-4)
    assert found["TY name"] == "TR", found
    back = runs[0]
    assert back["name"] == "tr4_back1" and back["data"] is mx, back
    assert back["allow_mx"] is True and back["DS"] < 0, back


def test_a_run_back_that_stops_short_is_an_error_naming_it(monkeypatch):
    def run(rundir, name, kind, data, **kw):
        return Diagram([point("LP", 131.7), point("MX", 107.7)])
    monkeypatch.setattr(torus.ct, "run", run)
    branch = Diagram([point("LP", 131.7), point("MX", 467.7)])
    with pytest.raises(runerror.RunError) as error:
        torus.tr_point("rundir", "tr4", branch, 304.6, 1e-4)
    assert "tr4_back1" in str(error.value) and "107.7" in str(error.value), str(error.value)
