/* Linear modes of straight rolling (LAPACK dgeev on the analytic Jacobian)
 * and the zero-freeplay Hopf speed found by scanning them over V, against
 * docs/model.md (sections 5 and 7). */
#include <stdlib.h>

#include "mlg_model.h"
#include "unit.h"

void dgeev_(const char *jobvl, const char *jobvr, const int *n, double *a, const int *lda,
            double *wr, double *wi, double *vl, const int *ldvl, double *vr, const int *ldvr,
            double *work, const int *lwork, int *info);

/* Eigenvalues of df/du at u; returns the largest real part. */
static double spectrum(const mlg_params *p, const double *u, double *wr, double *wi)
{
    double f[MLG_NX], J[MLG_NX * MLG_NX], work[8 * MLG_NX], dummy[1];
    int n = MLG_NX, lwork = 8 * MLG_NX, one = 1, info;
    mlg_rhs_jacobian(p, u, f, J, NULL);
    dgeev_("N", "N", &n, J, &n, wr, wi, dummy, &one, dummy, &one, work, &lwork, &info);
    if (info != 0) abort();
    double m = -INFINITY;
    for (int i = 0; i < MLG_NX; i++) m = fmax(m, wr[i]);
    return m;
}

static double growth(mlg_params p, double V, const double *u)
{
    double wr[MLG_NX], wi[MLG_NX];
    p.V = V;
    return spectrum(&p, u, wr, wi);
}

/* The V in [1, 600] where straight rolling loses stability (bisection). */
static double hopf_speed(mlg_params p)
{
    double u[MLG_NX];
    mlg_equilibrium(&p, -1.0, u);
    double lo = 1.0, hi = 600.0;
    if (growth(p, lo, u) >= 0.0 || growth(p, hi, u) <= 0.0) return NAN;
    while (hi - lo > 1e-6) {
        double mid = 0.5 * (lo + hi);
        if (growth(p, mid, u) < 0.0) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(void)
{
    mlg_params p = mlg_params_table();
    p.Fstar = 1.0;
    p.V = 100.0;
    double u[MLG_NX], wr[MLG_NX], wi[MLG_NX];
    mlg_equilibrium(&p, -1.0, u);
    double max_re = spectrum(&p, u, wr, wi);
    double freq[MLG_NX];
    int nf = 0;
    for (int i = 0; i < MLG_NX; i++)
        if (wi[i] > 0.0) freq[nf++] = wi[i] / (2.0 * MLG_PI);
    qsort(freq, nf, sizeof freq[0], by_value);
    check(nf == 4, "four_oscillatory_modes", "%d complex pairs", nf);
    check(max_re < 0.0, "stable_at_V100", "max Re = %.4g", max_re);
    if (nf == 4) {
        /* notes: about 1.61 (axial), 7.89 (longitudinal), 12.5 (lateral), 39.05 (torsion) Hz */
        check(fabs(freq[0] - 1.61) <= 0.005, "axial_mode_Hz", "%.4f Hz, notes 1.61", freq[0]);
        check(fabs(freq[1] - 7.89) <= 0.005, "longitudinal_mode_Hz", "%.4f Hz, notes 7.89",
              freq[1]);
        check(fabs(freq[2] - 12.5) <= 0.05, "lateral_mode_Hz", "%.4f Hz, notes 12.5", freq[2]);
        check(fabs(freq[3] - 39.05) <= 0.005, "torsion_mode_Hz", "%.4f Hz, notes 39.05",
              freq[3]);
    }

    /* zero-freeplay Hopf speed at F* = 1 (docs/model.md 5) */
    p.c_psi = 410.0;
    double V410 = hopf_speed(p);
    check(fabs(V410 - 193.0) <= 1.0, "hopf_speed_c_psi_410", "V_H = %.3f m/s, notes about 193",
          V410);
    p.c_psi = 730.0;
    double V730 = hopf_speed(p);
    check(V730 >= 346.0 && V730 <= 351.0, "hopf_speed_c_psi_730",
          "V_H = %.3f m/s, notes about 346-351", V730);
    mlg_params fig = mlg_params_figures();
    fig.Fstar = 1.0;
    double Vfig = hopf_speed(fig);
    check(fabs(Vfig - 346.1) <= 0.05, "hopf_speed_figures_set",
          "V_H = %.3f m/s with c_psi = %.3f, paper 346.1", Vfig, fig.c_psi);
    return unit_exit();
}
