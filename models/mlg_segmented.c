/* AUTO-07p equations file: periodic orbits of the non-smooth freeplay law
 * (14) as a segmented boundary-value problem (IPS = 4), a thin layer over
 * the c/ library like models/mlg.c (docs/model.md 9.6).
 *
 * The orbit visits the modes of eq. (14) (gap, contact+, contact-) in a
 * fixed sequence of NSEG = NDIM / MLG_NX segments.  Segment k holds the
 * state u_k(s), s in [0, 1], in mode PAR(SEG_MODE + k) for a duration
 * T_k = PAR(SEG_DURATION + k):
 *     u_k' = T_k f_{mode k}(u_k),
 *     u_k(1) = u_{k+1}(0)  (u_NSEG(1) = u_1(0): periodic),
 *     h(u_k(1)) = 0        on the surface between mode k and mode k+1.
 * The field of eq. (14) is continuous across h = 0, so the state is too
 * (no reset).  The switch that ends the last segment anchors the orbit's
 * phase: no integral condition.  NBC = NSEG (MLG_NX + 1), NINT = 0: the free
 * parameters are the continuation parameter and the NSEG durations.
 * A duration that passes through zero is a grazing (a UZ of the driver).
 *
 * PAR as models/mlg.c; PAR(11) is the period sum T_k, written by PVLS with
 * the measures of MLG_MEASURES taken over all segments. */
#include "auto_plugin.h"

#define SEG_MAX 8            /* segments at most */
#define SEG_DURATION 30      /* T_k is PAR(SEG_DURATION + k), k = 1..NSEG */
#define SEG_MODE 40          /* the mode of segment k is PAR(SEG_MODE + k) */

static int segments(integer ndim)
{
    return (int)(ndim / MLG_NX);
}

static int mode_of(const doublereal *par, int k)
{
    return (int)par[SEG_MODE + k];     /* PAR(SEG_MODE + k + 1), 0-based k */
}

/* The switching function between modes a and b (adjacent in eq. (14): one
 * of them the gap), or -1 */
static int surface_between(int a, int b)
{
    if (a == b || (a != MLG_MODE_GAP && b != MLG_MODE_GAP)) return -1;
    int contact = a == MLG_MODE_GAP ? b : a;
    return contact == MLG_MODE_CONTACT_POS ? MLG_SWITCH_freeplay_upper
         : contact == MLG_MODE_CONTACT_NEG ? MLG_SWITCH_freeplay_lower : -1;
}

/* NULL if the segments, their modes and the law fit, else why not */
static const char *sequence_invalid(integer ndim, const doublereal *par, const mlg_params *p)
{
    static char why[200];
    int n = segments(ndim);
    if (ndim % MLG_NX != 0 || n < 2 || n > SEG_MAX) {
        snprintf(why, sizeof why, "NDIM = %ld must be %d x (2 to %d segments)", (long)ndim,
                 MLG_NX, SEG_MAX);
        return why;
    }
    if (!mlg_switching_applies(p, MLG_SWITCH_freeplay_upper))
        return "the segmented orbits need freeplay_law nonsmooth (eq. 14) and yfp > 0";
    for (int k = 0; k < n; k++) {
        if (surface_between(mode_of(par, k), mode_of(par, (k + 1) % n)) < 0) {
            snprintf(why, sizeof why, "segment modes PAR(%d) = %g, PAR(%d) = %g: adjacent "
                     "segments must be the gap and a contact mode (0 gap, 1 contact+, "
                     "2 contact-)", SEG_MODE + k + 1, par[SEG_MODE + k],
                     SEG_MODE + (k + 1) % n + 1, par[SEG_MODE + (k + 1) % n]);
            return why;
        }
    }
    return NULL;
}

