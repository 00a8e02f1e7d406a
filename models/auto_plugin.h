/* What the AUTO equations files of models/ share: the parameters read from
 * AUTO's PAR (validated, the constants file read, once per change), a
 * starting point refused with one message, a step outside the domain
 * answered with a huge residual, and a non-finite solution stopping the run.
 * Included by one equations file each (static functions). */
#ifndef MLG_AUTO_PLUGIN_H
#define MLG_AUTO_PLUGIN_H

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "auto_f2c.h"
#include "mlg_model.h"

/* At the first call (the starting point: STPNT, the constants, a restart)
 * a rejection ends the run with one message; later ones are AUTO's steps. */
static void start_failed(int started, const char *what, const char *why)
{
    if (started) return;
    fprintf(stderr, "mlg: %s: %s\n", what, why);
    exit(1);
}

/* A step outside the domain: a huge residual, so that AUTO's iteration fails
 * and it halves the step.  A finite residual with a regular Jacobian is not
 * enough: on a periodic orbit AUTO solves u' = T f, which any finite f
 * satisfies with T = 0 (Fig. 13's orbits in y_fp then end on such a point).
 * Where the iteration overflows to NaN instead, which AUTO's convergence
 * test takes as converged, pvls stops the run. */
static void reject(integer ndim, doublereal *f)
{
    for (integer i = 0; i < ndim; i++) f[i] = 1e30;
}

/* The constants for PAR(15): the `table` values, overridden by the file
 * mlg.constants.<k> of the run directory for k > 0.  NULL, or why not. */
static const char *read_base(double id, mlg_params *base, char *why, size_t n)
{
    *base = mlg_params_table();
    if (id == 0.0) return NULL;
    if (!(id > 0.0 && id < 1e15 && id == (double)(long long)id)) {
        snprintf(why, n, "parameter constants = %g must be 0 or the number k of a file "
                 "mlg.constants.<k> in the run directory", id);
        return why;
    }
    char path[64];
    snprintf(path, sizeof path, "mlg.constants.%.0f", id);
    return mlg_params_read_constants(base, path, why, n) != 0 ? why : NULL;
}

/* The parameters for par: validated, and the constants file read, only when
 * PAR(1-15) change, so a continuation step costs one comparison and no
 * string handling.  NULL if valid, or a message naming what is invalid. */
static const char *parameters_for(const doublereal *par, mlg_params *p)
{
    static double last[MLG_PAR_SLOTS], base_id = -1.0;
    static mlg_params base, cached;
    static const char *invalid;
    static int known;
    static char why[256];
    if (!known || memcmp(last, par, sizeof last) != 0) {
        memcpy(last, par, sizeof last);
        known = 1;
        double id = par[MLG_PAR_CONSTANTS_FILE - 1];
        invalid = id == base_id ? NULL : read_base(id, &base, why, sizeof why);
        base_id = invalid ? -1.0 : id;
        if (invalid == NULL) {
            cached = base;
            mlg_params_set_par(&cached, par);
            if (mlg_params_check(&cached, why, sizeof why) != 0) invalid = why;
        }
    }
    *p = cached;
    return invalid;
}

/* Exit status of a run stopped at a non-finite solution (drivers read it
 * from the log line, shared/runerror.py NON_FINITE) */
#define NON_FINITE_EXIT 3

/* AUTO accepted a non-finite solution (its convergence test passes NaN):
 * end the run at once, naming where. */
static void stop_if_not_finite(integer ndim, const doublereal *u, const doublereal *par)
{
    for (integer i = 1; i <= ndim; i++) {
        if (!isfinite(getp("NRM", i, u))) {
            fprintf(stderr, "mlg: non-finite solution (component %ld) at V = %g m/s, "
                    "F* = %g: run stopped\n", (long)i, par[MLG_PAR_V],
                    par[MLG_PAR_Fstar]);
            exit(NON_FINITE_EXIT);
        }
    }
}

#endif
