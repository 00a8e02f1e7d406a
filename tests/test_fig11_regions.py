"""Fig. 11's region helpers on synthetic input (no AUTO run): where a
torus curve crosses a slice load, the pairing of MX ends where two Hopf
curves or two tongue edges meet, and the region map's codes around one
curve (a tongue edge left out)."""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "drivers"))
from check import check, check_close  # noqa: E402
from mlgshimmy.studies.atlas import compare as atlas_compare  # noqa: E402
from mlgshimmy.figures import fig11  # noqa: E402

V = fig11.V_GRID
HIGH, QUASI = fig11.ATTRACTORS["high"], fig11.ATTRACTORS["quasi"]


def branch(Vs, Fs, mx_at_end):
    """A stored branch of a curve (jobs.stored's record)."""
    return {"columns": {"V": list(Vs), "Fstar": list(Fs)}, "stable": [True] * len(Vs),
            "labels": [[len(Vs) - 1, 9, "MX"]] if mx_at_end else []}


def main():
    # a torus curve rising from (350, 0) to (450, 1), then folding back to (420, 0.5)
    edges = [{"name": "torus1.1", "kind": "torus", "V": [350.0, 450.0, 420.0],
              "Fstar": [0.0, 1.0, 0.5]},
             {"name": "hopf1.1", "kind": "hopf", "V": [100.0, 100.0], "Fstar": [0.0, 4.0]}]
    check_close("torus speed: where the curve crosses the load", fig11.torus_speed(edges, 0.2),
                370.0, abs=1e-9)
    check_close("a load the curve crosses twice: the lower speed", fig11.torus_speed(edges, 0.75),
                425.0, abs=1e-9)
    check("a load no torus curve crosses: beyond the plot (other curves ignored)",
          fig11.torus_speed(edges, 1.5) == fig11.BEYOND and fig11.BEYOND > fig11.V_MAX)

    # one family born at 5 Hz whose stable part runs 6-14 Hz, one born at 12 Hz
    Vs = np.linspace(1.0, 50.0, 50)
    grows = {"columns": {"V": list(Vs), "freq": list(np.linspace(5.0, 14.0, 50)),
                         "psi_amp": list(np.linspace(0.0, 2e-3, 50))},
             "stable": [False] + [True] * 49, "labels": []}
    high_born = {"columns": {"V": list(Vs + 100), "freq": list(np.linspace(12.0, 9.0, 50)),
                             "psi_amp": list(np.linspace(0.0, 2e-3, 50))},
                 "stable": [False] + [True] * 49, "labels": []}
    found = fig11.stable_orbits([grows, high_born])
    check("a family is labelled by its Hopf frequency, not by its stable part's",
          len(found["low"]) == 1 and len(found["high"]) == 1
          and found["low"][0][1] == 50.0 and found["high"][0][0] > 100.0, found)

    drawn = {"hopf": [[branch([1.4, 7.3237], [1.0, 0.685025], True)],
                      [branch([28.3, 7.3240], [1.0, 0.685025], True)],
                      [branch([144.0, 300.0], [1.0, 0.5], True)]], "fold": []}
    joins, stops = fig11.mx_ends(drawn)
    check("two MX ends 3e-4 m/s apart are joined", len(joins) == 1
          and joins[0]["curves"] == ["hopf1", "hopf2"], joins)
    check_close("the join lies half way", joins[0]["V"], 7.32385, abs=1e-9)
    check("a lone MX end stays a stop", len(stops) == 1 and stops[0]["curve"] == "hopf3", stops)
    # a tongue's edges stop 2.1 m/s short of each other at its tip (fig11.JOIN_TOL):
    # joined there; Hopf ends as far apart, or a Hopf end and a tongue end, are not
    drawn = {"hopf": [[branch([400.0, 512.9], [0.8, 0.8629], True)],
                      [branch([600.0, 515.0], [0.9, 0.8635], True)]],
             "tongue": [[branch([470.0, 512.9], [0.8, 0.8629], True)],
                        [branch([483.0, 515.0], [0.8, 0.8635], True)],
                        [branch([480.0, 371.8], [0.8, 0.712], True)]]}
    joins, stops = fig11.mx_ends(drawn)
    check("two tongue edges' MX ends 2.1 m/s apart are one join (its tip)", len(joins) == 1
          and joins[0]["curves"] == ["tongue1", "tongue2"] and joins[0]["kind"] == "tongue",
          joins)
    check("Hopf ends 2.1 m/s apart, and a Hopf end on a tongue end, stay stops",
          sorted(s["curve"] for s in stops) == ["hopf1", "hopf2", "tongue3"], stops)

    # one vertical curve at 300 m/s; the slices find the high orbit right of it
    sr = np.zeros((len(fig11.F_GRID), len(V)), dtype=bool)
    rows = [(F, np.where(V > 300, HIGH, 0)) for F in (1.0, 2.0)]
    edges = [{"name": "hopf1.1", "kind": "hopf", "V": [300.0, 300.0], "Fstar": [0.0, 4.0]}]
    found, report = fig11.region_map(sr, rows, edges, [0.037, 0.408])
    above = fig11.F_GRID > 0.5
    check("right of the curve: high-frequency shimmy at every load above the band",
          np.all(found[np.ix_(above, V > 301)] == HIGH))
    check("left of it: nothing stable found (code 0) at every load above the band",
          np.all(found[np.ix_(above, V < 299)] == 0))
    band = (fig11.F_GRID >= 0.037) & (fig11.F_GRID <= 0.408)
    check("the pitchfork band carries the yaw bit", np.all(found[band] & fig11.ATTRACTORS["yaw"]))
    check("the synthetic samples agree with their pieces", report["disagree"] == 0, report)
    check("no quasi-periodic code without a torus point", not np.any(found & QUASI))
    # a closed tongue inside the high region whose slice finds no stable orbit
    # inside it: it bounds no region (as an edge, its inside would be code 0:
    # checked as kind "hopf"), the region's majority labels it; nor is it a torus speed
    tongue = {"name": "tongue1.1", "kind": "tongue", "V": [400.0, 500.0, 500.0, 400.0, 400.0],
              "Fstar": [2.2, 2.2, 2.8, 2.8, 2.2]}
    inside = (fig11.slice_row(2.5), (V > 420) & (V < 480))
    rows_in = rows + [(2.5, np.where((V > 300) & ((V < 410) | (V > 490)), HIGH, 0))]
    for kind, code in (("tongue", HIGH), ("hopf", 0)):
        mapped, _ = fig11.region_map(sr, rows_in, edges + [dict(tongue, kind=kind)],
                                     [0.037, 0.408])
        check(f"inside a closed curve of kind {kind}: code {code}",
              np.all(mapped[inside] == code), np.unique(mapped[inside]))
    check("a tongue edge is no torus speed", fig11.torus_speed([tongue], 2.5) == fig11.BEYOND)


    # a lift-off edge from V = 600 at F* = 1.2 to V = 550 at 1.5 and back to
    # 600 at 1.8, right of the same curve: its pocket is lift-off, not high
    Fs = np.linspace(1.2, 1.8, 61)
    lift = {"points": [(600.0, 1.2), (550.0, 1.5), (600.0, 1.8)],
            "V": 600.0 - 50.0 * (1.0 - np.abs(Fs - 1.5) / 0.3), "Fstar": Fs}
    edges.append({"name": "liftoff", "kind": "liftoff", "V": lift["V"], "Fstar": lift["Fstar"]})
    rows = [(F, np.where(V > 300, HIGH, 0)) for F in (1.0, 1.5, 2.0)]
    found, report = fig11.region_map(sr, rows, edges, [0.037, 0.408], lift)
    at = fig11.slice_row(1.5)
    check("right of the lift-off edge at F* = 1.5: lift-off alone",
          np.all(found[at, V > 552] == fig11.ATTRACTORS["liftoff"]), found[at, V > 540])
    check("left of it at F* = 1.5, and beside its ends: high-frequency shimmy",
          np.all(found[at, (V > 301) & (V < 548)] == HIGH)
          and np.all(found[fig11.slice_row(1.1)][V > 301] == HIGH)
          and np.all(found[fig11.slice_row(1.9)][V > 301] == HIGH))
    check("the lift-off samples agree with their piece", report["disagree"] == 0, report)
    check("every code is the atlas's, lift-off its 'left the domain'",
          all(atlas_compare.CODES[kind] == fig11.ATTRACTORS[kind]
              for kind in ("straight", "low", "high", "yaw", "quasi"))
          and fig11.ATTRACTORS["liftoff"] == atlas_compare.CODES["domain"]
          and "lift-off" in fig11.NAMES[fig11.ATTRACTORS["liftoff"]],
          (fig11.ATTRACTORS, atlas_compare.CODES))
    missing = set(fig11.TONGUE_EDGES) - set(fig11.parts())
    check("every tongue edge that compute draws is a part make runs", not missing, missing)


main()
