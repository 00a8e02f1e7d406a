/* AUTO-07p equations file for the MLG model: a thin layer over the c/
 * library (c/mlg_model.h).  Built by the Makefile (c/c.mk, mk/auto.mk) into
 * build/models/mlg.exe, linked with build/lib/libmlg.a.
 *
 * PAR(1..10): the continuation parameters of c/parameters.h, in that order.
 * PAR(11): period (AUTO).  PAR(21..28): solution measures written by PVLS. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "auto_f2c.h"
#include "mlg_model.h"

/* Solution measures, 1-based AUTO indices (constants/c.mlg names them). */
enum {
    PAR_PERIOD = 11,
    PAR_PSI_AMP = 21,    /* (max - min)/2 of psi [rad] */
    PAR_DELTA_AMP,       /* (max - min)/2 of delta [rad] */
    PAR_BETA_MEAN,       /* mean of beta over a period [rad] */
    PAR_BETA_AMP,
    PAR_ETA_MEAN,        /* mean of eta [m] */
    PAR_ETA_AMP,
    PAR_FREQ,            /* 1/T [Hz]; 0 on equilibria */
    PAR_PSI_MEAN         /* mean of psi [rad]: the yaw of off-centre equilibria */
};

/* Report a rejected evaluation once per kind, and answer it with a large
 * residual so that AUTO's Newton iteration rejects the step (MX if it
 * persists; the drivers report MX). */
static void reject(const char *what, const char *detail, integer ndim, doublereal *f)
{
    static char last[256];
    char line[sizeof last];
    snprintf(line, sizeof line, "mlg: %s: %s", what, detail);
    if (strcmp(line, last) != 0) {
        fprintf(stderr, "%s\n", line);
        snprintf(last, sizeof last, "%s", line);
    }
    for (integer i = 0; i < ndim; i++) f[i] = 1e30;
}

int func(integer ndim, const doublereal *u, const integer *icp, const doublereal *par,
         integer ijac, doublereal *f, doublereal *dfdu, doublereal *dfdp)
{
    /* Drivers validate the starting parameters; a continuation step that
     * leaves the physical range (V < 0, y_fp < 0, ...) is rejected here. */
    mlg_params p = mlg_params_table();
    char msg[200];
    mlg_params_set_par(&p, par);
    if (mlg_params_check(&p, msg, sizeof msg) != 0) {
        reject("invalid parameters", msg, ndim, f);
        return 0;
    }
    double J[MLG_NX * MLG_NX], P[MLG_NX * MLG_NPAR];
    int status = ijac == 0 ? mlg_rhs(&p, u, f)
                           : mlg_rhs_jacobian(&p, u, f, J, ijac == 2 ? P : NULL);
    if (status != MLG_OK) {
        reject("state outside the model's domain", mlg_status_text(status), ndim, f);
        return 0;
    }
    if (ijac == 0) return 0;
    /* AUTO's arrays are column-major with leading dimension ndim, as ours */
    for (int k = 0; k < MLG_NX * MLG_NX; k++) dfdu[k] = J[k];
    if (ijac == 1) return 0;
    for (int k = 0; k < MLG_NX * MLG_NPAR; k++) dfdp[k] = P[k];
    return 0;
}

/* Straight rolling for the parameters below.  AUTO applies the PAR and U
 * values of the constants file after STPNT, so a run at other parameters
 * passes the matching equilibrium in U (drivers/mlgmodel.py computes it). */
int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
    mlg_params p = mlg_params_figures();
    p.V = 50.0;
    p.Fstar = 1.0;
    mlg_params_get_par(&p, par);
    if (mlg_equilibrium(&p, -1.0, u) != 0) {
        fprintf(stderr, "mlg: no straight-rolling equilibrium at the default parameters\n");
        exit(1);
    }
    return 0;
}

int pvls(integer ndim, const doublereal *u, doublereal *par)
{
    const int psi = MLG_PSI + 1, delta = MLG_DELTA + 1, beta = MLG_BETA + 1, eta = MLG_ETA + 1;
    par[PAR_PSI_AMP - 1] = 0.5 * (getp("MAX", psi, u) - getp("MIN", psi, u));
    par[PAR_DELTA_AMP - 1] = 0.5 * (getp("MAX", delta, u) - getp("MIN", delta, u));
    par[PAR_BETA_MEAN - 1] = getp("INT", beta, u);
    par[PAR_BETA_AMP - 1] = 0.5 * (getp("MAX", beta, u) - getp("MIN", beta, u));
    par[PAR_ETA_MEAN - 1] = getp("INT", eta, u);
    par[PAR_ETA_AMP - 1] = 0.5 * (getp("MAX", eta, u) - getp("MIN", eta, u));
    par[PAR_PSI_MEAN - 1] = getp("INT", psi, u);
    /* DTM (a mesh interval) is 0 for equilibria and positive for orbits */
    int periodic = getp("DTM", 1, u) > 0.0;
    par[PAR_FREQ - 1] = periodic ? 1.0 / par[PAR_PERIOD - 1] : 0.0;
    return 0;
}

/* Unused by this model (no boundary or integral conditions, no optimisation). */
int bcnd(integer ndim, const doublereal *par, const integer *icp, integer nbc,
         const doublereal *u0, const doublereal *u1, integer ijac, doublereal *fb,
         doublereal *dbc)
{
    return 0;
}

int icnd(integer ndim, const doublereal *par, const integer *icp, integer nint,
         const doublereal *u, const doublereal *uold, const doublereal *udot,
         const doublereal *upold, integer ijac, doublereal *fi, doublereal *dint)
{
    return 0;
}

int fopt(integer ndim, const doublereal *u, const integer *icp, const doublereal *par,
         integer ijac, doublereal *fs, doublereal *dfdu, doublereal *dfdp)
{
    return 0;
}
