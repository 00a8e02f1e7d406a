"""What the tests check of each figure's qualitative content, and the
section of docs/reproduction.md that discusses the figure: the report
lists both under each figure.  tests/figures/test_checks.py holds every entry to
the tree: each test named exists, each heading is in the docs.

CHECKS[figure] = (heading in docs/reproduction.md, [(feature, test)]),
test as "tests/<file>.py::<test function>", a C program "tests/c/<file>.c",
or "make regress-<fig>" (its reference set, compared by `make regress`).
"""
from typing import Dict, List, Tuple

DOCS = "docs/reproduction.md"
REFERENCE = "tests/regression/test_regression_quick.py::test_make_regress_of_each_quick_figure_agrees_with_its_reference"
DIAGRAMS = "tests/figures/test_freeplay_diagrams.py"

CHECKS: Dict[str, Tuple[str, List[Tuple[str, str]]]] = {
    "fig06": ("Fig. 6 — torque-link force profiles", [
        ("eq. (15) tends to eq. (14) as the smoothing width shrinks; zero freeplay is linear",
         "tests/c/test_freeplay.c")]),
    "fig07": ("Fig. 7 — zero freeplay, one-parameter diagrams in V", [
        ("one Hopf point at F* = 1, at the calibrated 346.1 m/s, found by AUTO's own scripting",
         "tests/jobs/test_demo.py::test_auto_script_reproduces_fig07_hopf_point"),
        ("it is supercritical: the orbits are born on the unstable side, with the amplitude "
         "the first Lyapunov coefficient predicts",
         "tests/continuation/test_lyapunov.py::test_amplitude_predicted_by_l1_matches_the_first_orbits"),
        ("every labelled point and stability change as in the reference diagrams", REFERENCE)]),
    "fig08": ("Fig. 8 — time simulation at V = 300 m/s, $F^*$ = 0.2", [
        ("unstable straight rolling grows at the linear shimmy rate, torsionally",
         "tests/model/test_simulate.py::test_unstable_shimmy_is_torsional"),
        ("the AUTO orbit and the simulated one agree",
         "tests/model/test_auto_plugin.py::test_orbit_matches_simulation")]),
    "fig09": ("Fig. 9 — zero-freeplay Hopf curve in (V, $F^*$)", [
        ("the Hopf curve as in the reference diagrams", REFERENCE)]),
    "fig10": ("Fig. 10 — F* = 1 with ±1 mm of freeplay, diagram in V", [
        ("three Hopf points near 1.5, 28.1 and 142.5 m/s",
         f"{DIAGRAMS}::test_hopf_speeds_at_unit_load_match_the_paper"),
        ("named by their mode: H1, H2 low-frequency (lose, regain stability), H3 "
         "high-frequency; H1, H2 supercritical, H3 subcritical",
         "tests/continuation/test_naming.py::test_the_paper_s_gear_has_its_three_named_points"),
        ("the high-frequency orbits from H3 fold at S near 41.5 m/s (bistability from S to H3)",
         f"{DIAGRAMS}::test_fold_s_matches_the_paper"),
        ("the orbits are born on the side l1 says",
         "tests/continuation/test_lyapunov.py::test_orbits_are_born_on_the_side_l1_says")]),
    "fig11": ("Fig. 11 — (V, F*) plane with ±1 mm of freeplay", [
        ("the Hopf curves are one curve entering and leaving the plane",
         f"{DIAGRAMS}::test_joined_hopf_curve"),
        ("the fold curve of S passes through the fold of the diagram in V",
         f"{DIAGRAMS}::test_fold_curve_meets_the_fold_of_a_diagram_in_V"),
        ("regions coded as the attractor atlas codes them",
         "tests/figures/test_fig11_regions.py::test_region_codes_are_the_atlas_codes_liftoff_its_left_the_domain"),
        ("a wheel lifts off at 600 m/s and not at 100 m/s",
         "tests/model/test_liftoff.py::test_lifts_off_simulated_at_600_and_100_m_s")]),
    "fig12": ("Fig. 12 — V = 50 m/s, diagram in F*", [
        ("two pitchforks at low load, then one Hopf point",
         f"{DIAGRAMS}::test_loads_at_50_pitchfork_pitchfork_hopf"),
        ("the pitchfork loads do not depend on V",
         f"{DIAGRAMS}::test_pitchfork_loads_independent_of_V_and_low"),
        ("yawed states between the pitchforks, as mirror pairs",
         "tests/model/test_yawed.py::test_baseline_yawed_states_exist_between_the_pitchforks_as_mirror_pairs"),
        ("their stability as a simulation from them finds it",
         "tests/model/test_yawed.py::test_stability_agrees_with_a_simulation_from_the_yawed_state")]),
    "fig13": ("Fig. 13 — $\\varepsilon = 0.1\\,y_{fp}$, diagrams in V and orbits in $y_{fp}$", [
        ("the Hopf speeds do not move with y_fp",
         "tests/figures/test_magnitude.py::test_linear_scaling_hopf_speeds_do_not_move_with_yfp"),
        ("orbit amplitudes scale linearly with y_fp",
         "tests/figures/test_magnitude.py::test_linear_scaling_psi_amplitude_at_v_15_doubles_from_yfp_half_to_1"),
        ("orbit frequencies do not depend on y_fp",
         "tests/figures/test_magnitude.py::test_linear_scaling_frequency_at_v_15_independent_of_yfp")]),
    "fig14": ("Fig. 14 — $\\varepsilon$ = 0.1 mm, diagrams in V and orbits in $y_{fp}$", [
        ("the thresholds in y_fp of the eigenvalue scan are AUTO's Hopf points in y_fp",
         "tests/figures/test_magnitude.py::test_thresholds_agree_with_auto_hopf_point_in_yfp")]),
    "fig15": ("Fig. 15 — rescaled profiles", [
        ("the rescaled profiles coincide for eps = 0.1 y_fp",
         "tests/figures/test_magnitude.py::test_profiles_rescaled_coincide_for_eps_proportional_to_yfp"),
        ("and differ for eps fixed",
         "tests/figures/test_magnitude.py::test_profiles_rescaled_differ_for_fixed_eps")]),
    "fig16": ("Fig. 16 — periodic orbits over (V, $y_{fp}$)", [
        ("straight rolling stable up to 120 m/s just below the threshold a",
         "tests/figures/test_magnitude.py::test_thresholds_straight_rolling_stable_up_to_120_just_below_a"),
        ("the orbit surfaces keep each slice's fold and stability",
         "tests/continuation/test_surfaces.py::test_loft_joins_the_folds_of_neighbouring_slices_by_a_quad_edge")]),
    "fig17": ("Fig. 17 — the curves of Fig. 16(b) in (V, $y_{fp}/\\varepsilon$)", [
        ("a and b where the high-frequency mode changes stability at 120 m/s",
         "tests/figures/test_magnitude.py::test_thresholds_a_and_b_at_v_120_as_reported")]),
    "fig18": ("Fig. 18 — a, b, c in $F^*$; regions; $\\kappa^*$", [
        ("kappa*'s first instability is Fig. 18's scan",
         "tests/figures/test_criterion.py::test_kappa_first_instability_equals_fig18_scan"),
        ("kappa* is a local minimum over F*", "tests/figures/test_criterion.py::test_kappa_minimum_is_local")]),
    "fig19": ("Fig. 19 — allowed rescaled profiles", [
        ("kappa* as documented", "tests/figures/test_criterion.py::test_kappa_star_of_variant_0_is_the_documented_one")]),
}
# Figures with a reference set (tests/reference/<fig>) that `make test` does
# not rerun: `make regress` compares every labelled point and stability change.
for _figure in ("fig10", "fig11", "fig12", "fig13", "fig14", "fig16", "fig18"):
    CHECKS[_figure][1].append(("every labelled point and stability change as in its "
                               "reference diagrams", f"make regress-{_figure}"))
# The variants share their figure's section and checks.
CHECKS["fig12_v1"] = CHECKS["fig12"]
CHECKS["fig18_v1"] = CHECKS["fig18"]


_TEX = (("\\varepsilon", "ε"), ("\\kappa", "κ"), ("\\,", " "), ("^*", "*"), ("_{fp}", "_fp"),
        ("$", ""))


def title(heading: str) -> str:
    """The heading as a reader sees it rendered: its TeX as plain text."""
    for tex, text in _TEX:
        heading = heading.replace(tex, text)
    return heading


def anchor(heading: str) -> str:
    """GitHub's anchor of a Markdown heading: lower case, punctuation but
    '-' and '_' dropped, each space a '-'."""
    kept = "".join(c for c in heading.lower() if c.isalnum() or c in " -_")
    return kept.replace(" ", "-")
