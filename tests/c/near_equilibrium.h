/* A random state near straight rolling, shared by the C tests: the
 * equilibrium of p with small angles, rates and tyre deflections added. */
#ifndef MLG_NEAR_EQUILIBRIUM_H
#define MLG_NEAR_EQUILIBRIUM_H

#include "mlg_model.h"
#include "unit.h"

static inline void near_equilibrium(const mlg_params *p, double u[MLG_NX])
{
    mlg_equilibrium(p, -1.0, u);
    u[MLG_PSI] += unit_between(-0.01, 0.01);
    u[MLG_DELTA] += unit_between(-0.01, 0.01);
    u[MLG_BETA] += unit_between(-0.003, 0.003);
    u[MLG_ETA] += unit_between(-0.01, 0.01);
    u[MLG_PSI_DOT] = unit_between(-1.0, 1.0);
    u[MLG_DELTA_DOT] = unit_between(-0.5, 0.5);
    u[MLG_BETA_DOT] = unit_between(-0.2, 0.2);
    u[MLG_ETA_DOT] = unit_between(-0.1, 0.1);
    u[MLG_LAMBDA_L] = unit_between(-0.02, 0.02);
    u[MLG_LAMBDA_R] = unit_between(-0.02, 0.02);
}

#endif
