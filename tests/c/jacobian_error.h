/* The analytic (forward-mode) Jacobians df/du and df/dp of one sample
 * (state_samples.h) against central finite differences of the plain-double
 * vector field, in the modes the sample holds.
 *
 * Error measure: row-scaled maximum norm.  With s_j the scale of variable j
 * (the finite-difference step is 1e-4 s_j), the scaled entry is
 * J_ij s_j / max_k |J_ik s_k|, and the error is the largest difference of
 * scaled entries between analytic and finite-difference Jacobians.  The
 * difference quotient is Richardson-extrapolated from steps h and h/2
 * (truncation error O(h^4)).  Used by test_jacobian.c over every sample and
 * by an effect's own test at its parameter's values. */
#ifndef MLG_JACOBIAN_ERROR_H
#define MLG_JACOBIAN_ERROR_H

#include "state_samples.h"

/* Central difference of f in direction j (state j, or parameter j - MLG_NX). */
static void difference(const sample *s, int j, double h, double *df)
{
    double fp[MLG_NX], fm[MLG_NX];
    for (int sign = -1; sign <= 1; sign += 2) {
        sample t = *s;
        if (j < MLG_NX) {
            t.u[j] += sign * h;
        } else {
            double par[MLG_PAR_SLOTS];
            mlg_params_get_par(&t.p, par);
            par[j - MLG_NX] += sign * h;
            mlg_params_set_par(&t.p, par);
        }
        mlg_rhs_in_modes(&t.p, t.modes, t.u, sign > 0 ? fp : fm);
    }
    for (int i = 0; i < MLG_NX; i++) df[i] = (fp[i] - fm[i]) / (2.0 * h);
}

static void richardson(const sample *s, int j, double h, double *df)
{
    double d1[MLG_NX], d2[MLG_NX];
    difference(s, j, h, d1);
    difference(s, j, 0.5 * h, d2);
    for (int i = 0; i < MLG_NX; i++) df[i] = (4.0 * d2[i] - d1[i]) / 3.0;
}

/* The row-scaled errors of df/du (*err_u) and df/dp (*err_p) at the sample;
 * returns the status of its Jacobian (errors 0 unless MLG_OK). */
static int jacobian_error(const sample *s, double *err_u, double *err_p)
{
    double f[MLG_NX], J[MLG_NX * MLG_NX], P[MLG_NX * MLG_NPAR];
    *err_u = *err_p = 0.0;
    int status = mlg_rhs_jacobian_in_modes(&s->p, s->modes, s->u, f, J, P);
    if (status != MLG_OK) return status;
    double scale[MLG_NDIR], fd[MLG_NDIR][MLG_NX], row[MLG_NX];
    scales(s, scale);
    /* near the stroke's top-out term F_topout / eta, a first difference needs
     * steps small against eta (test_forms' third differences do not: roundoff) */
    scale[MLG_ETA] = fmin(scale[MLG_ETA], 0.1 * s->u[MLG_ETA]);
    for (int j = 0; j < MLG_NDIR; j++)
        if (scale[j] > 0.0) richardson(s, j, 1e-4 * scale[j], fd[j]);
    /* stuck, the twist's acceleration is zero by construction (at eom_terms 0
     * psi'' itself): its rows are measured against their size when sliding */
    double Jslip[MLG_NX * MLG_NX], Pslip[MLG_NX * MLG_NPAR];
    int stuck = s->p.friction_law == 1.0 && s->modes[MLG_DISCRETE_FRICTION] == MLG_MODE_STICK;
    if (stuck) {
        sample t = *s;
        t.modes[MLG_DISCRETE_FRICTION] = MLG_MODE_SLIP_POS;
        mlg_rhs_jacobian_in_modes(&t.p, t.modes, t.u, f, Jslip, Pslip);
    }
    for (int i = 0; i < MLG_NX; i++) {
        row[i] = 0.0;
        for (int j = 0; j < MLG_NDIR; j++) {
            double an = j < MLG_NX ? J[i + MLG_NX * j] : P[i + MLG_NX * (j - MLG_NX)];
            row[i] = fmax(row[i], fabs(an) * scale[j]);
            if (stuck) {
                double slid = j < MLG_NX ? Jslip[i + MLG_NX * j]
                                         : Pslip[i + MLG_NX * (j - MLG_NX)];
                row[i] = fmax(row[i], fabs(slid) * scale[j]);
            }
        }
    }
    for (int i = 0; i < MLG_NX; i++) {
        if (row[i] == 0.0) continue;
        for (int j = 0; j < MLG_NDIR; j++) {
            if (scale[j] == 0.0) continue;
            double an = j < MLG_NX ? J[i + MLG_NX * j] : P[i + MLG_NX * (j - MLG_NX)];
            double err = fabs(an - fd[j][i]) * scale[j] / row[i];
            if (j < MLG_NX) *err_u = fmax(*err_u, err);
            else *err_p = fmax(*err_p, err);
        }
    }
    return MLG_OK;
}

#endif
