"""Fig. 11's region helpers on synthetic input (no AUTO run): where a
torus curve crosses a slice load, the pairing of MX ends where two Hopf
curves or two tongue edges meet, the ends explained by the stage switch or
the lift-off edge, and the region map's codes around one
curve (a tongue edge left out)."""
import math

import numpy as np
import pytest

from mlgshimmy.figures import fig11
from mlgshimmy.figures.fig11 import ends, plane, tori
from mlgshimmy.figures.fig11 import regions as fig11_regions
from mlgshimmy.shared import jobs, regions
from mlgshimmy.studies.atlas import compare as atlas_compare

slice_row = fig11_regions.slice_row

V = fig11.V_GRID
HIGH, QUASI = fig11.ATTRACTORS["high"], fig11.ATTRACTORS["quasi"]
# a stable yawed equilibrium (yaw_stable's grid) between the pitchforks
# below the yawed states' Hopf point
YAW_BAND = (fig11.F_GRID >= 0.037) & (fig11.F_GRID <= 0.408)
YAW = YAW_BAND[:, None] & (V < 130.0)[None, :]


def branch(Vs, Fs, mx_at_end):
    """A stored branch of a curve (jobs.stored's record)."""
    return {"columns": {"V": list(Vs), "Fstar": list(Fs)}, "stable": [True] * len(Vs),
            "labels": [[len(Vs) - 1, 9, "MX"]] if mx_at_end else []}


# a torus curve rising from (350, 0) to (450, 1), then folding back to (420, 0.5)
TORUS_EDGES = [{"name": "torus1.1", "kind": "torus", "V": [350.0, 450.0, 420.0],
                "Fstar": [0.0, 1.0, 0.5]},
               {"name": "hopf1.1", "kind": "hopf", "V": [100.0, 100.0], "Fstar": [0.0, 4.0]}]


def test_torus_speed_where_the_curve_crosses_the_load():
    speed = tori.torus_speed(TORUS_EDGES, 0.2)
    assert math.isclose(speed, 370.0, abs_tol=1e-9), speed


def test_torus_speed_of_a_load_crossed_twice_is_the_lower_speed():
    speed = tori.torus_speed(TORUS_EDGES, 0.75)
    assert math.isclose(speed, 425.0, abs_tol=1e-9), speed


def test_torus_speed_of_a_load_no_torus_curve_crosses_is_beyond_the_plot():
    """Other curves than torus curves are ignored."""
    assert tori.torus_speed(TORUS_EDGES, 1.5) == tori.BEYOND and tori.BEYOND > plane.V_MAX


def test_stable_orbits_labelled_by_their_hopf_frequency():
    """One family born at 5 Hz whose stable part runs 6-14 Hz, one born at
    12 Hz: a family is labelled by its Hopf frequency, not by its stable
    part's."""
    Vs = np.linspace(1.0, 50.0, 50)
    grows = {"columns": {"V": list(Vs), "freq": list(np.linspace(5.0, 14.0, 50)),
                         "psi_amp": list(np.linspace(0.0, 2e-3, 50))},
             "stable": [False] + [True] * 49, "labels": []}
    high_born = {"columns": {"V": list(Vs + 100), "freq": list(np.linspace(12.0, 9.0, 50)),
                             "psi_amp": list(np.linspace(0.0, 2e-3, 50))},
                 "stable": [False] + [True] * 49, "labels": []}
    found = fig11.stable_orbits([grows, high_born])
    assert len(found["low"]) == 1 and len(found["high"]) == 1 \
        and found["low"][0][1] == 50.0 and found["high"][0][0] > 100.0, found


def test_mx_ends_of_two_hopf_curves_joined_half_way_a_lone_end_stays_a_stop():
    drawn = {"hopf": [[branch([1.4, 7.3237], [1.0, 0.685025], True)],
                      [branch([28.3, 7.3240], [1.0, 0.685025], True)],
                      [branch([144.0, 300.0], [1.0, 0.5], True)]], "fold": []}
    joins, stops = fig11.mx_ends(drawn)
    assert len(joins) == 1 and joins[0]["curves"] == ["hopf1", "hopf2"], \
        f"two MX ends 3e-4 m/s apart are not joined: {joins}"
    assert math.isclose(joins[0]["V"], 7.32385, abs_tol=1e-9), joins[0]["V"]
    assert len(stops) == 1 and stops[0]["curve"] == "hopf3", stops


def test_mx_ends_of_two_tongue_edges_joined_at_its_tip():
    """A tongue's edges stop 2.1 m/s short of each other at its tip
    (ends.JOIN_TOL): joined there; Hopf ends as far apart, or a Hopf end
    and a tongue end, are not."""
    drawn = {"hopf": [[branch([400.0, 512.9], [0.8, 0.8629], True)],
                      [branch([600.0, 515.0], [0.9, 0.8635], True)]],
             "tongue": [[branch([470.0, 512.9], [0.8, 0.8629], True)],
                        [branch([483.0, 515.0], [0.8, 0.8635], True)],
                        [branch([480.0, 371.8], [0.8, 0.712], True)]]}
    joins, stops = fig11.mx_ends(drawn)
    assert len(joins) == 1 and joins[0]["curves"] == ["tongue1", "tongue2"] \
        and joins[0]["kind"] == "tongue", joins
    assert sorted(s["curve"] for s in stops) == ["hopf1", "hopf2", "tongue3"], stops