int func(integer ndim, const doublereal *u, const integer *icp, const doublereal *par,
         integer ijac, doublereal *f, doublereal *dfdu, doublereal *dfdp)
{
    static int started;
    mlg_params p;
    const char *invalid = parameters_for(par, &p);
    if (invalid == NULL) invalid = sequence_invalid(ndim, par, &p);
    if (invalid) {
        start_failed(started, "invalid starting parameters", invalid);
        reject(ndim, f);
        return 0;
    }
    int n = segments(ndim);
    if (ijac > 0)
        memset(dfdu, 0, sizeof *dfdu * (size_t)(ndim * ndim));
    for (int k = 0; k < n; k++) {
        int modes[MLG_NDISCRETE] = {[MLG_DISCRETE_FREEPLAY] = mode_of(par, k),
                                    [MLG_DISCRETE_FRICTION] = MLG_MODE_BY_STATE};
        int row = MLG_NX * k;
        double T = par[SEG_DURATION + k], fk[MLG_NX], J[MLG_NX * MLG_NX], P[MLG_NX * MLG_NPAR];
        int status = ijac == 0 ? mlg_rhs_in_modes(&p, modes, u + row, fk)
                               : mlg_rhs_jacobian_in_modes(&p, modes, u + row, fk, J,
                                                           ijac == 2 ? P : NULL);
        if (status != MLG_OK) {
            start_failed(started, "starting point outside the model's domain",
                         mlg_status_text(status));
            reject(ndim, f);
            return 0;
        }
        for (int i = 0; i < MLG_NX; i++) f[row + i] = T * fk[i];
        if (ijac == 0) continue;
        for (int j = 0; j < MLG_NX; j++)
            for (int i = 0; i < MLG_NX; i++)
                dfdu[(row + i) + ndim * (row + j)] = T * J[i + MLG_NX * j];
        if (ijac == 1) continue;
        for (int q = 0; q < MLG_NPAR; q++)
            for (int i = 0; i < MLG_NX; i++)
                dfdp[(row + i) + ndim * q] = T * P[i + MLG_NX * q];
        for (int m = 0; m < n; m++)   /* d/dT_m: the field in segment m only */
            for (int i = 0; i < MLG_NX; i++)
                dfdp[(row + i) + ndim * (SEG_DURATION + m)] = m == k ? fk[i] : 0.0;
    }
    started = 1;
    return 0;
}

/* h of the surface ending segment k, at u (and its gradient in dh) */
static int switch_value(const mlg_params *p, const doublereal *par, int n, int k,
                        const double *u, double *h, double dh[MLG_NX])
{
    int s = surface_between(mode_of(par, k), mode_of(par, (k + 1) % n));
    double all[MLG_NSWITCH], grad[MLG_NSWITCH * MLG_NX];
    int status = mlg_switching(p, NULL, u, all, grad);
    *h = all[s];
    if (dh != NULL) memcpy(dh, grad + MLG_NX * s, sizeof grad[0] * MLG_NX);
    return status;
}

