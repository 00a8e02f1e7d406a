/* The continuation parameters as dual numbers, seeded for df/dp, beside the
 * plain constants.  Derivative direction dir_par1 + k is PAR(k+1), in PAR
 * units; directions outside 0..DUAL_N-1 are not seeded.  The model reads
 * parameters only through this struct: a continuation parameter is a dual,
 * everything else is in mlg_constants. */
#ifndef MLG_MODEL_PARAMETERS_H
#define MLG_MODEL_PARAMETERS_H

#include "dual.h"
#include "mlg_model.h"

/* dir_par1 that seeds no parameter (df/du alone, or plain doubles) */
#define MLG_PARS_PLAIN (-(1 << 20))

typedef struct {
    const mlg_constants *c;  /* every constant and switch, plain */
    dual V, F_z, yfp, eps, c_psi, rho, mu, k_tlk;   /* SI: yfp and eps in metres */
} model_parameters;

/* PAR(k+1) as an independent variable, in PAR units */
#define PAR_VAR(p, name) d_var((p)->name, dir_par1 + MLG_PAR_##name)

static inline model_parameters model_parameters_seed(const mlg_params *p, int dir_par1)
{
    model_parameters mp;
    mp.c = &p->constants;
    mp.V = PAR_VAR(p, V);
    mp.F_z = d_mulc(PAR_VAR(p, Fstar), p->g_0 * p->m_0);     /* II.A */
    dual yfp = PAR_VAR(p, yfp);
    mp.yfp = d_mulc(yfp, 1e-3);
    mp.eps = d_mulc(d_add(PAR_VAR(p, eps_abs), d_mul(PAR_VAR(p, eps_rel), yfp)), 1e-3);
    mp.c_psi = PAR_VAR(p, c_psi);
    mp.rho = PAR_VAR(p, rho);
    mp.mu = PAR_VAR(p, mu);
    mp.k_tlk = PAR_VAR(p, k_tlk);
    return mp;
}

#endif
