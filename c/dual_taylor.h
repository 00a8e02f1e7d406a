/* The `dual` of dual.h as a truncated Taylor polynomial in one variable t:
 * a(t) = v + t[0] t + ... + t[K-1] t^K, K = DUAL_TAYLOR_ORDER, for the model
 * evaluated along the line u + t d (vector_field_taylor.c), so f(u + t d)
 * carries the derivatives D^k f(u)[d, ..., d] = k! t[k-1], k = 1..K, exact
 * to rounding.  The same names and signatures as dual.h's, so the model
 * headers compile unchanged on it; included by dual.h when DUAL_TAYLOR is
 * defined.
 *
 * Arithmetic of truncated power series (Griewank and Walther, Evaluating
 * Derivatives, 2nd ed., chapter 13): products by the Cauchy rule, quotients
 * and square roots by the recursions of q b = a and s s = a, and each
 * elementary function by the recursion of the linear ODE it solves along t
 * (exp' = exp a', tanh' = (1 - tanh^2) a', ...), so any order K is one
 * constant: K = 5 gives the forms up to E of the second Lyapunov coefficient. */
#ifndef MLG_DUAL_TAYLOR_H
#define MLG_DUAL_TAYLOR_H

#include <math.h>

#define DUAL_INLINE static inline __attribute__((always_inline))
#define DUAL_TAYLOR_ORDER 5

typedef struct {
    double v;                      /* value */
    double t[DUAL_TAYLOR_ORDER];   /* t[k-1]: the coefficient of t^k */
} dual;

/* The coefficient of t^k, k = 0..K (k = 0: the value) */
DUAL_INLINE double d_coef(const dual *a, int k) { return k == 0 ? a->v : a->t[k - 1]; }
DUAL_INLINE void d_set(dual *a, int k, double c)
{
    if (k == 0) a->v = c;
    else a->t[k - 1] = c;
}

DUAL_INLINE dual d_const(double c)
{
    dual r = {c, {0.0}};
    return r;
}
/* only the states are seeded (d_taylor_seed); a parameter direction is a constant */
DUAL_INLINE dual d_var(double x, int dir) { (void)dir; return d_const(x); }
DUAL_INLINE dual d_taylor_seed(double x, double slope)
{
    dual r = d_const(x);
    r.t[0] = slope;
    return r;
}

DUAL_INLINE int d_finite(dual a)
{
    int finite = isfinite(a.v);
    for (int k = 0; k < DUAL_TAYLOR_ORDER; k++) finite = finite && isfinite(a.t[k]);
    return finite;
}

DUAL_INLINE dual d_add(dual a, dual b)
{
    a.v += b.v;
    for (int k = 0; k < DUAL_TAYLOR_ORDER; k++) a.t[k] += b.t[k];
    return a;
}

DUAL_INLINE dual d_sub(dual a, dual b)
{
    a.v -= b.v;
    for (int k = 0; k < DUAL_TAYLOR_ORDER; k++) a.t[k] -= b.t[k];
    return a;
}

DUAL_INLINE dual d_mulc(dual a, double c)
{
    a.v *= c;
    for (int k = 0; k < DUAL_TAYLOR_ORDER; k++) a.t[k] *= c;
    return a;
}

DUAL_INLINE dual d_neg(dual a) { return d_mulc(a, -1.0); }
DUAL_INLINE dual d_addc(dual a, double c) { a.v += c; return a; }

/* the Cauchy product: r_k = sum_j a_j b_(k-j) */
DUAL_INLINE dual d_mul(dual a, dual b)
{
    dual r;
    for (int k = 0; k <= DUAL_TAYLOR_ORDER; k++) {
        double s = 0.0;
        for (int j = 0; j <= k; j++) s += d_coef(&a, j) * d_coef(&b, k - j);
        d_set(&r, k, s);
    }
    return r;
}

DUAL_INLINE dual d_sq(dual a) { return d_mul(a, a); }

/* q = a / b from q b = a, coefficient by coefficient */
DUAL_INLINE dual d_div(dual a, dual b)
{
    dual q;
    for (int k = 0; k <= DUAL_TAYLOR_ORDER; k++) {
        double s = d_coef(&a, k);
        for (int j = 0; j < k; j++) s -= d_coef(&q, j) * d_coef(&b, k - j);
        d_set(&q, k, s / b.v);
    }
    return q;
}

