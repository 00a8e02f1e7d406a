/* The continuation parameters as dual numbers, seeded for df/dp.
 * Derivative direction MLG_NX + k is PAR(k+1), in PAR units. */
#ifndef MLG_MODEL_PARAMETERS_H
#define MLG_MODEL_PARAMETERS_H

#include "dual.h"
#include "mlg_model.h"

typedef struct {
    const mlg_params *c;     /* every constant, plain */
    dual V, F_z, yfp, eps, c_psi, rho, mu, k_tlk;   /* SI: yfp and eps in metres */
} model_parameters;

static inline dual par_var(const mlg_params *p, int index)
{
    double par[MLG_PAR_SLOTS];
    mlg_params_get_par(p, par);
    return d_var(par[index], MLG_NX + index);
}

static inline model_parameters model_parameters_seed(const mlg_params *p)
{
    model_parameters mp;
    mp.c = p;
    mp.V = par_var(p, MLG_PAR_V);
    mp.F_z = d_mulc(par_var(p, MLG_PAR_Fstar), p->g_0 * p->m_0);     /* II.A */
    mp.yfp = d_mulc(par_var(p, MLG_PAR_yfp), 1e-3);
    mp.eps = d_mulc(d_add(par_var(p, MLG_PAR_eps_abs),
                          d_mul(par_var(p, MLG_PAR_eps_rel), par_var(p, MLG_PAR_yfp))), 1e-3);
    mp.c_psi = par_var(p, MLG_PAR_c_psi);
    mp.rho = par_var(p, MLG_PAR_rho);
    mp.mu = par_var(p, MLG_PAR_mu);
    mp.k_tlk = par_var(p, MLG_PAR_k_tlk);
    return mp;
}

#endif
