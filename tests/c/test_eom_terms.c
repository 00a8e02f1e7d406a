/* The eom_terms switch (docs/model.md, section 8).
 *
 * (a) rho = mu = 0: the side-stay corrections (eom_terms = 1) vanish exactly,
 *     so f and df/du are bit-identical to the printed equations (0).
 * (b) rho = mu = 0: the complete equations (2) differ from the printed ones
 *     only at second order in (psi, delta, rates) and in the (beta, eta)
 *     coupling of the vertical load (docs/model.md 4.16): same straight-rolling
 *     equilibrium, same linearisation of the torsional/lateral block (which
 *     holds the shimmy Hopf points), to 1e-12.
 * (c) Mass matrix: with the tyres off (ideal support) and the dampers at zero,
 *     the accelerations (psi'', delta'', beta'', eta'') answer generalised
 *     forces b through M^-1 b.  Four probes whose generalised force is known
 *     (c_psi, zeta_delta, k_beta, c_eta1, each entering linearly) give
 *     M_eff = B A^-1 with A the responses.  For the complete equations M_eff
 *     must equal the Hessian H of the kinetic energy of mlg_energy in the
 *     rates (symmetric positive definite); for the printed ones it does not
 *     at non-zero angles (reported, and required to differ). */
#include <string.h>

#include "mlg_model.h"
#include "near_equilibrium.h"
#include "unit.h"

void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda,
            double *w, double *work, const int *lwork, int *info);

static void identical_at_zero_angles(void)
{
    int same = 1, n_ok = 0;
    double worst_other = 0.0;
    for (int n = 0; n < 300; n++) {
        mlg_params p = mlg_params_table();
        p.Fstar = unit_between(0.1, 3.5);
        p.V = unit_between(0.0, 600.0);
        p.yfp = n % 2 ? 1.0 : 0.0;
        p.strut_variant = (n / 2) % 2;
        double u[MLG_NX], f[2][MLG_NX], J[2][MLG_NX * MLG_NX], P[2][MLG_NX * MLG_NPAR];
        near_equilibrium(&p, u);
        int status = 0;
        for (int k = 0; k < 2; k++) {
            p.eom_terms = k;
            status |= mlg_rhs_jacobian(&p, u, f[k], J[k], P[k]);
        }
        if (status != MLG_OK) continue;
        n_ok++;
        same &= memcmp(f[0], f[1], sizeof f[0]) == 0 && memcmp(J[0], J[1], sizeof J[0]) == 0;
        /* df/dp: equal except d/drho, d/dmu (sin p = 0 but its derivative is not) */
        for (int k = 0; k < MLG_NPAR; k++) {
            if (k == MLG_PAR_rho || k == MLG_PAR_mu) continue;
            for (int i = 0; i < MLG_NX; i++)
                worst_other = fmax(worst_other, fabs(P[0][i + MLG_NX * k] - P[1][i + MLG_NX * k]));
        }
    }
    check(n_ok >= 250, "zero_angles_samples", "%d states", n_ok);
    check(same, "sidestay_terms_bit_identical_at_zero_angles",
          "f and df/du of eom_terms 1 and 0 are %s", same ? "bit-identical" : "different");
    check(worst_other == 0.0, "sidestay_terms_dfdp_identical_at_zero_angles",
          "max |difference| %.2e in the columns other than rho, mu", worst_other);
}

static int odd(int i)
{
    return i == MLG_PSI || i == MLG_DELTA || i == MLG_PSI_DOT || i == MLG_DELTA_DOT ||
           i == MLG_LAMBDA_L || i == MLG_LAMBDA_R;
}

