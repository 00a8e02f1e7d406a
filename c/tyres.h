/* Tyres (section II.B): load split, deflection, effective radius, contact
 * patch and relaxation lengths, Magic-Formula force and moment (eqs. 7-8),
 * and each tyre's contact: slip dynamics (eqs. 5-6) and loads on the gear. */
#ifndef MLG_TYRES_H
#define MLG_TYRES_H

#include "geometry.h"
#include "gyroscopic.h"

/* Load split (II.B.1): F_L + F_R = F_dyn and d_R - d_L = 2 a u_a,Z with
 * d(F) = a_d (sqrt(F + b_d) - sqrt(b_d)).  With s_i = sqrt(F_i + b_d),
 * S = F_dyn + 2 b_d and D = 2 a u_a,Z / a_d the split is closed-form:
 * s_L = (-D + sqrt(2S - D^2))/2, s_R = (D + sqrt(2S - D^2))/2.
 * Returns MLG_WHEEL_LIFT_OFF if a load is not positive (or no split exists). */
static inline int tyre_load_split(const mlg_constants *c, dual F_dyn, dual u_aZ, dual F[2])
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
static inline dual tyre_law_load(const mlg_constants *c, dual F)
{
    return F.v < c->F_tyre_min ? d_const(c->F_tyre_min) : F;
}

static inline tyre_shape tyre_shape_at(const mlg_constants *c, dual F, int *status)
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
static inline dual tyre_lateral_force(const mlg_constants *c, dual F, dual alpha)
{
    F = tyre_law_load(c, F);
    dual D = d_addc(d_sqrt(d_addc(d_mulc(F, c->a3_F), c->a2_F)), c->a1_F);
    dual E = d_addc(d_add(d_mulc(d_sq(F), c->a6_F), d_mulc(F, c->a7_F)), c->E0_F);
    dual B = d_div(d_mulc(d_sin(d_mulc(d_atan(d_mulc(F, 1.0 / c->a5_F)), 1.8)), c->a4_F),
                   d_mulc(D, c->C_F));
    return magic_formula(alpha, B, c->C_F, D, E);
}

/* Self-aligning moment magnitude about e_Z, eq. (8) */
static inline dual tyre_aligning_moment(const mlg_constants *c, dual F, dual alpha)
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

/* Rates of the gear that the contact points move with (after eq. 6). */
typedef struct {
    dual psi_dot, delta_dot, beta_dot, eta_dot;
    dual beta_twist;      /* the axle's twist rate carried by beta (0 as printed) */
    dvec Omega;           /* axle angular velocity, eq. (9) */
} gear_rates;

/* One tyre in contact: its slip rate and what it puts on the gear. */
typedef struct {
    dual lambda_dot;      /* eqs. (5), (6) */
    dvec P_C;             /* contact point */
    dvec force;           /* F_i e_Z + F_klambda,i u_lambda, acting at P_C */
    dvec free_moment;     /* -M_kalpha,i e_Z - M_gyr,i */
    tyre_shape shape;
    dual alpha, F_y, M_z;
} tyre_contact;

/* Tyre i (0 = L, 1 = R) with load F and lateral deflection lambda. */
static inline tyre_contact tyre_contact_at(const model_parameters *mp, const sidestay *g,
                                           const pose *q, const gear_rates *w, int i, dual F,
                                           dual lambda, int *status)
{
    const mlg_constants *c = mp->c;
    tyre_contact t;
    t.shape = tyre_shape_at(c, F, status);
    t.P_C = v_add(q->P_wheel[i], v_scale(q->u_r, d_addc(d_neg(t.shape.d), c->r)));
    dvec P_CF = v_add(t.P_C, v_scale(q->u_f, d_mulc(t.shape.h, 0.5)));
    /* contact-point velocities V*_iCF and V_iCF (after eq. 6); V* leaves out
     * the yaw psi' of the torsional DoF, not the twist that beta carries */
    dvec twist_arm = v_cross(q->u_psi, v_sub(P_CF, q->P_0));
    dvec V_star = v_add(v_scale(v_cross(q->u_delta, P_CF), w->delta_dot),
                        v_scale(v_cross(g->u_beta, v_sub(P_CF, q->P_beta)), w->beta_dot));
    V_star = v_add(V_star, v_scale(q->u_eta, w->eta_dot));
    V_star.c[0] = d_add(V_star.c[0], mp->V);
    V_star = v_add(V_star, v_scale(twist_arm, w->beta_twist));
    dvec V_CF = v_add(V_star, v_scale(twist_arm, w->psi_dot));
    dual rolling = v_dot(V_CF, q->u_f);
    /* eqs. (5), (6) */
    t.lambda_dot = d_neg(d_add(d_div(d_mul(rolling, lambda), t.shape.L),
                               v_dot(V_star, q->u_lambda)));
    t.alpha = d_atan(d_div(lambda, t.shape.L));
    t.F_y = tyre_lateral_force(c, F, t.alpha);
    t.M_z = tyre_aligning_moment(c, F, t.alpha);
    dvec e_Z = v_const(0.0, 0.0, 1.0);
    t.force = v_add(v_scale(e_Z, F), v_scale(q->u_lambda, t.F_y));
    dvec M_gyr = gyroscopic_moment(w->Omega, c->I, rolling, t.shape.r_eff, q->u_a);
    t.free_moment = v_neg(v_add(v_scale(e_Z, t.M_z), M_gyr));
    return t;
}

#endif
