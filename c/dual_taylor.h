/* The `dual` of dual.h as a truncated Taylor polynomial in one variable t:
 * a(t) = v + t[0] t + t[1] t^2 + t[2] t^3 for the model evaluated along the
 * line u + t d (vector_field_taylor.c), so f(u + t d) carries the first
 * three derivatives D^k f(u)[d, ..., d] = k! t[k-1], exact to rounding.
 * The same names and signatures as dual.h's, so the model headers compile
 * unchanged on it; included by dual.h when DUAL_TAYLOR is defined.
 *
 * Arithmetic of truncated power series (Griewank and Walther, Evaluating
 * Derivatives, 2nd ed., chapter 13): products by the Cauchy rule; a smooth
 * g(a) by Faa di Bruno's formula to third order from g', g'', g''' at a.v. */
#ifndef MLG_DUAL_TAYLOR_H
#define MLG_DUAL_TAYLOR_H

#include <math.h>

#define DUAL_INLINE static inline __attribute__((always_inline))

typedef struct {
    double v;        /* value */
    double t[3];     /* t[k-1]: the coefficient of t^k */
} dual;

DUAL_INLINE dual d_const(double c) { dual r = {c, {0.0, 0.0, 0.0}}; return r; }
/* only the states are seeded (d_taylor_seed); a parameter direction is a constant */
DUAL_INLINE dual d_var(double x, int dir) { (void)dir; return d_const(x); }
DUAL_INLINE dual d_taylor_seed(double x, double slope)
{
    dual r = {x, {slope, 0.0, 0.0}};
    return r;
}

DUAL_INLINE int d_finite(dual a)
{
    return isfinite(a.v) && isfinite(a.t[0]) && isfinite(a.t[1]) && isfinite(a.t[2]);
}

DUAL_INLINE dual d_add(dual a, dual b)
{
    dual r = {a.v + b.v, {a.t[0] + b.t[0], a.t[1] + b.t[1], a.t[2] + b.t[2]}};
    return r;
}

DUAL_INLINE dual d_sub(dual a, dual b)
{
    dual r = {a.v - b.v, {a.t[0] - b.t[0], a.t[1] - b.t[1], a.t[2] - b.t[2]}};
    return r;
}

DUAL_INLINE dual d_mulc(dual a, double c)
{
    dual r = {a.v * c, {a.t[0] * c, a.t[1] * c, a.t[2] * c}};
    return r;
}

DUAL_INLINE dual d_neg(dual a) { return d_mulc(a, -1.0); }
DUAL_INLINE dual d_addc(dual a, double c) { a.v += c; return a; }

DUAL_INLINE dual d_mul(dual a, dual b)
{
    dual r = {a.v * b.v,
              {a.v * b.t[0] + a.t[0] * b.v,
               a.v * b.t[1] + a.t[0] * b.t[0] + a.t[1] * b.v,
               a.v * b.t[2] + a.t[0] * b.t[1] + a.t[1] * b.t[0] + a.t[2] * b.v}};
    return r;
}

DUAL_INLINE dual d_sq(dual a) { return d_mul(a, a); }

/* q = a / b from q b = a, coefficient by coefficient */
DUAL_INLINE dual d_div(dual a, dual b)
{
    dual q;
    q.v = a.v / b.v;
    q.t[0] = (a.t[0] - q.v * b.t[0]) / b.v;
    q.t[1] = (a.t[1] - q.v * b.t[1] - q.t[0] * b.t[0]) / b.v;
    q.t[2] = (a.t[2] - q.v * b.t[2] - q.t[0] * b.t[1] - q.t[1] * b.t[0]) / b.v;
    return q;
}

/* g(a) with g(a.v) = g0 and its derivatives g1, g2, g3 there (Faa di Bruno) */
DUAL_INLINE dual d_chain3(dual a, double g0, double g1, double g2, double g3)
{
    dual r = {g0,
              {g1 * a.t[0],
               g1 * a.t[1] + 0.5 * g2 * a.t[0] * a.t[0],
               g1 * a.t[2] + g2 * a.t[0] * a.t[1] + g3 / 6.0 * a.t[0] * a.t[0] * a.t[0]}};
    return r;
}

DUAL_INLINE dual d_sin(dual a)
{
    double s = sin(a.v), c = cos(a.v);
    return d_chain3(a, s, c, -s, -c);
}

DUAL_INLINE dual d_cos(dual a)
{
    double s = sin(a.v), c = cos(a.v);
    return d_chain3(a, c, -s, -c, s);
}

DUAL_INLINE dual d_exp(dual a)
{
    double e = exp(a.v);
    return d_chain3(a, e, e, e, e);
}

DUAL_INLINE dual d_sqrt(dual a)
{
    double s = sqrt(a.v), g1 = 0.5 / s, g2 = -0.5 * g1 / a.v;
    return d_chain3(a, s, g1, g2, -1.5 * g2 / a.v);
}

/* atan' = 1/(1 + x^2), atan'' = -2x/(1 + x^2)^2, atan''' = (6x^2 - 2)/(1 + x^2)^3 */
DUAL_INLINE dual d_atan(dual a)
{
    double w = 1.0 / (1.0 + a.v * a.v);
    return d_chain3(a, atan(a.v), w, -2.0 * a.v * w * w, (6.0 * a.v * a.v - 2.0) * w * w * w);
}

/* tanh' = 1 - t^2, tanh'' = -2 t (1 - t^2), tanh''' = (1 - t^2)(6 t^2 - 2), t = tanh x */
DUAL_INLINE dual d_tanh(dual a)
{
    double t = tanh(a.v), g1 = 1.0 - t * t;
    return d_chain3(a, t, g1, -2.0 * t * g1, g1 * (6.0 * t * t - 2.0));
}

/* acos' = -(1 - x^2)^(-1/2), acos'' = -x (1 - x^2)^(-3/2), acos''' = -(1 + 2x^2) (1 - x^2)^(-5/2) */
DUAL_INLINE dual d_acos(dual a)
{
    double w = 1.0 / (1.0 - a.v * a.v), s = sqrt(w);
    return d_chain3(a, acos(a.v), -s, -a.v * s * w, -(1.0 + 2.0 * a.v * a.v) * s * w * w);
}

/* |a(t)| for t -> 0+: the sign of a's first nonzero coefficient (at a kink,
 * a.v = 0, the one-sided expansion along +d; elsewhere the branch in force) */
DUAL_INLINE dual d_abs(dual a)
{
    double lead = a.v != 0.0 ? a.v : a.t[0] != 0.0 ? a.t[0] : a.t[1] != 0.0 ? a.t[1] : a.t[2];
    return d_mulc(a, lead < 0.0 ? -1.0 : 1.0);
}

/* atan2(y, x) = its value plus the integral of (x y' - y x') / (x^2 + y^2) */
DUAL_INLINE dual d_atan2(dual y, dual x)
{
    /* the derivatives of x and y as series: x'(t) = t[0] + 2 t[1] t + 3 t[2] t^2 */
    dual dx = {x.t[0], {2.0 * x.t[1], 3.0 * x.t[2], 0.0}};
    dual dy = {y.t[0], {2.0 * y.t[1], 3.0 * y.t[2], 0.0}};
    dual rate = d_div(d_sub(d_mul(x, dy), d_mul(y, dx)), d_add(d_sq(x), d_sq(y)));
    dual r = {atan2(y.v, x.v), {rate.v, 0.5 * rate.t[0], rate.t[1] / 3.0}};
    return r;
}

#endif
