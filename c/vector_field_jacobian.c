/* f, df/du and df/dp: the model of vector_field.h with a derivative
 * direction for each state, then each of PAR(1..MLG_NPAR). */
#include "mlg_model.h"
#define DUAL_N 20    /* a literal for #if: the states, then PAR(1..10) */
#define JACOBIAN_FUNCTION mlg_rhs_jacobian_full
#include "jacobian_export.h"
_Static_assert(MLG_DIR_PAR0 + MLG_NPAR <= DUAL_N, "a derivative direction for every PAR");
