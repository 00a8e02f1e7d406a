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

/* Every continuation parameter, seeded, in PAR units: generated from
 * MLG_CONTINUATION_PARAMETERS, so a new one is read as mp->par.<name>. */
typedef struct {
#define X(name, value, unit, doc) dual name;
    MLG_CONTINUATION_PARAMETERS(X)
#undef X
} par_duals;

typedef struct {
    const mlg_constants *c;  /* every constant and switch, plain */
    par_duals par;
    /* the paper's quantities in SI units, derived from par: yfp and eps in metres */
    dual V, F_z, yfp, eps, c_psi, rho, mu, k_tlk;
} model_parameters;

static inline model_parameters model_parameters_seed(const mlg_params *p, int dir_par1)
{
    model_parameters mp;
    mp.c = &p->constants;
#define X(name, value, unit, doc) mp.par.name = d_var(p->name, dir_par1 + MLG_PAR_##name);
    MLG_CONTINUATION_PARAMETERS(X)
#undef X
    mp.V = mp.par.V;
    mp.F_z = d_mulc(mp.par.Fstar, p->g_0 * p->m_0);     /* II.A */
    mp.yfp = d_mulc(mp.par.yfp, 1e-3);
    mp.eps = d_mulc(d_add(mp.par.eps_abs, d_mul(mp.par.eps_rel, mp.par.yfp)), 1e-3);
    mp.c_psi = mp.par.c_psi;
    mp.rho = mp.par.rho;
    mp.mu = mp.par.mu;
    mp.k_tlk = mp.par.k_tlk;
    return mp;
}

#endif
