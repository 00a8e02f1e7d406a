"""The segmented equations file (models/mlg_segmented.c) compiled into a
small harness (no AUTO run): its Jacobians against central differences, its
boundary conditions at an orbit's switches, and the clear refusals of a
mode sequence that cannot be (two contact modes side by side) and of a
smoothed law.

Run: /usr/bin/python3 -m pytest -q tests/model/test_segmented_plugin.py
"""
import os
import subprocess

import numpy
import pytest

from mlgshimmy.shared import autosession, mlgmodel, paths

# four segments gap, contact+, gap, contact-: each at a state near the
# freeplay edge, y_tlk = r_tlk psi of about +-y_fp (psi = +-2.1e-3 rad)
HARNESS = r"""
#include "mlg_segmented.c"
doublereal getp(const char *code, integer ic, const doublereal *u) { return 0.0; }
enum { N = 4, NDIM = MLG_NX * N, NBC = (MLG_NX + 1) * N, NPAR = 48 };
int main(int argc, char **argv)
{
    doublereal par[NPAR] = {0}, u[NDIM], f[NDIM], dfdu[NDIM * NDIM], dfdp[NDIM * NPAR];
    doublereal u0[NDIM], u1[NDIM], fb[NBC], dbc[NBC * (2 * NDIM + NPAR)];
    integer icp[5] = {1, 31, 32, 33, 34};
    stpnt(NDIM, 0.0, u, par);
    par[0] = 100.0;                 /* V */
    par[2] = 1.0;                   /* yfp [mm] */
    par[4] = 0.0;                   /* eps_rel */
    par[14] = 1.0;                  /* constants: mlg.constants.1 (freeplay_law) */
    for (int k = 0; k < N; k++) par[30 + k] = 0.01 + 0.002 * k;
    int modes[N] = {0, 1, 0, 2};
    for (int k = 0; k < N; k++) par[40 + k] = argc > 1 ? atoi(argv[1 + k]) : modes[k];
    for (int i = 0; i < NDIM; i++) {
        if (scanf("%lf", &u[i]) != 1) return 2;
    }
    for (int i = 0; i < NDIM; i++) {
        if (scanf("%lf", &u1[i]) != 1) return 2;
        u0[i] = u[i];
    }
    func(NDIM, u, icp, par, 2, f, dfdu, dfdp);
    bcnd(NDIM, par, icp, NBC, u0, u1, 2, fb, dbc);
    for (int i = 0; i < NDIM; i++) printf("f %.17g\n", f[i]);
    for (int i = 0; i < NDIM * NDIM; i++) printf("dfdu %.17g\n", dfdu[i]);
    for (int i = 0; i < NDIM * NPAR; i++) printf("dfdp %.17g\n", dfdp[i]);
    for (int i = 0; i < NBC; i++) printf("fb %.17g\n", fb[i]);
    for (int i = 0; i < NBC * (2 * NDIM + NPAR); i++) printf("dbc %.17g\n", dbc[i]);
    return 0;
}
"""
N, NX = 4, 10
NDIM, NBC, NPAR = NX * N, (NX + 1) * N, 48


@pytest.fixture(scope="module")
def harness(tmp_path_factory):
    where = tmp_path_factory.mktemp("segmented")
    (where / "harness.c").write_text(HARNESS)
    (where / "mlg.constants.1").write_text("freeplay_law 1\n")
    exe = str(where / "harness")
    subprocess.run(["gcc", "-I", os.path.join(autosession.auto_dir(), "include"),
                    "-I", os.path.join(paths.ROOT, "c"), "-I", os.path.join(paths.ROOT, "models"),
                    str(where / "harness.c"), os.path.join(paths.BUILD, "lib", "libmlg.a"),
                    "-lm", "-o", exe], check=True)

    def run(u, u1, modes=None):
        done = subprocess.run([exe] + [str(m) for m in modes or []], cwd=where,
                              input=" ".join(map(repr, numpy.r_[u, u1])), capture_output=True,
                              text=True)
        out = {}
        for line in done.stdout.splitlines():
            key, value = line.split()
            out.setdefault(key, []).append(float(value))
        return done.returncode, {k: numpy.array(v) for k, v in out.items()}, done.stderr
    return run


