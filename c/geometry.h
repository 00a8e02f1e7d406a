/* Gear geometry: side-stay angles, strut lengths, and the axes and points of
 * section II (Fig. 3).  Masses and stiffnesses are in structure.h. */
#ifndef MLG_GEOMETRY_H
#define MLG_GEOMETRY_H

#include "model_parameters.h"
#include "vec3.h"

/* Quantities fixed by the side-stay orientation (rho, mu) and rake phi0. */
typedef struct {
    dvec u_beta, u_psi0, u_delta0;
    dual m, sin_p, cos_p;
    dual H1, H2, H3;          /* cos(phi) = H1 cos(beta) + H2 sin(beta) + H3 */
    dmat R0;                  /* R(-e_Y, phi0) */
} sidestay;

static inline sidestay sidestay_geometry(const model_parameters *mp)
{
    const double phi0 = mp->c->phi0, c0 = cos(phi0), s0 = sin(phi0);
    dual cr = d_cos(mp->rho), sr = d_sin(mp->rho), cm = d_cos(mp->mu), sm = d_sin(mp->mu);
    sidestay g;
    g.u_beta = v_make(d_neg(d_mul(cr, sm)), d_neg(d_mul(cr, cm)), d_neg(sr));
    g.u_psi0 = v_const(-s0, 0.0, c0);
    /* m and p: docs/model.md 4.13; u_delta0 is then normal to u_beta and u_psi0 */
    g.sin_p = d_sub(d_mulc(sr, c0), d_mulc(d_mul(cr, sm), s0));
    g.cos_p = d_sqrt(d_sub(d_const(1.0), d_sq(g.sin_p)));
    g.m = d_atan2(d_add(d_mulc(d_mul(cr, sm), c0), d_mulc(sr, s0)), d_mul(cr, cm));
    dual cmm = d_cos(g.m);
    g.u_delta0 = v_make(d_mulc(cmm, c0), d_neg(d_sin(g.m)), d_mulc(cmm, s0));
    /* H1..H3 as printed after eq. (6) */
    g.H1 = d_add(d_mulc(d_sq(cr), c0), d_mulc(d_mul(d_mul(sr, cr), sm), s0));
    g.H2 = d_mulc(d_mul(cr, cm), -s0);
    g.H3 = d_sub(d_mulc(d_sq(sr), c0), d_mulc(d_mul(d_mul(sr, cr), sm), s0));
    dvec minus_e_Y = v_const(0.0, -1.0, 0.0);
    m_rotation(&g.R0, &minus_e_Y, d_const(phi0));
    return g;
}

/* psi_s = psi + beta sin p: the axle's twist about the strut (after eq. 6),
 * which deflects the torque-link apex by y_tlk = r_tlk psi_s */
static inline dual twist_angle(dual psi, dual beta, dual sin_p)
{
    return d_add(psi, d_mul(beta, sin_p));
}

/* Lengths that shorten with the compression eta (section II.A). */
typedef struct {
    dual L_beta, L_delta, z_tlk;
} strut_lengths;

static inline strut_lengths strut_lengths_at(const mlg_constants *c, dual eta)
{
    strut_lengths l;
    l.L_beta = d_sub(d_const(c->L_beta0), eta);
    l.L_delta = d_sub(d_const(c->L_delta0), eta);
    l.z_tlk = d_sub(d_const(c->z_tlk0), eta);
    return l;
}

/* Orientation and points of the gear for given (psi, delta, beta, eta). */
typedef struct {
    dvec u_psi, u_delta, u_eta, u_a, u_lambda, u_f, u_r;
    dvec P_0, P_beta, P_wheel[2];         /* P_delta is the origin; wheel [0]=L, [1]=R */
    dual cos_phi;                         /* H1 cos b + H2 sin b + H3 */
    dual dcos_phi;                        /* d cos(phi)/d beta = -H1 sin b + H2 cos b */
    dual d2cos_phi;                       /* d2 cos(phi)/d beta2 = -H1 cos b - H2 sin b */
} pose;

static inline dvec unit_horizontal(dual x, dual y)
{
    dual n = d_sqrt(d_add(d_sq(x), d_sq(y)));
    return v_make(d_div(x, n), d_div(y, n), d_const(0.0));
}

/* r = R R0 x: the point at offset x in the unraked, unturned gear */
static inline void placed_point(dvec *r, const dmat *R, const dmat *R0, dvec x)
{
    dvec raked;
    m_apply(&raked, R0, &x);
    m_apply(r, R, &raked);
}

/* fills *q (a pose returned by value is copied: 4 kB at ten directions) */
static inline void pose_at(pose *q, const model_parameters *mp, const sidestay *g,
                           const strut_lengths *s, dual psi, dual delta, dual beta)
{
    const mlg_constants *c = mp->c;
    dual psi_s = twist_angle(psi, beta, g->sin_p);
    dmat R_b, R_d, R_bd, R_p, R_bdp;
    m_rotation(&R_b, &g->u_beta, beta);
    m_rotation(&R_d, &g->u_delta0, delta);
    m_mul(&R_bd, &R_b, &R_d);
    m_rotation(&R_p, &g->u_psi0, psi_s);
    m_mul(&R_bdp, &R_bd, &R_p);
    const dvec e_Y = v_const(0.0, 1.0, 0.0);
    m_apply(&q->u_delta, &R_b, &g->u_delta0);
    m_apply(&q->u_psi, &R_bd, &g->u_psi0);
    m_apply(&q->u_eta, &R_b, &g->u_psi0);
    m_apply(&q->u_a, &R_bdp, &e_Y);
    q->u_lambda = unit_horizontal(q->u_a.c[0], q->u_a.c[1]);
    q->u_f = unit_horizontal(q->u_a.c[1], d_neg(q->u_a.c[0]));
    /* u_r = R(u_f, -pi/2) u_a = u_a x u_f, exactly, since u_f is normal to u_a */
    q->u_r = v_cross(q->u_a, q->u_f);
    placed_point(&q->P_0, &R_bd, &g->R0, v_make(d_const(0), d_const(0), d_neg(s->L_delta)));
    placed_point(&q->P_beta, &R_b, &g->R0,
                 v_make(d_const(0), d_const(0), d_sub(s->L_beta, s->L_delta)));
    for (int i = 0; i < 2; i++) {
        double side = i == 0 ? c->a : -c->a;
        placed_point(&q->P_wheel[i], &R_bdp, &g->R0,
                     v_make(d_const(-c->e), d_const(side), d_neg(s->L_delta)));
    }
    dual cb = d_cos(beta), sb = d_sin(beta);
    q->cos_phi = d_add(d_add(d_mul(g->H1, cb), d_mul(g->H2, sb)), g->H3);
    q->dcos_phi = d_add(d_neg(d_mul(g->H1, sb)), d_mul(g->H2, cb));
    q->d2cos_phi = d_neg(d_add(d_mul(g->H1, cb), d_mul(g->H2, sb)));
}

#endif