/* s = sqrt(a) from s s = a: s_k = (a_k - sum_(0<j<k) s_j s_(k-j)) / (2 s_0) */
DUAL_INLINE dual d_sqrt(dual a)
{
    dual s = d_const(sqrt(a.v));
    for (int k = 1; k <= DUAL_TAYLOR_ORDER; k++) {
        double c = d_coef(&a, k);
        for (int j = 1; j < k; j++) c -= d_coef(&s, j) * d_coef(&s, k - j);
        d_set(&s, k, c / (2.0 * s.v));
    }
    return s;
}

/* a'(t) as a series (its top coefficient, beyond the order, left 0) */
DUAL_INLINE dual d_rate(dual a)
{
    dual r = d_const(0.0);
    for (int k = 0; k < DUAL_TAYLOR_ORDER; k++) d_set(&r, k, (k + 1) * a.t[k]);
    return r;
}

/* value + the integral of rate(t) from 0 */
DUAL_INLINE dual d_integral(double value, dual rate)
{
    dual r = d_const(value);
    for (int k = 1; k <= DUAL_TAYLOR_ORDER; k++) d_set(&r, k, d_coef(&rate, k - 1) / k);
    return r;
}

/* r with r' = r a': k r_k = sum_(j=1..k) j a_j r_(k-j) */
DUAL_INLINE dual d_exp(dual a)
{
    dual r = d_const(exp(a.v));
    for (int k = 1; k <= DUAL_TAYLOR_ORDER; k++) {
        double s = 0.0;
        for (int j = 1; j <= k; j++) s += j * d_coef(&a, j) * d_coef(&r, k - j);
        d_set(&r, k, s / k);
    }
    return r;
}

/* s = sin a, c = cos a together: s' = c a', c' = -s a' */
DUAL_INLINE void d_sincos(dual a, dual *s, dual *c)
{
    *s = d_const(sin(a.v)), *c = d_const(cos(a.v));
    for (int k = 1; k <= DUAL_TAYLOR_ORDER; k++) {
        double ds = 0.0, dc = 0.0;
        for (int j = 1; j <= k; j++) {
            ds += j * d_coef(&a, j) * d_coef(c, k - j);
            dc -= j * d_coef(&a, j) * d_coef(s, k - j);
        }
        d_set(s, k, ds / k), d_set(c, k, dc / k);
    }
}

DUAL_INLINE dual d_sin(dual a)
{
    dual s, c;
    d_sincos(a, &s, &c);
    return s;
}

DUAL_INLINE dual d_cos(dual a)
{
    dual s, c;
    d_sincos(a, &s, &c);
    return c;
}

/* r = tanh a: r' = w a' with w = 1 - r^2, whose coefficient k-1 needs r up to k-1 */
DUAL_INLINE dual d_tanh(dual a)
{
    dual r = d_const(tanh(a.v)), w = d_const(0.0);
    for (int k = 1; k <= DUAL_TAYLOR_ORDER; k++) {
        double wk = k == 1 ? 1.0 : 0.0, s = 0.0;
        for (int i = 0; i <= k - 1; i++) wk -= d_coef(&r, i) * d_coef(&r, k - 1 - i);
        d_set(&w, k - 1, wk);
        for (int j = 1; j <= k; j++) s += j * d_coef(&a, j) * d_coef(&w, k - j);
        d_set(&r, k, s / k);
    }
    return r;
}

/* atan a = its value + the integral of a' / (1 + a^2) */
DUAL_INLINE dual d_atan(dual a)
{
    return d_integral(atan(a.v), d_div(d_rate(a), d_addc(d_sq(a), 1.0)));
}

/* acos a = its value - the integral of a' / sqrt(1 - a^2) */
DUAL_INLINE dual d_acos(dual a)
{
    return d_integral(acos(a.v), d_neg(d_div(d_rate(a), d_sqrt(d_addc(d_neg(d_sq(a)), 1.0)))));
}

/* |a(t)| for t -> 0+: the sign of a's first nonzero coefficient (at a kink,
 * a.v = 0, the one-sided expansion along +d; elsewhere the branch in force) */
DUAL_INLINE dual d_abs(dual a)
{
    double lead = 0.0;
    for (int k = 0; k <= DUAL_TAYLOR_ORDER && lead == 0.0; k++) lead = d_coef(&a, k);
    return d_mulc(a, lead < 0.0 ? -1.0 : 1.0);
}

/* atan2(y, x) = its value plus the integral of (x y' - y x') / (x^2 + y^2) */
DUAL_INLINE dual d_atan2(dual y, dual x)
{
    dual rate = d_div(d_sub(d_mul(x, d_rate(y)), d_mul(y, d_rate(x))), d_add(d_sq(x), d_sq(y)));
    return d_integral(atan2(y.v, x.v), rate);
}

#endif
