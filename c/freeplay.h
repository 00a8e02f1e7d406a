/* Torque-link freeplay (section III): r_tlk, eq. (14), eq. (15), eq. (16). */
#ifndef MLG_FREEPLAY_H
#define MLG_FREEPLAY_H

#include "model_parameters.h"

/* Distance from the torque-link apex to the strut axis (section III, Fig. 5).
 * atan2 replaces the printed atan((a-b)/z): z_tlk -> 0 at eta = z_tlk0. */
static inline dual torque_link_radius(const mlg_params *c, dual z_tlk)
{
    double ab = c->a_tlk - c->b_tlk;
    dual chord = d_sqrt(d_addc(d_sq(z_tlk), ab * ab));
    dual angle = d_sub(d_acos(d_mulc(chord, 0.5 / c->l_tlk)), d_atan2(d_const(ab), z_tlk));
    return d_addc(d_mulc(d_sin(angle), c->l_tlk), c->a_tlk);
}

/* Lateral torque-link force [N] at apex deflection y [m]: eq. (15) for
 * eps > 0, the non-smooth eq. (14) for eps == 0 (its limit; with zero
 * freeplay both are k_tlk y).  The vector field is only used with eps > 0
 * or zero freeplay (mlg_params_check); eq. (14) also serves the plots. */
static inline dual torque_link_force(dual k_tlk, dual y, dual yfp, dual eps)
{
    dual yp = d_add(y, yfp), ym = d_sub(y, yfp);
    if (eps.v == 0.0) {
        /* closed contact sets: with zero freeplay y = 0 takes the slope k_tlk */
        if (yp.v <= 0.0) return d_mul(k_tlk, yp);
        if (ym.v >= 0.0) return d_mul(k_tlk, ym);
        return d_const(0.0);
    }
    dual t1 = d_mul(yp, d_addc(d_atan(d_neg(d_div(yp, eps))), 0.5 * MLG_PI));
    dual t2 = d_mul(ym, d_addc(d_atan(d_div(ym, eps)), 0.5 * MLG_PI));
    return d_mulc(d_mul(k_tlk, d_add(t1, t2)), 1.0 / MLG_PI);
}

/* M_kpsi = r_tlk * force(y_tlk), y_tlk = r_tlk psi_s (eq. 15) */
static inline dual torsional_stiffness_moment(const model_parameters *mp, dual r_tlk, dual psi_s)
{
    dual y_tlk = d_mul(r_tlk, psi_s);
    return d_mul(r_tlk, torque_link_force(mp->k_tlk, y_tlk, mp->yfp, mp->eps));
}

/* M_cpsi = c_psi psi' (eq. 16) */
static inline dual torsional_damping_moment(const model_parameters *mp, dual psi_dot)
{
    return d_mul(mp->c_psi, psi_dot);
}

#endif
