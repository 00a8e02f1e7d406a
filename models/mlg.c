/* AUTO-07p equations file for the MLG model: a thin layer over the c/
 * library (c/mlg_model.h).  Built by the Makefile (c/c.mk, mk/auto.mk) into
 * build/models/mlg.exe, linked with build/lib/libmlg.a.
 *
 * PAR layout: c/mlg_parameters.h and docs/model.md 2.1 (PAR(1-10) continuation
 * parameters, PAR(11) the period, PAR(13-14) switches, PAR(15) the constants
 * file, PAR(21-28) the measures of MLG_MEASURES written by PVLS).
 *
 * Bad starting parameters end the run: one message on stderr naming the
 * parameter and exit status 1 (AUTO's Python interface raises).  Later, a
 * continuation step that leaves the domain is answered with a huge residual,
 * without a message, so that AUTO shortens its step (MX if it persists).  A
 * non-finite solution that AUTO accepts anyway ends the run at once, naming
 * where (pvls). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "auto_f2c.h"
#include "mlg_model.h"
#include "auto_plugin.h"

int func(integer ndim, const doublereal *u, const integer *icp, const doublereal *par,
         integer ijac, doublereal *f, doublereal *dfdu, doublereal *dfdp)
{
    static int started;
    mlg_params p;
    const char *invalid = parameters_for(par, &p);
    if (invalid) {
        start_failed(started, "invalid starting parameters", invalid);
        reject(ndim, f);
        return 0;
    }
    double J[MLG_NX * MLG_NX], P[MLG_NX * MLG_NPAR];
    int status = ijac == 0 ? mlg_rhs(&p, u, f)
                           : mlg_rhs_jacobian(&p, u, f, J, ijac == 2 ? P : NULL);
    if (status != MLG_OK) {
        start_failed(started, "starting point outside the model's domain",
                     mlg_status_text(status));
        reject(ndim, f);
        return 0;
    }
    started = 1;
    if (ijac == 0) return 0;
    /* AUTO's arrays are column-major with leading dimension ndim, as ours */
    for (int k = 0; k < MLG_NX * MLG_NX; k++) dfdu[k] = J[k];
    if (ijac == 1) return 0;
    for (int k = 0; k < MLG_NX * MLG_NPAR; k++) dfdp[k] = P[k];
    return 0;
}

/* The PAR and U values of the constants (c.mlg's PAR = {...}, run(PAR=...)),
 * which AUTO 0.9.2 applies only after STPNT (toolboxae.f90, STPNUS), read
 * from its module AUTO_CONSTANTS: PARVALS and UVALS, arrays of
 * (CHARACTER(13) name or index, value), through gfortran's array descriptor
 * (gfortran >= 8). Weak, and checked: elsewhere nothing is read. */
typedef struct { char index[13]; double value; } auto_indexvar;
typedef struct {
    auto_indexvar *base;
    size_t offset;
    struct { size_t elem_len; int version; signed char rank, type; short attribute; } dtype;
    ptrdiff_t span;
    struct { ptrdiff_t stride, lbound, ubound; } dim[1];
} auto_list;
extern auto_list __auto_constants_MOD_parvals __attribute__((weak));
extern auto_list __auto_constants_MOD_uvals __attribute__((weak));

static ptrdiff_t list_length(const auto_list *list)
{
    if (list == NULL || list->base == NULL || list->dtype.rank != 1 ||
        list->dtype.elem_len != sizeof(auto_indexvar) || list->dim[0].stride != 1)
        return 0;
    return list->dim[0].ubound - list->dim[0].lbound + 1;
}

/* par[] with the constants' PAR values set: by PAR index or by name. */
static void apply_given_par(doublereal *par)
{
    const auto_list *list = &__auto_constants_MOD_parvals;
    for (ptrdiff_t i = 0; i < list_length(list); i++) {
        char name[14];
        memcpy(name, list->base[i].index, 13);
        name[13] = '\0';
        for (int k = 12; k >= 0 && name[k] == ' '; k--) name[k] = '\0';
        char *end;
        long slot = strtol(name, &end, 10);
        if (*end != '\0' || end == name) {
            slot = 0;
            for (int k = 0; k < MLG_PAR_SLOTS && slot == 0; k++)
                if (mlg_par_name(k) && strcmp(mlg_par_name(k), name) == 0) slot = k + 1;
        }
        if (slot >= 1 && slot <= MLG_PAR_SLOTS) par[slot - 1] = list->base[i].value;
    }
}

/* Straight rolling at the PAR the run is given (the constants' PAR over the
 * built-in V = 50 m/s, F* = 1 of the `figures` set), by Newton from the
 * static balance (mlg_equilibrium). Invalid PAR: FUNC's first call says
 * which. With every state given in U, AUTO's U is the start instead. */
int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
    mlg_params p = mlg_params_figures();
    p.V = 50.0;
    p.Fstar = 1.0;
    mlg_params_get_par(&p, par);
    apply_given_par(par);
    if (parameters_for(par, &p) != NULL) return 0;
    if (mlg_equilibrium(&p, -1.0, u) != 0 &&
        list_length(&__auto_constants_MOD_uvals) < MLG_NX) {
        fprintf(stderr, "mlg: no straight-rolling equilibrium at the starting parameters "
                "(V = %g m/s, Fstar = %g): give the starting state in U\n", p.V, p.Fstar);
        exit(1);
    }
    return 0;
}

/* One measure of MLG_MEASURES (c/mlg_parameters.h) on the current solution u. */
enum measure_kind { AMP, MEAN, FREQ };
static doublereal measure(enum measure_kind kind, int state, const doublereal *u,
                          const doublereal *par)
{
    switch (kind) {
    case AMP: return 0.5 * (getp("MAX", state + 1, u) - getp("MIN", state + 1, u));
    case MEAN: return getp("INT", state + 1, u);
    case FREQ:   /* DTM (a mesh interval) is 0 for equilibria and positive for orbits */
        return getp("DTM", 1, u) > 0.0 ? 1.0 / par[MLG_PAR_PERIOD - 1] : 0.0;
    }
    return 0.0;
}

int pvls(integer ndim, const doublereal *u, doublereal *par)
{
    stop_if_not_finite(ndim, u, par);
    int k = MLG_MEASURES_FIRST_PAR - 1;
#define X(name, kind, state, unit, doc) par[k++] = measure(kind, state, u, par);
    MLG_MEASURES(X)
#undef X
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