static void complete_linearisation_at_zero_angles(void)
{
    double worst_u = 0.0, worst_odd = 0.0, even_diff = 0.0;
    for (int n = 0; n < 40; n++) {
        mlg_params p = mlg_params_figures();
        p.Fstar = unit_between(0.1, 3.5);
        p.V = unit_between(1.0, 600.0);
        p.yfp = n % 2 ? 1.0 : 0.0;
        double u[2][MLG_NX], f[MLG_NX], J[2][MLG_NX * MLG_NX];
        for (int k = 0; k < 2; k++) {
            p.eom_terms = 2 * k;
            mlg_equilibrium(&p, -1.0, u[k]);
            mlg_rhs_jacobian(&p, u[0], f, J[k], NULL);
        }
        for (int i = 0; i < MLG_NX; i++) worst_u = fmax(worst_u, fabs(u[0][i] - u[1][i]));
        for (int i = 0; i < MLG_NX; i++) {
            double row = 0.0;
            for (int j = 0; j < MLG_NX; j++) row = fmax(row, fabs(J[0][i + MLG_NX * j]));
            for (int j = 0; j < MLG_NX; j++) {
                double d = fabs(J[0][i + MLG_NX * j] - J[1][i + MLG_NX * j]) / row;
                if (odd(i) && odd(j)) worst_odd = fmax(worst_odd, d);
                else if (!odd(i) && !odd(j)) even_diff = fmax(even_diff, d);
            }
        }
    }
    check(worst_u <= 1e-12, "complete_same_equilibrium_at_zero_angles",
          "max |u_2 - u_0| = %.2e", worst_u);
    check(worst_odd <= 1e-12, "complete_same_odd_block_at_zero_angles",
          "max row-scaled difference %.2e (the (beta, eta) block differs by %.2e: "
          "the load counted once, docs/model.md 4.16)", worst_odd, even_diff);
}

/* Accelerations (psi'', delta'', beta'', eta'') at u. */
static void accelerations(const mlg_params *p, const double *u, double *a)
{
    double f[MLG_NX];
    mlg_rhs(p, u, f);
    for (int i = 0; i < 4; i++) a[i] = f[MLG_PSI_DOT + i];
}

/* H_ij = d2 T / d rate_i d rate_j, central second differences (T is quadratic) */
static void kinetic_hessian(const mlg_params *p, const double *u, double *H)
{
    const double h = 0.1;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double sum = 0.0;
            for (int si = -1; si <= 1; si += 2)
                for (int sj = -1; sj <= 1; sj += 2) {
                    double v[MLG_NX];
                    mlg_energy_parts e;
                    memcpy(v, u, sizeof v);
                    v[MLG_PSI_DOT + i] += si * h;
                    v[MLG_PSI_DOT + j] += sj * h;
                    mlg_energy(p, v, u[MLG_ETA], &e);
                    sum += si * sj * e.kinetic;
                }
            H[i + 4 * j] = sum / (4.0 * h * h);
        }
}

/* Solve X A = B for X (4x4, column-major) by Gauss-Jordan on A^T X^T = B^T. */
static void right_divide(const double *B, const double *A, double *X)
{
    double m[4][8];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            m[i][j] = A[j + 4 * i];          /* A^T */
            m[i][4 + j] = B[j + 4 * i];      /* B^T */
        }
    for (int c = 0; c < 4; c++) {
        int piv = c;
        for (int r = c + 1; r < 4; r++) if (fabs(m[r][c]) > fabs(m[piv][c])) piv = r;
        for (int k = 0; k < 8; k++) { double t = m[c][k]; m[c][k] = m[piv][k]; m[piv][k] = t; }
        for (int r = 0; r < 4; r++) {
            if (r == c) continue;
            double q = m[r][c] / m[c][c];
            for (int k = 0; k < 8; k++) m[r][k] -= q * m[c][k];
        }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) X[j + 4 * i] = m[i][4 + j] / m[i][i];   /* X = (X^T)^T */
}

/* M_eff = B A^-1 from the four probes; returns max |M_eff - H| / max |H| and
 * the asymmetry max |M_eff - M_eff^T| / max |H|; H's smallest eigenvalue in *lmin. */
