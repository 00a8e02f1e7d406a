/* f and df/du only: the model of vector_field.h with DUAL_N = MLG_NX
 * directions, about half the cost of the full Jacobian. */
#include "mlg_model.h"
#define DUAL_N 10    /* a literal for #if: MLG_NX */
#define JACOBIAN_FUNCTION mlg_rhs_jacobian_states
#include "jacobian_export.h"
_Static_assert(DUAL_N == MLG_NX, "one derivative direction per state");

int mlg_rhs_jacobian_full(const mlg_params *p, const double u[MLG_NX], double f[MLG_NX],
                          double dfdu[MLG_NX * MLG_NX], double dfdp[MLG_NX * MLG_NPAR]);

int mlg_rhs_jacobian(const mlg_params *p, const double u[MLG_NX], double f[MLG_NX],
                     double dfdu[MLG_NX * MLG_NX], double dfdp[MLG_NX * MLG_NPAR])
{
    return dfdp != NULL ? mlg_rhs_jacobian_full(p, u, f, dfdu, dfdp)
                        : mlg_rhs_jacobian_states(p, u, f, dfdu, NULL);
}
