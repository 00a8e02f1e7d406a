/* The torque-link freeplay laws: the lateral force [N] at apex deflection y
 * [m] for freeplay half-width y_fp and smoothing width eps [m], each one
 * function on the dual type, so that its exact derivative comes with it.
 *
 * MLG_FREEPLAY_LAWS is the one table: X(name, uses_eps, description).  A law
 * is selected by the switch freeplay_law, its index here (0, atan, is the
 * paper's model; append new laws at the end so that stored indices keep
 * their meaning).  Each smoothed law tends to the non-smooth law (14) as
 * eps -> 0 and is evaluated as (14) at eps == 0 (torque_link_force); with
 * uses_eps = 0 the law ignores eps.  Every law is odd in y and, written as
 * the sum of its two contact terms, is k_tlk y at zero freeplay, except
 * hertz, whose contact stiffness starts at zero (docs/model.md 9). */
#ifndef MLG_FREEPLAY_LAWS_H
#define MLG_FREEPLAY_LAWS_H

#include "dual.h"
#include "mlg_model.h"

#define MLG_FREEPLAY_LAWS(X)                                                          \
    X(atan,      1, "eq. (15): arctangent smoothing of eq. (14) over eps")           \
    X(nonsmooth, 0, "eq. (14): no force inside |y| < y_fp, k_tlk (|y| - y_fp) beyond") \
    X(tanh,      1, "each contact term of eq. (14) switched on by (1 + tanh(x/eps))/2") \
    X(cubic,     1, "stiffness rising from 0 to k_tlk along the cubic smoothstep over " \
                    "|y| - y_fp in [-eps, eps]: exactly eq. (14) outside that band")  \
    X(hertz,     1, "Hertz-like contact: stiffness k_tlk (x/eps)^(1/2) for a contact "   \
                    "depth 0 < x = |y| - y_fp < eps, k_tlk beyond")

enum mlg_freeplay_law {
#define X(name, uses_eps, doc) MLG_FREEPLAY_##name,
    MLG_FREEPLAY_LAWS(X)
#undef X
    MLG_FREEPLAY_NLAWS
};

/* Eq. (14) in one mode (enum mlg_freeplay_mode), or in the mode of the
 * state: closed contact sets, so that with zero freeplay y = 0 takes the
 * slope k_tlk. */
static inline dual nonsmooth_in_mode(dual k_tlk, dual y, dual yfp, int mode)
{
    dual yp = d_add(y, yfp), ym = d_sub(y, yfp);
    if (mode == MLG_MODE_BY_STATE)
        mode = yp.v <= 0.0 ? MLG_MODE_CONTACT_NEG : ym.v >= 0.0 ? MLG_MODE_CONTACT_POS
                                                                : MLG_MODE_GAP;
    if (mode == MLG_MODE_CONTACT_NEG) return d_mul(k_tlk, yp);
    if (mode == MLG_MODE_CONTACT_POS) return d_mul(k_tlk, ym);
    return d_const(0.0);
}

static inline dual freeplay_nonsmooth(dual k_tlk, dual y, dual yfp, dual eps)
{
    (void)eps;
    return nonsmooth_in_mode(k_tlk, y, yfp, MLG_MODE_BY_STATE);
}

/* Eq. (15) */
static inline dual freeplay_atan(dual k_tlk, dual y, dual yfp, dual eps)
{
    dual yp = d_add(y, yfp), ym = d_sub(y, yfp);
    dual t1 = d_mul(yp, d_addc(d_atan(d_neg(d_div(yp, eps))), 0.5 * MLG_PI));
    dual t2 = d_mul(ym, d_addc(d_atan(d_div(ym, eps)), 0.5 * MLG_PI));
    return d_mulc(d_mul(k_tlk, d_add(t1, t2)), 1.0 / MLG_PI);
}

/* k/2 [(y - y_fp)(1 + tanh((y - y_fp)/eps)) + (y + y_fp)(1 - tanh((y + y_fp)/eps))] */
static inline dual freeplay_tanh(dual k_tlk, dual y, dual yfp, dual eps)
{
    dual yp = d_add(y, yfp), ym = d_sub(y, yfp);
    dual t1 = d_mul(ym, d_addc(d_tanh(d_div(ym, eps)), 1.0));
    dual t2 = d_mul(yp, d_addc(d_neg(d_tanh(d_div(yp, eps))), 1.0));
    return d_mulc(d_mul(k_tlk, d_add(t1, t2)), 0.5);
}

/* One contact term of the cubic law at x = y - y_fp: 0 for x <= -eps, x for
 * x >= eps, between them 2 eps (tau^3 - tau^4/2), tau = (x + eps)/(2 eps),
 * whose slope is the smoothstep 3 tau^2 - 2 tau^3. */
static inline dual cubic_term(dual x, dual eps)
{
    if (x.v <= -eps.v) return d_const(0.0);
    if (x.v >= eps.v) return x;
    dual tau = d_div(d_add(x, eps), d_mulc(eps, 2.0));
    dual tau3 = d_mul(d_sq(tau), tau);
    return d_mul(d_mulc(eps, 2.0), d_sub(tau3, d_mulc(d_mul(tau3, tau), 0.5)));
}

/* k [c(y - y_fp) - c(-y - y_fp)]: the two terms of the smoothstep, whose
 * slopes add to 1, give k y at zero freeplay */
static inline dual freeplay_cubic(dual k_tlk, dual y, dual yfp, dual eps)
{
    dual upper = cubic_term(d_sub(y, yfp), eps), lower = cubic_term(d_sub(d_neg(y), yfp), eps);
    return d_mul(k_tlk, d_sub(upper, lower));
}

/* One Hertz-like contact term at depth x = |y| - y_fp: 0 for x <= 0,
 * (2/3) x^(3/2) / eps^(1/2) up to eps, then x - eps/3 (force and stiffness
 * continuous at x = eps) */
static inline dual hertz_term(dual x, dual eps)
{
    if (x.v <= 0.0) return d_const(0.0);
    if (x.v >= eps.v) return d_sub(x, d_mulc(eps, 1.0 / 3.0));
    return d_mulc(d_mul(x, d_sqrt(d_div(x, eps))), 2.0 / 3.0);
}

static inline dual freeplay_hertz(dual k_tlk, dual y, dual yfp, dual eps)
{
    dual upper = hertz_term(d_sub(y, yfp), eps), lower = hertz_term(d_sub(d_neg(y), yfp), eps);
    return d_mul(k_tlk, d_sub(upper, lower));
}

/* The force of law `law` (a valid index: mlg_params_unusable checks it),
 * or of eq. (14) in a given mode (only with law (14): vector_field) */
static inline dual torque_link_force(int law, int mode, dual k_tlk, dual y, dual yfp, dual eps)
{
    if (mode != MLG_MODE_BY_STATE || eps.v == 0.0) return nonsmooth_in_mode(k_tlk, y, yfp, mode);
    switch (law) {
#define X(name, uses_eps, doc) \
    case MLG_FREEPLAY_##name: return freeplay_##name(k_tlk, y, yfp, eps);
        MLG_FREEPLAY_LAWS(X)
#undef X
    }
    return d_const(NAN);
}

#endif