int bcnd(integer ndim, const doublereal *par, const integer *icp, integer nbc,
         const doublereal *u0, const doublereal *u1, integer ijac, doublereal *fb,
         doublereal *dbc)
{
    mlg_params p;
    if (parameters_for(par, &p) != NULL || sequence_invalid(ndim, par, &p) != NULL) {
        reject(nbc, fb);    /* func, called first, has said why */
        return 0;
    }
    int n = segments(ndim);
    integer cols = 2 * ndim;
    if (ijac > 0) memset(dbc, 0, sizeof *dbc * (size_t)(nbc * cols));
    for (int k = 0; k < n; k++) {      /* continuity: u_k(1) = u_{k+1}(0) */
        int next = MLG_NX * ((k + 1) % n);
        for (int i = 0; i < MLG_NX; i++) {
            integer b = MLG_NX * k + i;
            fb[b] = u1[MLG_NX * k + i] - u0[next + i];
            if (ijac == 0) continue;
            dbc[b + nbc * (ndim + MLG_NX * k + i)] = 1.0;
            dbc[b + nbc * (next + i)] = -1.0;
        }
    }
    for (int k = 0; k < n; k++) {      /* h = 0 where segment k ends */
        integer b = MLG_NX * n + k;
        double dh[MLG_NX];
        if (switch_value(&p, par, n, k, u1 + MLG_NX * k, &fb[b], dh) != MLG_OK) {
            reject(nbc, fb);
            return 0;
        }
        if (ijac == 0) continue;
        for (int j = 0; j < MLG_NX; j++) dbc[b + nbc * (ndim + MLG_NX * k + j)] = dh[j];
    }
    if (ijac < 2) return 0;
    /* d/dPAR: the continuity rows and the durations' columns are zero; h
     * depends on y_fp and the side-stay angles among PAR(1-MLG_NPAR) (not
     * on V), by central differences there */
    doublereal shifted[SEG_MODE + SEG_MAX];
    memcpy(shifted, par, sizeof shifted);
    for (int q = 0; q < MLG_NPAR; q++) {
        double step = 1e-6 * fmax(1.0, fabs(par[q])), h[2];
        for (int k = 0; k < n; k++) {
            for (int side = 0; side < 2; side++) {
                shifted[q] = par[q] + (side ? step : -step);
                parameters_for(shifted, &p);
                switch_value(&p, shifted, n, k, u1 + MLG_NX * k, &h[side], NULL);
            }
            dbc[(MLG_NX * n + k) + nbc * (cols + q)] = (h[1] - h[0]) / (2.0 * step);
        }
        shifted[q] = par[q];
    }
    parameters_for(par, &p);
    for (int k = 0; k < n; k++)
        for (integer b = 0; b < nbc; b++) dbc[b + nbc * (cols + SEG_DURATION + k)] = 0.0;
    return 0;
}

int icnd(integer ndim, const doublereal *par, const integer *icp, integer nint,
         const doublereal *u, const doublereal *uold, const doublereal *udot,
         const doublereal *upold, integer ijac, doublereal *fi, doublereal *dint)
{
    return 0;     /* the phase: anchored on the last switch (bcnd) */
}

/* The parameters of the `figures` set at V = 50 m/s, F* = 1; the run gives
 * PAR (the modes, the durations) and the starting orbit (dat). */
int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
    mlg_params p = mlg_params_figures();
    p.V = 50.0;
    p.Fstar = 1.0;
    mlg_params_get_par(&p, par);
    return 0;
}

enum measure_kind { AMP, MEAN, FREQ };
static doublereal measure(enum measure_kind kind, int state, int n, const doublereal *u,
                          const doublereal *par, double period)
{
    double hi = -INFINITY, lo = INFINITY, mean = 0.0;
    for (int k = 0; k < n; k++) {
        integer c = MLG_NX * k + state + 1;
        hi = fmax(hi, getp("MAX", c, u));
        lo = fmin(lo, getp("MIN", c, u));
        mean += par[SEG_DURATION + k] * getp("INT", c, u);
    }
    switch (kind) {
    case AMP: return 0.5 * (hi - lo);
    case MEAN: return mean / period;
    case FREQ: return 1.0 / period;
    }
    return 0.0;
}

/* The measures of MLG_MEASURES over all segments: amplitudes from the
 * extremes of every segment, means weighted by the durations, and PAR(11)
 * the period. */
int pvls(integer ndim, const doublereal *u, doublereal *par)
{
    stop_if_not_finite(ndim, u, par);
    int n = segments(ndim);
    double period = 0.0;
    for (int k = 0; k < n; k++) period += par[SEG_DURATION + k];
    par[MLG_PAR_PERIOD - 1] = period;
    int q = MLG_MEASURES_FIRST_PAR - 1;
#define X(name, kind, state, unit, doc) par[q++] = measure(kind, state, n, u, par, period);
    MLG_MEASURES(X)
#undef X
    return 0;
}

int fopt(integer ndim, const doublereal *u, const integer *icp, const doublereal *par,
         integer ijac, doublereal *fs, doublereal *dfdu, doublereal *dfdp)
{
    return 0;
}
