/* Straight-rolling equilibrium against the independent prototype values of
 * docs/model.md section 7 (4 significant digits). */
#include "mlg_model.h"
#include "unit.h"

static void equilibrium_at(double Fstar, double variant, double V, double u[MLG_NX])
{
    mlg_params p = mlg_params_table();
    p.Fstar = Fstar;
    p.strut_variant = variant;
    p.V = V;
    int status = mlg_equilibrium(&p, -1.0, u);
    char name[64];
    snprintf(name, sizeof name, "equilibrium_converges_F%.1f_variant%.0f", Fstar, variant);
    check(status == 0, name, "status %d", status);
}

int main(void)
{
    /* prototype values (docs/model.md 7): F*, beta*, eta* (monotone strut, variant 0) */
    const double table[5][3] = {{0.2, -0.00193, 0.2701}, {0.5, -0.00482, 0.3264},
                                {1.0, -0.00974, 0.3982}, {2.0, -0.02074, 0.4409},
                                {3.5, -0.0410, 0.4645}};
    char name[64];
    for (int k = 0; k < 5; k++) {
        double u[MLG_NX];
        equilibrium_at(table[k][0], 0.0, 100.0, u);
        /* 4 significant digits: half a unit in the last printed digit */
        snprintf(name, sizeof name, "beta_star_F%.1f", table[k][0]);
        check(fabs(u[MLG_BETA] - table[k][1]) <= (k == 4 ? 5e-5 : 5e-6), name,
              "beta* = %.6f, notes %.5f", u[MLG_BETA], table[k][1]);
        snprintf(name, sizeof name, "eta_star_F%.1f", table[k][0]);
        check(fabs(u[MLG_ETA] - table[k][2]) <= 5e-5, name, "eta* = %.6f, notes %.4f",
              u[MLG_ETA], table[k][2]);
    }

    /* F* = 1 intermediate quantities */
    double u[MLG_NX];
    equilibrium_at(1.0, 0.0, 100.0, u);
    mlg_params p = mlg_params_table();
    p.V = 100.0;
    mlg_diagnostics d;
    check(mlg_diagnose(&p, u, &d) == MLG_OK, "diagnose_status", "evaluation at equilibrium");
    check_rel("F_dyn", d.F_dyn, 294210.0, 5e-5);
    check_rel("cos_phi", d.cos_phi, 0.99131, 5e-5);
    check_rel("I_delta", d.I_delta, 533.06, 5e-5);
    check_rel("k_delta", d.k_delta, 2.3752e6, 5e-5);
    check_rel("c_delta", d.c_delta, 590.7, 1e-4);
    check_rel("I_beta", d.I_beta, 4062.3, 5e-5);
    check_rel("r_tlk", d.r_tlk, 0.47895, 5e-5);
    check_rel("F_L", d.F[0], 147105.0, 5e-5);
    check_rel("F_R", d.F[1], 147105.0, 5e-5);
    check_rel("d_i", d.d[0], 0.0925, 1e-3);
    check_rel("h_i", d.h[0], 0.5342, 2e-4);
    check_rel("L_i", d.L[0], 0.3740, 2e-4);

    /* printed strut spring (variant 1): eta* = 0.3683 at F* = 1 */
    equilibrium_at(1.0, 1.0, 100.0, u);
    check(fabs(u[MLG_ETA] - 0.3683) <= 5e-5, "eta_star_printed_strut_F1.0",
          "eta* = %.6f, notes 0.3683", u[MLG_ETA]);
    /* printed strut at F* = 0.2: held near full extension by the -40/eta term */
    equilibrium_at(0.2, 1.0, 100.0, u);
    check(u[MLG_ETA] > 0.0 && u[MLG_ETA] < 1e-3, "eta_star_printed_strut_F0.2",
          "eta* = %.3g (notes: ~3e-4)", u[MLG_ETA]);

    /* straight rolling does not depend on V, and f vanishes there */
    double u0[MLG_NX], u1[MLG_NX], f[MLG_NX];
    equilibrium_at(1.0, 0.0, 0.0, u0);
    equilibrium_at(1.0, 0.0, 450.0, u1);
    double diff = 0.0, res = 0.0;
    for (int i = 0; i < MLG_NX; i++) diff = fmax(diff, fabs(u0[i] - u1[i]));
    p.V = 450.0;
    mlg_rhs(&p, u1, f);
    for (int i = 0; i < MLG_NX; i++) res = fmax(res, fabs(f[i]));
    check(diff < 1e-12, "equilibrium_independent_of_V", "max |u(V=0) - u(V=450)| = %.2e", diff);
    check(res < 1e-8, "equilibrium_residual", "max |f(u*)| = %.2e", res);

    /* Across the oleo's stage switch (eta near eta_stage, width 1/k_stage =
     * 1e-5 m; F* about 0.62-0.70 with the monotone spring) full Newton steps
     * overshoot: every load on a fine grid must converge, with f = 0. */
    int failures = 0;
    double worst = 0.0;
    for (double Fstar = 0.02; Fstar <= 3.5; Fstar += 0.002) {
        mlg_params q = mlg_params_figures();
        q.Fstar = Fstar;
        q.V = 50.0;
        q.yfp = 1.0;
        if (mlg_equilibrium(&q, -1.0, u) != MLG_OK || mlg_rhs(&q, u, f) != MLG_OK) {
            failures++;
            continue;
        }
        for (int i = 0; i < MLG_NX; i++) worst = fmax(worst, fabs(f[i]));
    }
    check(failures == 0 && worst < 1e-6, "equilibrium_across_stage_switch",
          "%d of 1741 loads in [0.02, 3.5] failed; max |f(u*)| = %.2e", failures, worst);
    return unit_exit();
}
