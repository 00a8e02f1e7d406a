"""shared/floquet.py reads the multipliers of each step from an AUTO d-file.
The MX point of a run whose last Newton solve diverged has a block of
placeholders (every multiplier exactly 1) and that solve's iterate as its
parameter value; read as a step it put a torus crossing of an unstable
orbit at a made-up speed (570.3 m/s at rho = -20, mu = -10 deg, F* = 0.3125,
on a branch that stopped at 448.1 m/s)."""
from mlgshimmy.shared import floquet

HEAD = "  BR    PT  IT         PAR           L2-NORM\n"


def block(point, V, pair_abs, iterates=(), placeholders=False):
    """One step's text: its Newton iterations (the last at V, or the
    diverged `iterates`) and its multipliers (a complex pair of modulus
    pair_abs, the trivial 1 and seven small ones; or ten placeholders)."""
    values = list(iterates) or [V, V]
    lines = [HEAD] + [f"   2   {point:3d}   {k}        {v: .5E}   2.37403E+01\n"
                      for k, v in enumerate(values)]
    if placeholders:
        mults = [(1.0, 0.0)] * 10
    else:
        re, im = 0.998 * pair_abs, (pair_abs ** 2 - (0.998 * pair_abs) ** 2) ** 0.5
        mults = [(1.0, 0.0), (re, im), (re, -im)] + [(0.5, 0.0)] * 7
    lines += [f"   2   {point:3d}         Multiplier {k + 1:2d}   {a: .5E}  {b: .5E}  Abs. Val."
              f"   {abs(complex(a, b)):.5E}\n" for k, (a, b) in enumerate(mults)]
    return "".join(lines) + "\n"


def test_the_placeholder_block_of_an_mx_point_is_no_step(tmp_path):
    path = tmp_path / "d.po1"
    path.write_text(block(666, 447.5, 0.9990) + block(667, 448.0, 1.0016)
                    + block(668, 448.1, 1.0016)
                    + block(669, None, 0.0, iterates=(448.12, -2.1e12, 6.55e6),
                            placeholders=True)
                    + "   2   669 NOTE:No convergence using minimum step size\n")
    steps = floquet.read(str(path))
    assert [v for v, _ in steps] == [447.5, 448.0, 448.1], steps
    crossings = floquet.torus_crossings(steps)
    # the one crossing, where the pair leaves the unit circle; none at the MX point
    assert [c["direction"] for c in crossings] == [1], crossings
    assert 447.5 < crossings[0]["value"] < 448.0, crossings


def test_a_step_with_the_trivial_multiplier_and_others_is_kept(tmp_path):
    """Only a block of exactly 1s is dropped: a step whose multipliers
    include the trivial 1 (every orbit's) is a step."""
    path = tmp_path / "d.po1"
    path.write_text(block(1, 100.0, 0.98) + block(2, 101.0, 0.99))
    assert [v for v, _ in floquet.read(str(path))] == [100.0, 101.0]
