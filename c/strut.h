/* Oleo strut: spring F_keta and damper F_ceta (section II.A). */
#ifndef MLG_STRUT_H
#define MLG_STRUT_H

#include "model_parameters.h"

/* F_keta.  The printed formula weights the stage (a e^{b eta} + c) by
 * [atan(+k (eta - eta_s)) + pi/2]/pi, i.e. switches it on ABOVE eta_s, and the
 * stage (d e^{e eta} + f) below.  strut_variant 0 swaps the two weights so the
 * oleo is a monotone two-stage spring (docs/model.md 4.15). */
static inline dual strut_spring_force(const mlg_constants *c, dual eta)
{
    dual stage_ac = d_addc(d_mulc(d_exp(d_mulc(eta, c->b_keta)), c->a_keta), c->c_keta);
    dual stage_df = d_addc(d_mulc(d_exp(d_mulc(eta, c->e_keta)), c->d_keta), c->f_keta);
    dual x = d_mulc(d_addc(eta, -c->eta_stage), c->k_stage);
    dual above = d_mulc(d_addc(d_atan(x), 0.5 * MLG_PI), 1.0 / MLG_PI);   /* -> 1 for eta > eta_s */
    dual below = d_mulc(d_addc(d_atan(d_neg(x)), 0.5 * MLG_PI), 1.0 / MLG_PI);
    dual force = c->strut_variant == 1.0
                     ? d_add(d_mul(stage_ac, above), d_mul(stage_df, below))
                     : d_add(d_mul(stage_ac, below), d_mul(stage_df, above));
    return d_sub(force, d_div(d_const(c->F_topout), eta));
}

/* F_ceta = sign(eta') (4e4/pi atan(1e4 (eta - 0.18)) + 7.5e4) eta'^2 + 1000 eta' */
static inline dual strut_damper_force(const mlg_constants *c, dual eta, dual eta_dot)
{
    dual coef = d_addc(d_mulc(d_atan(d_mulc(d_addc(eta, -c->eta_orifice), c->k_eta2)),
                              c->c_eta2a / MLG_PI), c->c_eta2b);
    dual signed_square = d_mul(eta_dot, d_abs(eta_dot));
    return d_add(d_mul(coef, signed_square), d_mulc(eta_dot, c->c_eta1));
}

/* Coulomb friction of the piston's seal in the strut, regularised for
 * continuation: size * tanh(slip / v_fric), slip the sliding speed at the
 * seal; a constant normal force (docs/model.md 10). */
static inline dual seal_friction(dual size, dual slip, const mlg_constants *c)
{
    return d_mul(size, d_tanh(d_mulc(slip, 1.0 / c->v_fric)));
}

/* the moment against the twist of piston in strut, acting as M_cpsi does */
static inline dual seal_friction_moment(const model_parameters *mp, dual twist_rate)
{
    return seal_friction(mp->par.M_fric, d_mulc(twist_rate, mp->c->r_seal), mp->c);
}

/* Coulomb's law (friction_law 1) in a mode of the twist: +-M_fric sliding,
 * 0 stuck until hold_twist (vector_field.h) finds the holding moment */
static inline dual coulomb_friction_moment(const model_parameters *mp, int mode)
{
    return mode == MLG_MODE_SLIP_POS ? mp->par.M_fric
         : mode == MLG_MODE_SLIP_NEG ? d_neg(mp->par.M_fric) : d_const(0.0);
}

/* the axial force against the compression rate, acting as F_ceta does */
static inline dual seal_friction_force(const model_parameters *mp, dual eta_dot)
{
    return seal_friction(d_const(mp->c->F_fric), eta_dot, mp->c);
}

#endif
