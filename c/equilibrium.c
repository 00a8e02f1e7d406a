/* Straight-rolling equilibrium: Newton on f(u) = 0 (all rates zero). */
#include <math.h>
#include <string.h>

#include "linear_solve.h"
#include "mlg_model.h"
#include "params_unusable.h"
#define DUAL_N 0
#include "geometry.h"
#include "strut.h"

/* Static axial balance at beta = 0 (eq. 4 with zero rates): F_keta = F_z cos(phi0). */
static double axial_residual(const mlg_params *p, double eta, double cos_phi)
{
    return strut_spring_force(&p->constants, d_const(eta)).v - p->Fstar * p->g_0 * p->m_0 * cos_phi;
}

/* Smallest root of the static axial balance in (0, z_tlk0), by scan and bisection. */
static double smallest_axial_root(const mlg_params *p, double cos_phi)
{
    const int steps = 4000;
    double lo = 1e-7, f_lo = axial_residual(p, lo, cos_phi);
    for (int k = 1; k <= steps; k++) {
        double hi = p->z_tlk0 * k / steps - 1e-9, f_hi = axial_residual(p, hi, cos_phi);
        if ((f_lo <= 0.0) != (f_hi <= 0.0)) {
            for (int it = 0; it < 200 && hi - lo > 1e-15; it++) {
                double mid = 0.5 * (lo + hi), f_mid = axial_residual(p, mid, cos_phi);
                if ((f_mid <= 0.0) == (f_lo <= 0.0)) {
                    lo = mid;
                    f_lo = f_mid;
                } else {
                    hi = mid;
                }
            }
            return 0.5 * (lo + hi);
        }
        lo = hi;
        f_lo = f_hi;
    }
    return -1.0;
}

static double residual_norm(const double f[MLG_NX])
{
    double sum = 0.0;
    for (int i = 0; i < MLG_NX; i++) sum += f[i] * f[i];
    return sqrt(sum);
}

int mlg_equilibrium(const mlg_params *p_in, double eta_guess, double u[MLG_NX])
{
    /* The equilibrium does not depend on V (rates vanish, and V cancels from
     * eqs. 5-6), but at V = 0 the tyre states are undetermined: solve at V >= 1. */
    if (mlg_params_unusable(p_in, NULL, 0)) return MLG_BAD_PARAMETER;
    mlg_params p = *p_in;
    if (p.V < 1.0) p.V = 1.0;
    /* at rest Coulomb's stick holds any twist within M_fric: the equilibrium
     * without that band is the regularised law's, where friction is zero */
    p.friction_law = 0.0;
    memset(u, 0, sizeof(double) * MLG_NX);
    if (eta_guess <= 0.0) {
        model_parameters mp = model_parameters_seed(&p, MLG_PARS_PLAIN);
        sidestay g = sidestay_geometry(&mp);
        eta_guess = smallest_axial_root(&p, g.H1.v + g.H3.v);
        if (eta_guess <= 0.0) return -1;
    }
    u[MLG_ETA] = eta_guess;

    /* Newton with backtracking on |f|: the oleo's stage switch is a step of
     * width ~1/k_stage in eta, where full Newton steps overshoot. */
    double f[MLG_NX], J[MLG_NX * MLG_NX];
    for (int it = 0; it < 100; it++) {
        int status = mlg_rhs_jacobian(&p, u, f, J, NULL);
        if (status != MLG_OK) return status;
        double step[MLG_NX];
        for (int i = 0; i < MLG_NX; i++) step[i] = -f[i];
        double norm = residual_norm(f), size = 0.0, trial[MLG_NX], f_trial[MLG_NX];
        /* at a bifurcation point J is singular, and no step reduces a
         * residual at rounding level: that is convergence */
        if (mlg_linear_solve(MLG_NX, J, step) != 0) return norm < 1e-6 ? MLG_OK : -1;
        int improved = 0;
        for (double scale = 1.0; scale > 1e-4 && !improved; scale *= 0.5) {
            for (int i = 0; i < MLG_NX; i++) trial[i] = u[i] + scale * step[i];
            improved = trial[MLG_ETA] > 0.0 && trial[MLG_ETA] < p.z_tlk0 &&
                       mlg_rhs(&p, trial, f_trial) == MLG_OK && residual_norm(f_trial) < norm;
        }
        if (!improved) return norm < 1e-6 ? MLG_OK : -1;
        for (int i = 0; i < MLG_NX; i++) {
            size = fmax(size, fabs(trial[i] - u[i]));
            u[i] = trial[i];
        }
        if (size < 1e-13) return mlg_rhs(&p, u, f);
    }
    return -1;
}
