/* The equations of motion: the dynamic load of eq. (4), the generalised
 * moments of eqs. (10)-(12) and the accelerations of eqs. (1)-(4), with the
 * switch eom_terms (enum mlg_eom_terms; docs/model.md 8). */
#ifndef MLG_EQUATIONS_OF_MOTION_H
#define MLG_EQUATIONS_OF_MOTION_H

#include "freeplay.h"
#include "structure.h"
#include "strut.h"
#include "tyres.h"

/* Everything the equations read besides the loads: parameters, geometry,
 * structure, rates and the torque-link moments. */
typedef struct {
    const model_parameters *mp;
    const sidestay *g;
    const strut_lengths *l;
    const structure *s;
    const pose *q;
    const gear_rates *w;
    int eom;                      /* enum mlg_eom_terms */
    dual delta, beta, eta, psi_s, theta_a, theta_a_dot;
    dual r_tlk, M_kpsi, M_cpsi;   /* eqs. (15), (16) */
} gear_state;

/* eq. (4) solved for the dynamic load: F_dyn = M H'' + F_z (docs/model.md 4.6) */
static inline dual dynamic_load(const gear_state *x, dual F_keta, dual F_ceta)
{
    const structure *s = x->s;
    dual axial = d_add(F_keta, F_ceta);
    axial = d_sub(axial, d_mulc(d_mul(s->dI_beta_deta, d_sq(x->w->beta_dot)), 0.5));
    axial = d_sub(axial, d_mulc(d_mul(s->dI_delta_deta, d_sq(x->w->delta_dot)), 0.5));
    if (x->eom == MLG_EOM_COMPLETE) {
        /* d/deta of the potentials 1/2 k_delta(eta) delta^2 and of the torque links,
         * whose apex deflection r_tlk(eta) psi_s gives M_kpsi psi_s (dr_tlk/deta) / r_tlk */
        axial = d_add(axial, d_mulc(d_mul(s->dk_delta_deta, d_sq(x->delta)), 0.5));
        dual dr_deta = d_neg(torque_link_radius_slope(x->mp->c, x->l->z_tlk));
        axial = d_add(axial, d_mul(x->M_kpsi, d_mul(x->psi_s, d_div(dr_deta, x->r_tlk))));
    }
    return d_div(axial, x->q->cos_phi);
}

/* Forces of both tyres, reduced to sums so that the moment about any point
 * Q is  sum_PxF - Q x sum_F + sum_G. */
typedef struct {
    dvec sum_F;      /* sum of F_i e_Z + F_klambda,i */
    dvec sum_PxF;    /* sum of P_iC x (F_i e_Z + F_klambda,i) */
    dvec sum_G;      /* sum of the free moments -M_kalpha,i - M_gyr,i */
} tyre_loads;

static inline void add_tyre_load(tyre_loads *t, const tyre_contact *contact)
{
    t->sum_F = v_add(t->sum_F, contact->force);
    t->sum_PxF = v_add(t->sum_PxF, v_cross(contact->P_C, contact->force));
    t->sum_G = v_add(t->sum_G, contact->free_moment);
}

static inline dual moment_about(const tyre_loads *t, dvec Q, dvec axis)
{
    dvec m = v_add(v_sub(t->sum_PxF, v_cross(Q, t->sum_F)), t->sum_G);
    return v_dot(m, axis);
}

/* Generalised moments M_psi, M_delta, M_beta: eqs. (10)-(12); P_delta is the
 * origin.  Eq. (12) turns beta with psi held, i.e. twists the axle by sin p
 * per unit beta; as printed it uses -u_beta . u_psi for sin p, exact only at
 * delta = 0. */
static inline void generalised_moments(const gear_state *x, const tyre_loads *t, dual M[3])
{
    const pose *q = x->q;
    M[0] = moment_about(t, q->P_0, q->u_psi);
    M[1] = moment_about(t, v_const(0, 0, 0), q->u_delta);
    dual twist_per_beta = x->eom == MLG_EOM_COMPLETE ? x->g->sin_p
                                                     : d_neg(v_dot(x->g->u_beta, q->u_psi));
    M[2] = d_add(moment_about(t, q->P_beta, x->g->u_beta), d_mul(M[0], twist_per_beta));
}

/* I_a (d' sin ta + b' cos ta cos p)(d' cos ta - b' sin ta cos p): eqs. (1), (3) */
static inline dual axle_coupling(dual I_a, dual delta_dot, dual beta_dot, dual s_ta, dual c_ta,
                                 dual cos_p)
{
    dual bc = d_mul(beta_dot, cos_p);
    return d_mul(I_a, d_mul(d_add(d_mul(delta_dot, s_ta), d_mul(bc, c_ta)),
                            d_sub(d_mul(delta_dot, c_ta), d_mul(bc, s_ta))));
}

/* psi'', delta'', beta'', eta'' from eqs. (1)-(4), given the moments M and
 * the dynamic load F_dyn. */
