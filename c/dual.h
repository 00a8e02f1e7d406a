/* Forward-mode automatic differentiation scalar ("dual number").
 *
 * The model equations are written once, on this type.  Each translation
 * unit that includes the model headers defines DUAL_N, the number of
 * derivative directions carried alongside the value:
 *   DUAL_N == 0  : plain values (the derivative code compiles away);
 *   DUAL_N == n  : value plus n directional derivatives, exact to rounding.
 *
 * The directions are held in blocks of DUAL_LANES doubles, each a GCC vector
 * that the compiler maps to SIMD instructions, as wide as the target's
 * registers: a wider vector is split through memory (twice the cost).
 * Every operation is one call of the chain rule d_lin1, d_lin2 or d_lin2_over.
 * vector_field_value.c and vector_field_jacobian.c compile the same model
 * with the two settings.  With DUAL_TAYLOR defined instead, `dual` carries
 * five derivatives along one direction (dual_taylor.h,
 * vector_field_taylor.c). */
#ifndef MLG_DUAL_H
#define MLG_DUAL_H

#ifdef DUAL_TAYLOR
#include "dual_taylor.h"
#else

#ifndef DUAL_N
#error "define DUAL_N (number of derivative directions) before including dual.h"
#endif

#include <math.h>

/* Two lanes, the SSE2 width of every x86-64; four in a unit built for AVX
 * (the AVX2 variant of the Jacobian, c/c.mk) */
#ifdef __AVX__
#define DUAL_LANES 4
#else
#define DUAL_LANES 2
#endif
#define DUAL_BLOCKS ((DUAL_N + DUAL_LANES - 1) / DUAL_LANES)
#define DUAL_INLINE static inline __attribute__((always_inline))

#if DUAL_N == 0

typedef struct {
    double v;                               /* value */
} dual;

DUAL_INLINE dual d_const(double c) { dual r = {c}; return r; }
DUAL_INLINE dual d_var(double x, int dir) { (void)dir; return d_const(x); }
/* r.v = value; dr = sa da + sb db, or that over den (derivatives only when DUAL_N > 0) */
DUAL_INLINE int d_finite(dual a) { return isfinite(a.v); }
DUAL_INLINE dual d_lin2(double value, dual a, double sa, dual b, double sb)
{
    (void)a, (void)sa, (void)b, (void)sb;
    return d_const(value);
}
DUAL_INLINE dual d_lin1(double value, dual a, double sa)
{
    (void)a, (void)sa;
    return d_const(value);
}
DUAL_INLINE dual d_lin2_over(double value, dual a, double sa, dual b, double sb, double den)
{
    (void)a, (void)sa, (void)b, (void)sb, (void)den;
    return d_const(value);
}

#else

typedef double dual_block __attribute__((vector_size(DUAL_LANES * sizeof(double))));

typedef struct {
    double v;                               /* value */
    dual_block d[DUAL_BLOCKS];              /* d[b][l] = dv/dx_(DUAL_LANES b + l) */
} dual;

DUAL_INLINE dual d_const(double c)
{
    dual r;
    r.v = c;
    for (int k = 0; k < DUAL_BLOCKS; k++) r.d[k] = (dual_block){0.0};
    return r;
}

DUAL_INLINE dual d_var(double x, int dir)
{
    dual r = d_const(x);
    if (dir >= 0 && dir < DUAL_N) r.d[dir / DUAL_LANES][dir % DUAL_LANES] = 1.0;
    return r;
}

DUAL_INLINE double d_slope(dual a, int dir) { return a.d[dir / DUAL_LANES][dir % DUAL_LANES]; }

/* the value and every derivative finite */
DUAL_INLINE int d_finite(dual a)
{
    int finite = isfinite(a.v);
    for (int dir = 0; dir < DUAL_N; dir++) finite &= isfinite(d_slope(a, dir));
    return finite;
}

DUAL_INLINE dual d_lin2(double value, dual a, double sa, dual b, double sb)
{
    dual r;
    r.v = value;
    for (int k = 0; k < DUAL_BLOCKS; k++) r.d[k] = sa * a.d[k] + sb * b.d[k];
    return r;
}

DUAL_INLINE dual d_lin1(double value, dual a, double sa)
{
    dual r;
    r.v = value;
    for (int k = 0; k < DUAL_BLOCKS; k++) r.d[k] = sa * a.d[k];
    return r;
}

/* dr = (sa da + sb db) / den: a quotient's rule, rounded as it is written */
DUAL_INLINE dual d_lin2_over(double value, dual a, double sa, dual b, double sb, double den)
{
    dual r;
    r.v = value;
    for (int k = 0; k < DUAL_BLOCKS; k++) r.d[k] = (sa * a.d[k] + sb * b.d[k]) / den;
    return r;
}

#endif

DUAL_INLINE dual d_add(dual a, dual b) { return d_lin2(a.v + b.v, a, 1.0, b, 1.0); }
DUAL_INLINE dual d_sub(dual a, dual b) { return d_lin2(a.v - b.v, a, 1.0, b, -1.0); }
DUAL_INLINE dual d_mul(dual a, dual b) { return d_lin2(a.v * b.v, a, b.v, b, a.v); }
DUAL_INLINE dual d_neg(dual a) { return d_lin1(-a.v, a, -1.0); }

DUAL_INLINE dual d_div(dual a, dual b)
{
    double q = a.v / b.v;
    return d_lin2_over(q, a, 1.0, b, -q, b.v);
}

/* a + c and a * c for a plain constant c */
DUAL_INLINE dual d_addc(dual a, double c)
{
    a.v += c;
    return a;
}

DUAL_INLINE dual d_mulc(dual a, double c) { return d_lin1(a.v * c, a, c); }

/* Chain rule: r = g(a) with g(a.v) = value and g'(a.v) = slope. */
DUAL_INLINE dual d_chain(dual a, double value, double slope) { return d_lin1(value, a, slope); }

DUAL_INLINE dual d_sq(dual a) { return d_chain(a, a.v * a.v, 2.0 * a.v); }
DUAL_INLINE dual d_sin(dual a) { return d_chain(a, sin(a.v), cos(a.v)); }
DUAL_INLINE dual d_cos(dual a) { return d_chain(a, cos(a.v), -sin(a.v)); }
DUAL_INLINE dual d_exp(dual a) { double e = exp(a.v); return d_chain(a, e, e); }
DUAL_INLINE dual d_atan(dual a) { return d_chain(a, atan(a.v), 1.0 / (1.0 + a.v * a.v)); }
DUAL_INLINE dual d_tanh(dual a) { double t = tanh(a.v); return d_chain(a, t, 1.0 - t * t); }
DUAL_INLINE dual d_abs(dual a) { return d_chain(a, fabs(a.v), a.v < 0.0 ? -1.0 : 1.0); }

DUAL_INLINE dual d_sqrt(dual a)
{
    double s = sqrt(a.v);
    return d_chain(a, s, 0.5 / s);
}

DUAL_INLINE dual d_acos(dual a)
{
    return d_chain(a, acos(a.v), -1.0 / sqrt(1.0 - a.v * a.v));
}

DUAL_INLINE dual d_atan2(dual y, dual x)
{
    double den = x.v * x.v + y.v * y.v;
    return d_lin2_over(atan2(y.v, x.v), y, x.v, x, -y.v, den);
}

#endif /* DUAL_TAYLOR */

#endif