LIFT = {"V": [600.0, 480.0, 470.0, 600.0], "Fstar": [0.1, 0.3, 0.5, 1.0]}
H3 = 144.26969   # m/s, the paper's gear's third Hopf point at F* = 1 (Fig. 10)


def test_mx_ends_inside_the_stage_switch_or_at_the_lift_off_edge_are_explained():
    """An end with F* inside the switch window is a stage-switch end (before
    the other tests), a fold curve's end at a Hopf point of straight
    rolling a generalised Hopf point by the Hopf-locus test (1 m/s off it
    not), one within
    ends.CLOSE_TOL of the lift-off edge a lift-off end, the rest stay MX
    stops; only a torus curve's lift-off end gets a closing segment, to
    the edge's nearest point."""
    stops = [{"V": 137.4, "Fstar": 0.6949, "curve": "hopf6"},
             {"V": 472.6, "Fstar": 0.5407, "curve": "torus1"},
             {"V": 473.0, "Fstar": 0.5328, "curve": "tongue1"},
             {"V": 300.0, "Fstar": 0.5407, "curve": "torus2"},
             {"V": H3, "Fstar": 1.0, "curve": "fold3"},
             {"V": H3 - 1.0, "Fstar": 1.0, "curve": "fold4"}]
    found = ends.explained(stops, (0.627, 0.700), LIFT, at_gh=ends.on_hopf_locus)
    assert [s["curve"] for s in found["stage_switch"]] == ["hopf6"], found
    assert [s["curve"] for s in found["generalised_hopf"]] == ["fold3"], found
    assert [s["curve"] for s in found["liftoff"]] == ["torus1", "tongue1"], found
    assert [s["curve"] for s in found["open"]] == ["torus2", "fold4"], found
    closing, = ends.closing_segments(found["liftoff"], LIFT)
    assert closing["V"] == [472.6, 470.0] and closing["Fstar"] == [0.5407, 0.5], closing
    assert ends.explained(stops, None, None, at_gh=ends.on_hopf_locus)["open"] \
        == [s for s in stops if s["curve"] != "fold3"]
    # without a GH test (no located point) a fold curve's end is no end
    assert ends.explained(stops, None, None)["open"] == stops


def test_a_torus_curves_end_on_a_fold_curve_is_explained_a_fold_curves_not():
    """A torus or tongue curve's MX end within ends.FOLD_TOL of a fold curve
    is an end on it; 0.012 off it in F* (3.4e-3 in the plane's units), or a
    fold curve's own end there, stays a stop."""
    fold = [branch([40.0, 60.0, 80.0], [0.05, 0.03, 0.02], False)]
    stops = [{"V": 59.58, "Fstar": 0.0311, "curve": "tongue1"},
             {"V": 60.0, "Fstar": 0.03, "curve": "torus2"},
             {"V": 60.0, "Fstar": 0.042, "curve": "torus3"},
             {"V": 60.0, "Fstar": 0.03, "curve": "fold5"}]
    found = ends.explained(stops, None, None, [jobs.loaded(fold)])
    assert [s["curve"] for s in found["on_fold"]] == ["tongue1", "torus2"], found
    assert [s["curve"] for s in found["open"]] == ["torus3", "fold5"], found
    assert ends.explained(stops, None, None)["open"] == stops


def test_mx_ends_beyond_the_plane_are_not_ends_in_it():
    """A curve started on the plane's lower edge that stops below it (F* =
    0.0095) has no end in the plane; one that stops on the edge has."""
    drawn = {"hopf": [[branch([138.0, 224.4], [plane.F_MIN, 0.0095], True)],
                      [branch([138.0, 150.0], [0.05, plane.F_MIN], True)]]}
    joins, stops = ends.mx_ends(drawn)
    assert joins == [] and stops == [{"V": 150.0, "Fstar": plane.F_MIN, "curve": "hopf2"}]


# one vertical curve at 300 m/s; the slices find the high orbit right of it
SR = np.zeros((len(fig11.F_GRID), len(V)), dtype=bool)
ROWS = [(F, np.where(V > 300, HIGH, 0)) for F in (1.0, 2.0)]
EDGES = [{"name": "hopf1.1", "kind": "hopf", "V": [300.0, 300.0], "Fstar": [0.0, 4.0]}]


@pytest.fixture(scope="module")
def one_curve_map():
    return fig11.region_map(SR, ROWS, EDGES, YAW)


def test_region_map_around_one_curve(one_curve_map):
    found, report = one_curve_map
    above = fig11.F_GRID > 0.5
    assert np.all(found[np.ix_(above, V > 301)] == HIGH), \
        "right of the curve: not high-frequency shimmy at every load above the band"
    assert np.all(found[np.ix_(above, V < 299)] == 0), \
        "left of it: not code 0 (nothing stable found) at every load above the band"
    assert np.array_equal((found & fig11.ATTRACTORS["yaw"]) != 0, YAW), \
        "the yaw bit is not exactly where the yawed equilibria are stable"
    assert report["disagree"] == 0, f"synthetic samples disagree with their pieces: {report}"
    assert not np.any(found & QUASI), "a quasi-periodic code without a torus point"