static inline void accelerations(const gear_state *x, const dual M[3], dual F_dyn,
                                 dual acc[4])
{
    const mlg_constants *c = x->mp->c;
    const structure *s = x->s;
    const sidestay *g = x->g;
    const pose *q = x->q;
    const dual delta_dot = x->w->delta_dot, beta_dot = x->w->beta_dot;
    const dual eta_dot = x->w->eta_dot, theta_a_dot = x->theta_a_dot;
    dual MH_ddot = d_sub(F_dyn, x->mp->F_z);
    dual s_ta = d_sin(x->theta_a), c_ta = d_cos(x->theta_a);
    dual cos_2ta = d_addc(d_mulc(d_sq(c_ta), 2.0), -1.0);            /* 2 cos^2 ta - 1 */
    dual sc2 = d_mulc(d_mul(s_ta, c_ta), 2.0);                        /* 2 sin ta cos ta */
    dual coupling = axle_coupling(s->I_a, delta_dot, beta_dot, s_ta, c_ta, g->cos_p);

    /* eq. (1) */
    dual rhs_psi = d_sub(d_sub(d_sub(M[0], coupling), x->M_cpsi), x->M_kpsi);
    acc[0] = d_mulc(rhs_psi, 1.0 / c->I_psi);

    /* eq. (2) */
    dual gyro_delta = d_mul(s->I_a, d_mul(d_add(d_mul(d_mul(beta_dot, cos_2ta), g->cos_p),
                                                 d_mul(delta_dot, sc2)), theta_a_dot));
    dual rhs_delta = d_add(M[1], gyro_delta);
    rhs_delta = d_sub(rhs_delta, d_mul(s->dI_delta_deta, d_mul(eta_dot, delta_dot)));
    rhs_delta = d_sub(rhs_delta, d_add(d_mul(s->c_delta, delta_dot), d_mul(s->k_delta, x->delta)));

    /* eq. (3), with the printed "sin theta_s" read as sin theta_a; the theta_a'
     * bracket carries cos p in the derived equations (it is d/dt of -I_a W sin ta cos p) */
    dual bracket = d_sub(d_mul(delta_dot, cos_2ta), d_mul(d_mul(beta_dot, sc2), g->cos_p));
    if (x->eom >= MLG_EOM_SIDESTAY) bracket = d_mul(bracket, g->cos_p);
    dual gyro_beta = d_mul(s->I_a, d_mul(bracket, theta_a_dot));
    dual rhs_beta = d_add(d_sub(M[2], d_mul(coupling, g->sin_p)), gyro_beta);
    /* the vertical load's moment about the side-stay axis, arm dH/dbeta = L_beta cos'(phi):
     * as printed, eq. (3) adds M H'' there although F_dyn = M H'' + F_z already acts in
     * M_beta (counted twice, docs/model.md 4.16); an ideal support carries F_dyn on that arm */
    dual beta_load = x->eom == MLG_EOM_COMPLETE ? d_const(0.0) : MH_ddot;
    if (c->tyre_forces == 0.0) beta_load = d_add(beta_load, F_dyn);
    rhs_beta = d_sub(rhs_beta, d_mul(beta_load, d_mul(x->l->L_beta, q->dcos_phi)));
    rhs_beta = d_sub(rhs_beta, d_mul(s->dI_beta_deta, d_mul(eta_dot, beta_dot)));
    rhs_beta = d_sub(rhs_beta, d_add(d_mulc(beta_dot, c->c_beta), d_mul(x->M_cpsi, g->sin_p)));
    rhs_beta = d_sub(rhs_beta, d_add(d_mulc(x->beta, c->k_beta), d_mul(x->M_kpsi, g->sin_p)));

    if (x->eom == MLG_EOM_COMPLETE) {
        /* the axle's kinetic energy 1/2 I_a W^2, W = delta' cos ta - beta' sin ta cos p,
         * couples the accelerations: [I_delta, -k; -k, I_beta + I_a sin^2 ta cos^2 p] */
        dual k = d_mul(s->I_a, d_mul(d_mul(s_ta, c_ta), g->cos_p));
        dual m_bb = d_add(s->I_beta, d_mul(s->I_a, d_sq(d_mul(s_ta, g->cos_p))));
        dual det = d_sub(d_mul(s->I_delta, m_bb), d_sq(k));
        acc[1] = d_div(d_add(d_mul(m_bb, rhs_delta), d_mul(k, rhs_beta)), det);
        acc[2] = d_div(d_add(d_mul(s->I_delta, rhs_beta), d_mul(k, rhs_delta)), det);
    } else {
        acc[1] = d_div(rhs_delta, s->I_delta);
        acc[2] = d_div(rhs_beta, s->I_beta);
    }

    /* eq. (4): H'' = cos'(phi)(L_b b'' - 2 eta' b') + cos''(phi) L_b b'^2 - eta'' cos(phi)
     * (docs/model.md 4.5: the printed last term eta' is eta''), solved for eta'' */
    dual H_ddot = d_mulc(MH_ddot, 1.0 / c->M);
    dual eta_rhs = d_mul(q->dcos_phi, d_sub(d_mul(x->l->L_beta, acc[2]),
                                            d_mulc(d_mul(eta_dot, beta_dot), 2.0)));
    eta_rhs = d_add(eta_rhs, d_mul(d_mul(q->d2cos_phi, x->l->L_beta), d_sq(beta_dot)));
    acc[3] = d_div(d_sub(eta_rhs, H_ddot), q->cos_phi);
}

#endif
