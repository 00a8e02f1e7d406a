/* Tyres (section II.B): load split, deflection, effective radius, contact
 * patch and relaxation lengths, Magic-Formula force and moment (eqs. 7-8). */
#ifndef MLG_TYRES_H
#define MLG_TYRES_H

#include "model_parameters.h"

/* Load split (II.B.1): F_L + F_R = F_dyn and d_R - d_L = 2 a u_a,Z with
 * d(F) = a_d (sqrt(F + b_d) - sqrt(b_d)).  With s_i = sqrt(F_i + b_d),
 * S = F_dyn + 2 b_d and D = 2 a u_a,Z / a_d the split is closed-form:
 * s_L = (-D + sqrt(2S - D^2))/2, s_R = (D + sqrt(2S - D^2))/2.
 * Returns MLG_WHEEL_LIFT_OFF if a load is not positive (or no split exists). */
static inline int tyre_load_split(const mlg_params *c, dual F_dyn, dual u_aZ, dual F[2])
{
    dual S = d_addc(F_dyn, 2.0 * c->b_d);
    dual D = d_mulc(u_aZ, 2.0 * c->a / c->a_d);
    dual disc = d_sub(d_mulc(S, 2.0), d_sq(D));
    if (!(disc.v > 0.0)) {
        F[0] = F[1] = d_const(0.0);
        return MLG_WHEEL_LIFT_OFF;
    }
    dual root = d_sqrt(disc);
    dual s_L = d_mulc(d_sub(root, D), 0.5), s_R = d_mulc(d_add(root, D), 0.5);
    F[0] = d_addc(d_sq(s_L), -c->b_d);
    F[1] = d_addc(d_sq(s_R), -c->b_d);
    return (F[0].v <= 0.0 || F[1].v <= 0.0) ? MLG_WHEEL_LIFT_OFF : MLG_OK;
}

typedef struct {
    dual d;        /* deflection (II.B.1) */
    dual r_eff;    /* effective radius (II.B.2) */
    dual h;        /* contact patch length (II.B.3) */
    dual L;        /* relaxation length (II.B.4) */
} tyre_shape;

/* The load the tyre laws (Magic-Formula coefficients, relaxation length) are
 * evaluated at: F, held at F_tyre_min below it.  F_tyre_min = 0 (default) is
 * the paper's laws, which all vanish as F -> 0; a positive value is the
 * low-load assumption of the allowable-freeplay criterion (docs/model.md 4.23). */
static inline dual tyre_law_load(const mlg_params *c, dual F)
{
    return F.v < c->F_tyre_min ? d_const(c->F_tyre_min) : F;
}

static inline tyre_shape tyre_shape_at(const mlg_params *c, dual F, int *status)
{
    tyre_shape t;
    t.d = d_mulc(d_addc(d_sqrt(d_addc(F, c->b_d)), -sqrt(c->b_d)), c->a_d);
    t.r_eff = d_addc(d_mulc(t.d, -c->k_reff), c->r);
    dual x = d_mulc(t.d, 0.5 / c->r);                       /* d / (2 r) */
    dual chord_sq = d_sub(x, d_sq(x));
    if (!(chord_sq.v > 0.0)) {
        *status |= (t.d.v <= 0.0) ? MLG_WHEEL_LIFT_OFF : MLG_TYRE_BOTTOMED;
        chord_sq = d_const(0.0);
        t.h = d_const(0.0);
    } else {
        t.h = d_mulc(d_sqrt(chord_sq), c->k_patch * 4.0 * c->r);
    }
    t.L = d_mulc(t.h, c->k_relax);
    if (F.v < c->F_tyre_min) {
        int held = MLG_OK;
        t.L = tyre_shape_at(c, d_const(c->F_tyre_min), &held).L;
    }
    return t;
}

/* Magic Formula D sin(C atan(B a - E (B a - atan(B a)))) (eqs. 7, 8) */
static inline dual magic_formula(dual alpha, dual B, double C, dual D, dual E)
{
    dual Ba = d_mul(B, alpha);
    dual inner = d_sub(Ba, d_mul(E, d_sub(Ba, d_atan(Ba))));
    return d_mul(D, d_sin(d_mulc(d_atan(inner), C)));
}

/* Lateral force magnitude along u_lambda, eq. (7), load-dependent coefficients */
static inline dual tyre_lateral_force(const mlg_params *c, dual F, dual alpha)
{
    F = tyre_law_load(c, F);
    dual D = d_addc(d_sqrt(d_addc(d_mulc(F, c->a3_F), c->a2_F)), c->a1_F);
    dual E = d_addc(d_add(d_mulc(d_sq(F), c->a6_F), d_mulc(F, c->a7_F)), c->E0_F);
    dual B = d_div(d_mulc(d_sin(d_mulc(d_atan(d_mulc(F, 1.0 / c->a5_F)), 1.8)), c->a4_F),
                   d_mulc(D, c->C_F));
    return magic_formula(alpha, B, c->C_F, D, E);
}

/* Self-aligning moment magnitude about e_Z, eq. (8) */
static inline dual tyre_aligning_moment(const mlg_params *c, dual F, dual alpha)
{
    F = tyre_law_load(c, F);
    dual F2 = d_sq(F);
    dual D = d_add(d_mulc(F2, c->a1_M), d_mulc(F, c->a2_M));
    dual E = d_addc(d_add(d_mulc(F2, c->a5_M), d_mulc(F, c->a6_M)),
                    c->E0_M + c->a6_M * c->a6_M / (4.0 * c->a5_M));
    dual B = d_div(d_add(d_mulc(F2, c->a3_M), d_mulc(F, c->a4_M)),
                   d_mul(d_mulc(D, c->C_M), d_exp(d_mulc(F, c->k_M_exp))));
    return magic_formula(alpha, B, c->C_M, D, E);
}

#endif
