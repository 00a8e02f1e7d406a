/* Forward-mode automatic differentiation scalar ("dual number").
 *
 * The model equations are written once, on this type.  Each translation
 * unit that includes the model headers defines DUAL_N, the number of
 * derivative directions carried alongside the value:
 *   DUAL_N == 0  : plain values (the derivative loops compile away);
 *   DUAL_N == n  : value plus n directional derivatives, exact to rounding.
 * vector_field_value.c and vector_field_jacobian.c compile the same model
 * with the two settings (see docs/model.md, "Jacobian").
 */
#ifndef MLG_DUAL_H
#define MLG_DUAL_H

#ifndef DUAL_N
#error "define DUAL_N (number of derivative directions) before including dual.h"
#endif

#include <math.h>

typedef struct {
    double v;                               /* value */
    double d[DUAL_N > 0 ? DUAL_N : 1];      /* derivatives, d[k] = dv/dx_k */
} dual;

#define DUAL_LOOP(k) for (int k = 0; k < DUAL_N; k++)

static inline dual d_const(double c)
{
    dual r;
    r.v = c;
    DUAL_LOOP(k) r.d[k] = 0.0;
    return r;
}

/* Independent variable number `dir` (0-based) with value x. */
static inline dual d_var(double x, int dir)
{
    dual r = d_const(x);
    if (dir >= 0 && dir < DUAL_N) r.d[dir] = 1.0;
    return r;
}

static inline dual d_add(dual a, dual b)
{
    dual r;
    r.v = a.v + b.v;
    DUAL_LOOP(k) r.d[k] = a.d[k] + b.d[k];
    return r;
}

static inline dual d_sub(dual a, dual b)
{
    dual r;
    r.v = a.v - b.v;
    DUAL_LOOP(k) r.d[k] = a.d[k] - b.d[k];
    return r;
}

static inline dual d_mul(dual a, dual b)
{
    dual r;
    r.v = a.v * b.v;
    DUAL_LOOP(k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
    return r;
}

static inline dual d_div(dual a, dual b)
{
    dual r;
    r.v = a.v / b.v;
    DUAL_LOOP(k) r.d[k] = (a.d[k] - r.v * b.d[k]) / b.v;
    return r;
}

static inline dual d_neg(dual a)
{
    dual r;
    r.v = -a.v;
    DUAL_LOOP(k) r.d[k] = -a.d[k];
    return r;
}

/* a + c and a * c for a plain constant c */
static inline dual d_addc(dual a, double c)
{
    a.v += c;
    return a;
}

static inline dual d_mulc(dual a, double c)
{
    dual r;
    r.v = a.v * c;
    DUAL_LOOP(k) r.d[k] = a.d[k] * c;
    return r;
}

/* Chain rule: r = g(a) with g(a.v) = value and g'(a.v) = slope. */
static inline dual d_chain(dual a, double value, double slope)
{
    dual r;
    r.v = value;
    DUAL_LOOP(k) r.d[k] = slope * a.d[k];
    return r;
}

static inline dual d_sq(dual a) { return d_chain(a, a.v * a.v, 2.0 * a.v); }
static inline dual d_sin(dual a) { return d_chain(a, sin(a.v), cos(a.v)); }
static inline dual d_cos(dual a) { return d_chain(a, cos(a.v), -sin(a.v)); }
static inline dual d_exp(dual a) { double e = exp(a.v); return d_chain(a, e, e); }
static inline dual d_atan(dual a) { return d_chain(a, atan(a.v), 1.0 / (1.0 + a.v * a.v)); }
static inline dual d_abs(dual a) { return d_chain(a, fabs(a.v), a.v < 0.0 ? -1.0 : 1.0); }

static inline dual d_sqrt(dual a)
{
    double s = sqrt(a.v);
    return d_chain(a, s, 0.5 / s);
}

static inline dual d_acos(dual a)
{
    return d_chain(a, acos(a.v), -1.0 / sqrt(1.0 - a.v * a.v));
}

static inline dual d_atan2(dual y, dual x)
{
    double den = x.v * x.v + y.v * y.v;
    dual r;
    r.v = atan2(y.v, x.v);
    DUAL_LOOP(k) r.d[k] = (x.v * y.d[k] - y.v * x.d[k]) / den;
    return r;
}

#endif
