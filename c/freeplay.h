/* Torque-link freeplay (section III): r_tlk, eq. (14), eq. (15), eq. (16). */
#ifndef MLG_FREEPLAY_H
#define MLG_FREEPLAY_H

#include "model_parameters.h"

/* Distance from the torque-link apex to the strut axis (section III, Fig. 5).
 * atan2 replaces the printed atan((a-b)/z): z_tlk -> 0 at eta = z_tlk0. */
static inline dual torque_link_radius(const mlg_constants *c, dual z_tlk)
{
    double ab = c->a_tlk - c->b_tlk;
    dual chord = d_sqrt(d_addc(d_sq(z_tlk), ab * ab));
    dual angle = d_sub(d_acos(d_mulc(chord, 0.5 / c->l_tlk)), d_atan2(d_const(ab), z_tlk));
    return d_addc(d_mulc(d_sin(angle), c->l_tlk), c->a_tlk);
}

/* d r_tlk / d z_tlk, from the formula above (d z_tlk / d eta = -1); the
 * complete equations need d r_tlk / d eta (docs/model.md, section 8). */
static inline dual torque_link_radius_slope(const mlg_constants *c, dual z_tlk)
{
    double ab = c->a_tlk - c->b_tlk;
    dual chord2 = d_addc(d_sq(z_tlk), ab * ab);
    dual chord = d_sqrt(chord2);
    dual x = d_mulc(chord, 0.5 / c->l_tlk);
    dual angle = d_sub(d_acos(x), d_atan2(d_const(ab), z_tlk));
    /* d acos(chord / 2l)/dz = -(z / chord) / (2l sqrt(1 - x^2));  d atan2(ab, z)/dz = -ab / chord^2 */
    dual dacos = d_neg(d_div(d_mulc(d_div(z_tlk, chord), 0.5 / c->l_tlk),
                             d_sqrt(d_sub(d_const(1.0), d_sq(x)))));
    dual dangle = d_add(dacos, d_div(d_const(ab), chord2));
    return d_mul(d_mulc(d_cos(angle), c->l_tlk), dangle);
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

/* Antiderivatives of the two terms of eq. (15), with x = y +- y_fp:
 * x (pi/2 - atan(x/eps)) -> pi x^2/4 - atan_part(x),  x (pi/2 + atan(x/eps)) -> pi x^2/4 + atan_part(x) */
static inline dual atan_part(dual x, dual eps)
{
    return d_mulc(d_sub(d_mul(d_add(d_sq(x), d_sq(eps)), d_atan(d_div(x, eps))), d_mul(eps, x)), 0.5);
}

static inline dual square_part(dual x)
{
    return d_mulc(d_sq(x), 0.25 * MLG_PI);
}

/* Potential of the torque links [J] at apex deflection y [m]: the integral of
 * torque_link_force from 0 to y, in closed form (eq. 15; eq. 14 for eps == 0). */
static inline dual torque_link_energy(dual k_tlk, dual y, dual yfp, dual eps)
{
    if (eps.v == 0.0) {
        dual out = d_sub(d_abs(y), yfp);
        return out.v > 0.0 ? d_mulc(d_mul(k_tlk, d_sq(out)), 0.5) : d_const(0.0);
    }
    dual yp = d_add(y, yfp), ym = d_sub(y, yfp), yfp_neg = d_neg(yfp);
    dual lower = d_sub(d_sub(square_part(yp), atan_part(yp, eps)),
                       d_sub(square_part(yfp), atan_part(yfp, eps)));
    dual upper = d_sub(d_add(square_part(ym), atan_part(ym, eps)),
                       d_add(square_part(yfp_neg), atan_part(yfp_neg, eps)));
    return d_mulc(d_mul(k_tlk, d_add(lower, upper)), 1.0 / MLG_PI);
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