static double mass_matrix_error(mlg_params p, const double *u, double *asym, double *lmin)
{
    static const char *probe[4] = {"c_psi", "zeta_delta", "k_beta", "c_eta1"};
    static const double step[4] = {10.0, 1e-3, 1e5, 100.0};
    mlg_diagnostics d;
    mlg_diagnose(&p, u, &d);
    double sin_p = sin(d.p);
    double twist = u[MLG_PSI_DOT] + (p.eom_terms >= 1 ? u[MLG_BETA_DOT] * sin_p : 0.0);
    /* generalised force per unit probe value, columns in (psi, delta, beta, eta) */
    double B[16] = {0};
    B[0 + 4 * 0] = -twist;
    B[2 + 4 * 0] = -twist * sin_p;
    B[1 + 4 * 1] = -sqrt(d.I_delta * d.k_delta) * u[MLG_DELTA_DOT];
    B[2 + 4 * 2] = -u[MLG_BETA];
    B[3 + 4 * 3] = -u[MLG_ETA_DOT];
    double A[16], M[16], H[16];
    for (int j = 0; j < 4; j++) {
        double ap[4], am[4];
        mlg_params q = p;
        double *ref = mlg_param_ref(&q, probe[j]), base = *ref;
        *ref = base + step[j];
        accelerations(&q, u, ap);
        *ref = base - step[j];
        accelerations(&q, u, am);
        for (int i = 0; i < 4; i++) A[i + 4 * j] = (ap[i] - am[i]) / (2.0 * step[j]);
    }
    right_divide(B, A, M);
    kinetic_hessian(&p, u, H);
    double scale = 0.0, err = 0.0;
    *asym = 0.0;
    for (int k = 0; k < 16; k++) scale = fmax(scale, fabs(H[k]));
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            err = fmax(err, fabs(M[i + 4 * j] - H[i + 4 * j]) / scale);
            *asym = fmax(*asym, fabs(M[i + 4 * j] - M[j + 4 * i]) / scale);
        }
    double w[4], work[64];
    int n = 4, lwork = 64, info;
    dsyev_("N", "U", &n, H, &n, w, work, &lwork, &info);
    *lmin = info == 0 ? w[0] : -1.0;
    return err;
}

static void mass_matrix(void)
{
    double worst = 0.0, worst_asym = 0.0, lmin = INFINITY, printed_err = INFINITY;
    int n_ok = 0;
    for (int n = 0; n < 60; n++) {
        mlg_params p = mlg_params_table();
        p.Fstar = unit_between(0.3, 3.0);
        p.rho = unit_between(-0.5, 0.5);
        p.mu = unit_between(-0.5, 0.5);
        p.yfp = n % 2 ? 1.0 : 0.0;
        p.tyre_forces = 0.0;
        p.c_psi = p.c_beta = p.zeta_delta = p.c_eta1 = p.c_eta2a = p.c_eta2b = 0.0;
        double u[MLG_NX], f[MLG_NX], asym, l;
        p.eom_terms = MLG_EOM_COMPLETE;
        near_equilibrium(&p, u);
        if (mlg_rhs(&p, u, f) != MLG_OK) continue;
        n_ok++;
        worst = fmax(worst, mass_matrix_error(p, u, &asym, &l));
        worst_asym = fmax(worst_asym, asym);
        lmin = fmin(lmin, l);
        p.eom_terms = MLG_EOM_PRINTED;
        printed_err = fmin(printed_err, mass_matrix_error(p, u, &asym, &l));
    }
    check(n_ok >= 50, "mass_matrix_samples", "%d states, |rho|, |mu| <= 0.5", n_ok);
    check(worst <= 1e-7, "complete_mass_matrix_is_kinetic_hessian",
          "max |M_eff - H| / max |H| = %.2e", worst);
    check(worst_asym <= 1e-7, "complete_mass_matrix_symmetric", "asymmetry %.2e", worst_asym);
    check(lmin > 0.0, "mass_matrix_positive_definite", "smallest eigenvalue %.4g", lmin);
    check(printed_err > 1e-4, "printed_mass_matrix_differs",
          "printed equations: min over states of max |M_eff - H| / max |H| = %.2e", printed_err);
}

int main(void)
{
    identical_at_zero_angles();
    complete_linearisation_at_zero_angles();
    mass_matrix();
    return unit_exit();
}
