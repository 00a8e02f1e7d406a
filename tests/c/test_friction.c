/* Oleo seal friction (docs/model.md 9): the moment and force the model
 * applies are size * tanh(slip / v_fric) at the seal, against the slip;
 * Coulomb's level away from stick, a viscous damper of size / v_fric at
 * stick; zero size leaves the model untouched at any v_fric and r_seal. */
#include <string.h>

#include "mlg_model.h"
#include "unit.h"

/* the diagnostics at straight rolling with the given rates (rad/s, m/s) */
static mlg_diagnostics at(const mlg_params *p, double psi_dot, double beta_dot, double eta_dot)
{
    double u[MLG_NX];
    mlg_equilibrium(p, -1.0, u);
    u[MLG_PSI_DOT] = psi_dot;
    u[MLG_BETA_DOT] = beta_dot;
    u[MLG_ETA_DOT] = eta_dot;
    mlg_diagnostics d;
    int status = mlg_diagnose(p, u, &d);
    if (status != MLG_OK) printf("# status %d: %s\n", status, mlg_status_text(status));
    return d;
}

int main(void)
{
    mlg_params off = mlg_params_figures();
    off.V = 30.0, off.yfp = 1.0, off.rho = 0.2, off.mu = -0.1, off.eom_terms = 2;
    mlg_params on = off;
    on.M_fric = 800.0, on.F_fric = 5e3, on.v_fric = 2e-3, on.r_seal = 0.12;

    /* the moment acts on the twist psi' + beta' sin p (eom_terms 2), as M_cpsi */
    double worst = 0.0, worst_force = 0.0, opposed = 0.0;
    for (int i = -20; i <= 20; i++) {
        double psi_dot = 0.004 * i, beta_dot = 0.001 * (i % 5), eta_dot = 0.0015 * (i % 7);
        mlg_diagnostics a = at(&off, psi_dot, beta_dot, eta_dot);
        mlg_diagnostics b = at(&on, psi_dot, beta_dot, eta_dot);
        double twist = psi_dot + beta_dot * sin(b.p);
        double moment = on.M_fric * tanh(on.r_seal * twist / on.v_fric);
        double force = on.F_fric * tanh(eta_dot / on.v_fric);
        worst = fmax(worst, fabs(b.M_cpsi - a.M_cpsi - moment) / on.M_fric);
        worst_force = fmax(worst_force, fabs(b.F_ceta - a.F_ceta - force) / on.F_fric);
        opposed = fmin(opposed, (b.M_cpsi - a.M_cpsi) * twist);
    }
    check(worst <= 1e-12, "friction_moment_is_regularised_coulomb",
          "max |dM - M_fric tanh(r_seal twist / v_fric)| / M_fric = %.2e", worst);
    check(worst_force <= 1e-9, "friction_force_is_regularised_coulomb",
          "max |dF - F_fric tanh(eta' / v_fric)| / F_fric = %.2e", worst_force);
    check(opposed >= 0.0, "friction_opposes_the_twist", "least moment * twist %.3g", opposed);

    /* Coulomb's level once the slip is 10 v_fric: within 2 e^-20 of M_fric */
    double slip = 10.0 * on.v_fric / on.r_seal;
    mlg_diagnostics a = at(&off, slip, 0.0, 0.0), b = at(&on, slip, 0.0, 0.0);
    check_rel("coulomb_level_away_from_stick", b.M_cpsi - a.M_cpsi, on.M_fric, 1e-8);

    /* at stick a viscous damper: d(psi'')/d(psi') falls by M_fric r_seal / (v_fric I_psi)
     * (eq. 1; rho = mu = 0, eom_terms 0, where psi'' = (...) / I_psi) */
    mlg_params flat_off = off, flat_on = on;
    flat_off.rho = flat_off.mu = flat_on.rho = flat_on.mu = 0.0;
    flat_off.eom_terms = flat_on.eom_terms = 0;
    double u[MLG_NX], f[MLG_NX], J0[MLG_NX * MLG_NX], J1[MLG_NX * MLG_NX];
    double P[MLG_NX * MLG_NPAR];
    mlg_equilibrium(&flat_on, -1.0, u);
    mlg_rhs_jacobian(&flat_off, u, f, J0, NULL);
    mlg_rhs_jacobian(&flat_on, u, f, J1, P);
    int row = MLG_PSI_DOT, col = MLG_PSI_DOT;
    check_rel("viscous_at_stick", J0[row + MLG_NX * col] - J1[row + MLG_NX * col],
              on.M_fric * on.r_seal / (on.v_fric * on.I_psi), 1e-12);
    check(P[row + MLG_NX * MLG_PAR_M_fric] == 0.0, "no_friction_moment_at_rest",
          "d(psi'')/dM_fric = %g at straight rolling", P[row + MLG_NX * MLG_PAR_M_fric]);

    /* zero size: the same f and Jacobians, to the bit, whatever v_fric and r_seal */
    mlg_params zero = on;
    zero.M_fric = zero.F_fric = 0.0;
    mlg_params other = zero;
    other.v_fric = 0.3, other.r_seal = 0.05;
    int same = 1;
    for (int i = 0; i < 50; i++) {
        double x[MLG_NX], f1[MLG_NX], f2[MLG_NX], A[MLG_NX * MLG_NX], B[MLG_NX * MLG_NX];
        mlg_equilibrium(&zero, -1.0, x);
        x[MLG_PSI] += 1e-4 * (i - 25), x[MLG_PSI_DOT] = 0.01 * (i - 25) * on.v_fric;
        x[MLG_ETA_DOT] = 0.02 * (i % 9 - 4) * on.v_fric;
        mlg_rhs_jacobian(&zero, x, f1, A, NULL);
        mlg_rhs_jacobian(&other, x, f2, B, NULL);
        same &= memcmp(f1, f2, sizeof f1) == 0 && memcmp(A, B, sizeof A) == 0;
    }
    check(same, "zero_friction_leaves_the_model", "50 states near stick, f and df/du %s",
          same ? "bitwise equal" : "differ");

    char msg[256];
    mlg_params bad = on;
    bad.v_fric = 0.0;
    check(mlg_params_check(&bad, msg, sizeof msg) && strstr(msg, "v_fric") != NULL,
          "v_fric_must_be_positive", "%s", msg);
    bad = on;
    bad.M_fric = -1.0;
    int refused = mlg_params_check(&bad, msg, sizeof msg);
    check(refused && strstr(msg, "parameter M_fric = -1 N m") != NULL,
          "M_fric_must_be_non_negative", "%s", msg);
    return unit_exit();
}