# a closed tongue inside the high region whose slice finds no stable orbit
# inside it: it bounds no region (as an edge, its inside would be code 0:
# checked as kind "hopf"), the region's majority labels it; nor is it a torus speed
TONGUE = {"name": "tongue1.1", "kind": "tongue", "V": [400.0, 500.0, 500.0, 400.0, 400.0],
          "Fstar": [2.2, 2.2, 2.8, 2.8, 2.2]}


@pytest.mark.parametrize("kind, code", (("tongue", HIGH), ("hopf", 0)))
def test_region_map_inside_a_closed_curve(kind, code):
    inside = (slice_row(2.5), (V > 420) & (V < 480))
    rows_in = ROWS + [(2.5, np.where((V > 300) & ((V < 410) | (V > 490)), HIGH, 0))]
    mapped, _ = fig11.region_map(SR, rows_in, EDGES + [dict(TONGUE, kind=kind)], YAW)
    assert np.all(mapped[inside] == code), \
        f"inside a closed curve of kind {kind}: {np.unique(mapped[inside])}, not {code}"


def test_torus_speed_ignores_a_tongue_edge():
    assert tori.torus_speed([TONGUE], 2.5) == tori.BEYOND


@pytest.fixture(scope="module")
def liftoff_map():
    """A lift-off edge from V = 600 at F* = 1.2 to V = 550 at 1.5 and back
    to 600 at 1.8, right of the same curve at 300 m/s."""
    Fs = np.linspace(1.2, 1.8, 61)
    lift = {"points": [(600.0, 1.2), (550.0, 1.5), (600.0, 1.8)],
            "V": 600.0 - 50.0 * (1.0 - np.abs(Fs - 1.5) / 0.3), "Fstar": Fs}
    edges = EDGES + [{"name": "liftoff", "kind": "liftoff", "V": lift["V"],
                      "Fstar": lift["Fstar"]}]
    rows = [(F, np.where(V > 300, HIGH, 0)) for F in (1.0, 1.5, 2.0)]
    return fig11.region_map(SR, rows, edges, YAW, lift)


def test_region_map_pocket_of_a_liftoff_edge_is_liftoff(liftoff_map):
    found, report = liftoff_map
    at = slice_row(1.5)
    assert np.all(found[at, V > 552] == fig11.ATTRACTORS["liftoff"]), \
        f"right of the lift-off edge at F* = 1.5: {found[at, V > 540]}"
    assert np.all(found[at, (V > 301) & (V < 548)] == HIGH) \
        and np.all(found[slice_row(1.1)][V > 301] == HIGH) \
        and np.all(found[slice_row(1.9)][V > 301] == HIGH), \
        "left of the lift-off edge at F* = 1.5, or beside its ends: not high-frequency shimmy"
    assert report["disagree"] == 0, f"the lift-off samples disagree with their piece: {report}"


def test_region_codes_are_the_atlas_codes_liftoff_its_left_the_domain():
    """Fig. 11's region map and the atlas use one table (shared.regions);
    an atlas cell whose starts all leave the domain has the lift-off code,
    named as such.  (Before the restructure, two tables were compared entry
    by entry.)"""
    assert fig11.ATTRACTORS is regions.ATTRACTORS and atlas_compare.CODES is regions.ATTRACTORS, \
        (fig11.ATTRACTORS, atlas_compare.CODES)
    left = {"starts": {"a": {"kind": "domain"}, "b": {"kind": "domain"}}}
    assert atlas_compare.cell_code(left) == fig11.ATTRACTORS["liftoff"] \
        == regions.code(["domain"]), (atlas_compare.cell_code(left), fig11.ATTRACTORS)
    assert "lift-off" in fig11_regions.NAMES[fig11.ATTRACTORS["liftoff"]], \
        fig11_regions.NAMES


def test_every_tongue_edge_drawn_is_a_part():
    """At the paper's gear (these tests' geometry) the four pinned tongue
    edges are parts; at a side-stay geometry the torus part finds them."""
    assert len(fig11.tongue_parts()) == 4, fig11.tongue_parts()
    missing = set(fig11.tongue_parts()) - set(fig11.parts())
    assert not missing, f"tongue edges compute draws that make does not run as parts: {missing}"


def test_hopf_joins_outside_the_stage_switch_are_named_apart():
    joins = [{"kind": "hopf", "Fstar": 0.685}, {"kind": "hopf", "Fstar": 0.267},
             {"kind": "tongue", "Fstar": 0.267}]
    kinds = [j["kind"] for j in ends.joins_outside(joins, (0.627, 0.700))]
    assert kinds == ["hopf", "hopf_elsewhere", "tongue"], kinds
    assert [j["kind"] for j in ends.joins_outside(joins, None)][0] == "hopf_elsewhere"
