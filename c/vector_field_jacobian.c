/* f, df/du and df/dp: the model of vector_field.h with DUAL_N = MLG_NDIR
 * forward-mode directions (the 10 states, then PAR(1..MLG_NPAR)). */
#include "mlg_model.h"
#define DUAL_N 24    /* a literal for #if: the states' 3 blocks, then PAR(1..12) */
#define JACOBIAN_FUNCTION mlg_rhs_jacobian_full
#include "jacobian_export.h"
_Static_assert(MLG_DIR_PAR0 + MLG_NPAR <= DUAL_N, "a derivative direction for every PAR");