def states(seed):
    """N segment states near straight rolling at 100 m/s, psi near +-y_fp/r_tlk."""
    model = mlgmodel.Model("figures", V=100.0, Fstar=1.0, yfp=1.0, eps_rel=0.0,
                           freeplay_law=1)
    base = numpy.array([model.equilibrium()[n] for n in mlgmodel.UNAMES])
    rng = numpy.random.default_rng(seed)
    out = []
    for psi in (1.9e-3, 2.5e-3, 1.5e-3, -2.5e-3):
        u = base + 1e-4 * rng.standard_normal(NX) * numpy.r_[1, 1, 1, 1e-2, 1e2, 1e2, 1e2, 1, 1, 1]
        u[0] = psi
        out.append(u)
    return numpy.concatenate(out)


def test_jacobians_agree_with_central_differences(harness):
    u, u1 = states(1), states(2)
    status, out, err = harness(u, u1)
    assert status == 0, err
    dfdu = out["dfdu"].reshape(NDIM, NDIM).T          # column-major
    dfdp = out["dfdp"].reshape(NPAR, NDIM).T
    dbc = out["dbc"].reshape(2 * NDIM + NPAR, NBC).T
    for j in range(NDIM):
        h = 1e-7 * max(1.0, abs(u[j]))
        plus, minus = u.copy(), u.copy()
        plus[j] += h
        minus[j] -= h
        fd = (harness(plus, u1)[1]["f"] - harness(minus, u1)[1]["f"]) / (2 * h)
        assert numpy.allclose(dfdu[:, j], fd, rtol=1e-5, atol=1e-6 * abs(dfdu).max()), j
        fd_bc = (harness(plus, u1)[1]["fb"] - harness(minus, u1)[1]["fb"]) / (2 * h)
        assert numpy.allclose(dbc[:, j], fd_bc, rtol=1e-6, atol=1e-9), j
    for j in range(NDIM):      # d/du1: continuity and h at each segment's end
        h = 1e-7 * max(1.0, abs(u1[j]))
        plus, minus = u1.copy(), u1.copy()
        plus[j] += h
        minus[j] -= h
        fd_bc = (harness(u, plus)[1]["fb"] - harness(u, minus)[1]["fb"]) / (2 * h)
        assert numpy.allclose(dbc[:, NDIM + j], fd_bc, rtol=1e-6, atol=1e-9), j
    # d/dT_k: the field of segment k alone
    f = out["f"]
    for k in range(N):
        column = dfdp[:, 30 + k]
        rows = slice(NX * k, NX * (k + 1))
        assert numpy.allclose(column[rows] * (0.01 + 0.002 * k), f[rows], rtol=1e-12)
        assert not numpy.delete(column, numpy.r_[rows]).any()


def test_the_switch_conditions_are_the_switching_functions(harness):
    u, u1 = states(3), states(4)
    _, out, _ = harness(u, u1)
    model = mlgmodel.Model("figures", V=100.0, Fstar=1.0, yfp=1.0, eps_rel=0.0,
                           freeplay_law=1)
    # segment k ends on the surface between its mode and the next:
    # gap->contact+: h+, contact+->gap: h+, gap->contact-: h-, contact-->gap: h-
    signs = (-1, -1, +1, +1)
    for k, sign in enumerate(signs):
        y = model.r_tlk(u1[NX * k + 3]) * u1[NX * k]
        assert out["fb"][NX * N + k] == pytest.approx(y + sign * 1e-3, rel=1e-12, abs=1e-15)
        # d h / d y_fp [1/mm], and nothing on V
        dbc = out["dbc"].reshape(2 * NDIM + NPAR, NBC).T
        assert dbc[NX * N + k, 2 * NDIM + 2] == pytest.approx(sign * 1e-3, rel=1e-8)
        assert dbc[NX * N + k, 2 * NDIM] == 0.0
    ends = u1.reshape(N, NX)
    starts = numpy.roll(u.reshape(N, NX), -1, axis=0)
    assert numpy.array_equal(out["fb"][:NX * N], (ends - starts).ravel())


def test_two_contact_modes_side_by_side_are_refused_naming_the_parameters(harness):
    status, _, err = harness(states(5), states(6), modes=[0, 1, 2, 0])
    assert status == 1
    assert "PAR(42) = 1, PAR(43) = 2" in err and "gap and a contact mode" in err
