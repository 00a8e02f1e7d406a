/* Torque-link freeplay: eq. (15) tends to eq. (14) as epsilon -> 0 away from
 * the corners; zero freeplay is exactly linear; r_tlk geometry. */
#include "mlg_model.h"
#include "unit.h"

int main(void)
{
    const double k = 3.9e7, yfp = 1e-3;
    /* away from the corners |y| = yfp by at least `gap`, the error of eq. (15)
     * is about k eps^2 / (pi gap)... bounded by k eps here, and it shrinks
     * with eps: compare eps = 1e-2 yfp and 1e-4 yfp */
    const double gap = 0.2 * yfp;
    double worst_coarse = 0.0, worst_fine = 0.0;
    for (int i = 0; i <= 400; i++) {
        double y = -3e-3 + 6e-3 * i / 400.0;
        if (fabs(fabs(y) - yfp) < gap) continue;
        double exact = mlg_torque_link_force(0, k, y, yfp, 0.0);
        worst_coarse = fmax(worst_coarse, fabs(mlg_torque_link_force(0, k, y, yfp, 1e-2 * yfp) - exact));
        worst_fine = fmax(worst_fine, fabs(mlg_torque_link_force(0, k, y, yfp, 1e-4 * yfp) - exact));
    }
    check(worst_fine <= k * 1e-4 * yfp, "eq15_to_eq14_fine",
          "max |eq15 - eq14| = %.3g N at eps = 1e-4 y_fp (bound k eps = %.3g N)", worst_fine,
          k * 1e-4 * yfp);
    check(worst_fine < 0.02 * worst_coarse, "eq15_converges_as_eps_decreases",
          "error %.3g N at eps = 1e-2 y_fp, %.3g N at 1e-4 y_fp", worst_coarse, worst_fine);

    /* inside the freeplay eq. (14) gives zero force, and eq. (15) nearly zero */
    check(fabs(mlg_torque_link_force(0, k, 0.3 * yfp, yfp, 0.0)) == 0.0, "eq14_zero_inside",
          "force %.3g", mlg_torque_link_force(0, k, 0.3 * yfp, yfp, 0.0));
    check(fabs(mlg_torque_link_force(0, k, 0.3 * yfp, yfp, 1e-3 * yfp)) < 1e-3 * k * yfp,
          "eq15_small_inside", "force %.3g N",
          mlg_torque_link_force(0, k, 0.3 * yfp, yfp, 1e-3 * yfp));

    /* odd symmetry, and zero freeplay is linear for any epsilon */
    double odd = 0.0, lin = 0.0;
    for (int i = 1; i <= 50; i++) {
        double y = 4e-3 * i / 50.0;
        odd = fmax(odd, fabs(mlg_torque_link_force(0, k, y, yfp, 1e-4) +
                             mlg_torque_link_force(0, k, -y, yfp, 1e-4)));
        lin = fmax(lin, fabs(mlg_torque_link_force(0, k, y, 0.0, 1e-4) - k * y) / (k * y));
    }
    check(odd <= 1e-9 * k * yfp, "eq15_odd", "max |F(y) + F(-y)| = %.3g N", odd);
    check(lin <= 1e-14, "zero_freeplay_linear", "max rel. deviation from k y = %.2e", lin);

    /* zero freeplay: the Jacobian at straight rolling (y_tlk = 0 exactly) does
     * not depend on whether epsilon is zero or not */
    {
        mlg_params p0 = mlg_params_table(), p1 = mlg_params_table();
        p0.V = p1.V = 100.0;
        p0.eps_abs = p0.eps_rel = 0.0;
        p1.eps_abs = 0.1;
        double u[MLG_NX], f0[MLG_NX], f1[MLG_NX], J0[MLG_NX * MLG_NX], J1[MLG_NX * MLG_NX];
        mlg_equilibrium(&p0, -1.0, u);
        mlg_rhs_jacobian(&p0, u, f0, J0, NULL);
        mlg_rhs_jacobian(&p1, u, f1, J1, NULL);
        double worst = 0.0;
        for (int k = 0; k < MLG_NX * MLG_NX; k++)
            worst = fmax(worst, fabs(J0[k] - J1[k]) / (fabs(J1[k]) + 1e-12));
        check(worst <= 1e-12, "zero_freeplay_jacobian_eps_independent",
              "max rel. difference %.2e between epsilon = 0 and 0.1 mm", worst);
    }

    /* r_tlk: value at the F* = 1 equilibrium (docs/model.md 7), finite at z_tlk = 0 */
    mlg_params p = mlg_params_table();
    check_rel("r_tlk_eta_0.3982", mlg_r_tlk(&p, 0.398193), 0.47895, 5e-5);
    double r_end = mlg_r_tlk(&p, p.z_tlk0), r_near = mlg_r_tlk(&p, p.z_tlk0 - 1e-9);
    check(isfinite(r_end) && r_end > 0.0 && fabs(r_end - r_near) < 1e-6,
          "r_tlk_continuous_at_z_tlk_0", "r_tlk = %.6f m at z_tlk = 0, %.6f m just before",
          r_end, r_near);
    return unit_exit();
}
