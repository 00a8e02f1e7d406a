/* Structural properties of the strut (section II.A): the axle inertia I_a,
 * the inertias I_beta and I_delta, the lateral stiffness k_delta and the
 * damping c_delta, with the eta-slopes that eq. (4) and the complete
 * equations need (lengths: L_beta = L_beta0 - eta, dL/deta = -1). */
#ifndef MLG_STRUCTURE_H
#define MLG_STRUCTURE_H

#include "geometry.h"

typedef struct {
    dual I_a;
    dual I_beta, dI_beta_deta;      /* I_beta and dI_beta/deta */
    dual I_delta, dI_delta_deta;    /* I_delta (at the current theta_a) and dI_delta/deta */
    dual k_delta, dk_delta_deta, c_delta;
} structure;

static inline structure structure_at(const mlg_constants *c, const sidestay *g,
                                     const strut_lengths *l, dual eta, dual theta_a)
{
    structure s;
    s.I_a = d_const(c->I_a2 * c->a * c->a + c->I_a0 + 2.0 * c->I_0);
    dual cos2p = d_sq(g->cos_p);
    /* I_beta = (640 L_b^2 - 100 L_b + 260) cos^2 p */
    s.I_beta = d_mul(d_addc(d_add(d_mulc(d_sq(l->L_beta), c->I_beta2),
                                  d_mulc(l->L_beta, c->I_beta1)), c->I_beta0), cos2p);
    s.dI_beta_deta = d_neg(d_mul(d_addc(d_mulc(l->L_beta, 2.0 * c->I_beta2), c->I_beta1), cos2p));
    /* I_delta = 630 L_d^2 - 140 L_d + 60 + I_a cos^2 theta_a */
    s.I_delta = d_add(d_addc(d_add(d_mulc(d_sq(l->L_delta), c->I_delta2),
                                   d_mulc(l->L_delta, c->I_delta1)), c->I_delta0),
                      d_mul(s.I_a, d_sq(d_cos(theta_a))));
    s.dI_delta_deta = d_neg(d_addc(d_mulc(l->L_delta, 2.0 * c->I_delta2), c->I_delta1));
    /* k_delta = K L_d^2 / (3bc(b+c) + a(b^2+c^2) + (b^3 + R c^3) + 2abc), c = c0 - eta */
    {
        double a = c->a_kdelta, b = c->b_kdelta;
        dual cc = d_sub(d_const(c->c_kdelta0), eta);
        dual den = d_mulc(d_mul(cc, d_addc(cc, b)), 3.0 * b);
        den = d_add(den, d_mulc(d_addc(d_sq(cc), b * b), a));
        den = d_add(den, d_addc(d_mulc(d_mul(cc, d_sq(cc)), c->R_kdelta), b * b * b));
        den = d_add(den, d_mulc(cc, 2.0 * a * b));
        s.k_delta = d_div(d_mulc(d_sq(l->L_delta), c->K_kdelta), den);
        /* dk_delta/deta, with dL_d/deta = dc/deta = -1 (complete equations, docs/model.md 8) */
        dual dden = d_addc(d_mulc(cc, 6.0 * b + 2.0 * a), 3.0 * b * b + 2.0 * a * b);
        dden = d_add(dden, d_mulc(d_sq(cc), 3.0 * c->R_kdelta));
        dual num = d_sub(d_mul(d_sq(l->L_delta), dden), d_mulc(d_mul(l->L_delta, den), 2.0));
        s.dk_delta_deta = d_div(d_mulc(num, c->K_kdelta), d_sq(den));
    }
    /* c_delta: constant fraction of critical damping (docs/model.md 4.1) */
    s.c_delta = d_mulc(d_sqrt(d_mul(s.I_delta, s.k_delta)), c->zeta_delta);
    return s;
}

#endif
