/* f, df/du and df/dp: the model of vector_field.h with ten derivative
 * directions, evaluated once seeded on the states and, for df/dp, once more
 * seeded on PAR(1..MLG_NPAR).  Two passes of ten directions cost less than
 * one of twenty: each pass's duals stay small enough to live in registers,
 * and each direction's derivative is computed by the same operations, so the
 * columns are those of a single wide pass to the bit. */
#include "jacobian_variants.h"
#define DUAL_N 10    /* a literal for #if: MLG_NX */
#include "vector_field.h"

/* c/c.mk builds this file once per variant under the variant's name */
#ifndef MLG_JACOBIAN_VARIANT
#define MLG_JACOBIAN_VARIANT mlg_rhs_jacobian_generic
#endif

_Static_assert(DUAL_N == MLG_NX, "one derivative direction per state");
_Static_assert(MLG_NPAR <= DUAL_N, "a derivative direction for every PAR in the second pass");

int MLG_JACOBIAN_VARIANT(const mlg_params *p, const int *modes, const double u[MLG_NX],
                         double f[MLG_NX], double dfdu[MLG_NX * MLG_NX],
                         double dfdp[MLG_NX * MLG_NPAR])
{
    dual x[MLG_NX], fx[MLG_NX];
    for (int i = 0; i < MLG_NX; i++) x[i] = d_var(u[i], i);
    int status = vector_field(p, x, modes, MLG_PARS_PLAIN, fx, NULL);
    for (int i = 0; i < MLG_NX; i++) {
        f[i] = fx[i].v;
        for (int j = 0; j < MLG_NX; j++) dfdu[i + MLG_NX * j] = d_slope(fx[i], j);
    }
    if (dfdp == NULL) return status;
    for (int i = 0; i < MLG_NX; i++) x[i] = d_const(u[i]);
    status |= vector_field(p, x, modes, 0, fx, NULL);   /* df/dp can overflow alone */
    for (int i = 0; i < MLG_NX; i++) {
        if (status != MLG_OK) f[i] = 0.0;
        for (int k = 0; k < MLG_NPAR; k++) dfdp[i + MLG_NX * k] = d_slope(fx[i], k);
    }
    return status;
}
