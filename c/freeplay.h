/* Torque links (section III): r_tlk, the moments of eqs. (14)-(16); the
 * freeplay laws are in freeplay_laws.h. */
#ifndef MLG_FREEPLAY_H
#define MLG_FREEPLAY_H

#include "freeplay_laws.h"
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

/* M_kpsi = r_tlk * force(y_tlk), y_tlk = r_tlk psi_s (eq. 15, or the law
 * freeplay_law selects; mode: enum mlg_freeplay_mode) */
static inline dual torsional_stiffness_moment(const model_parameters *mp, dual r_tlk, dual psi_s,
                                              int mode)
{
    dual y_tlk = d_mul(r_tlk, psi_s);
    return d_mul(r_tlk, torque_link_force((int)mp->c->freeplay_law, mode, mp->k_tlk, y_tlk,
                                          mp->yfp, mp->eps));
}

/* M_cpsi = c_psi psi' (eq. 16) */
static inline dual torsional_damping_moment(const model_parameters *mp, dual psi_dot)
{
    return d_mul(mp->c_psi, psi_dot);
}

#endif
