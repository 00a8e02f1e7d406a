/* Body shared by the two Jacobian translation units: defines the function
 * JACOBIAN_FUNCTION over the model of vector_field.h with DUAL_N directions
 * (the states first, then as many continuation parameters as fit). */
#ifndef JACOBIAN_FUNCTION
#error "define JACOBIAN_FUNCTION and DUAL_N before including jacobian_export.h"
#endif
#include "vector_field.h"

int JACOBIAN_FUNCTION(const mlg_params *p, const double u[MLG_NX], double f[MLG_NX],
                      double dfdu[MLG_NX * MLG_NX], double dfdp[MLG_NX * MLG_NPAR]);

int JACOBIAN_FUNCTION(const mlg_params *p, const double u[MLG_NX], double f[MLG_NX],
                      double dfdu[MLG_NX * MLG_NX], double dfdp[MLG_NX * MLG_NPAR])
{
    dual x[MLG_NX], fx[MLG_NX];
    for (int i = 0; i < MLG_NX; i++) x[i] = d_var(u[i], i);
    int status = vector_field(p, x, fx, NULL);
    for (int i = 0; i < MLG_NX; i++) {
        f[i] = fx[i].v;
        for (int j = 0; j < MLG_NX; j++) dfdu[i + MLG_NX * j] = d_slope(fx[i], j);
        if (dfdp != NULL)
            for (int k = 0; k < MLG_NPAR && MLG_DIR_PAR0 + k < DUAL_N; k++)
                dfdp[i + MLG_NX * k] = d_slope(fx[i], MLG_DIR_PAR0 + k);
    }
    return status;
}
