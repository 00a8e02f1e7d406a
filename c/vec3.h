/* 3-vectors and 3x3 matrices over the dual scalar; Rodrigues rotation. */
#ifndef MLG_VEC3_H
#define MLG_VEC3_H

#include "dual.h"

/* Forced inline in the derivative builds: a dual of ten directions is 128
 * bytes (AVX2), a dmat nine of them, and an out-of-line call passes these by
 * value through memory, copies that cost more than the arithmetic.  The
 * plain-double build keeps the compiler's choice (its f is faster so). */
#if DUAL_N > 0
#define VEC3_INLINE DUAL_INLINE
#else
#define VEC3_INLINE static inline
#endif

typedef struct { dual c[3]; } dvec;      /* components X, Y, Z */
typedef struct { dual a[3][3]; } dmat;   /* a[row][column] */

VEC3_INLINE dvec v_make(dual x, dual y, dual z)
{
    dvec r = {{x, y, z}};
    return r;
}

VEC3_INLINE dvec v_const(double x, double y, double z)
{
    return v_make(d_const(x), d_const(y), d_const(z));
}

VEC3_INLINE dvec v_add(dvec a, dvec b)
{
    return v_make(d_add(a.c[0], b.c[0]), d_add(a.c[1], b.c[1]), d_add(a.c[2], b.c[2]));
}

VEC3_INLINE dvec v_sub(dvec a, dvec b)
{
    return v_make(d_sub(a.c[0], b.c[0]), d_sub(a.c[1], b.c[1]), d_sub(a.c[2], b.c[2]));
}

VEC3_INLINE dvec v_neg(dvec a)
{
    return v_make(d_neg(a.c[0]), d_neg(a.c[1]), d_neg(a.c[2]));
}

VEC3_INLINE dvec v_scale(dvec a, dual s)
{
    return v_make(d_mul(a.c[0], s), d_mul(a.c[1], s), d_mul(a.c[2], s));
}

VEC3_INLINE dvec v_scalec(dvec a, double s)
{
    return v_make(d_mulc(a.c[0], s), d_mulc(a.c[1], s), d_mulc(a.c[2], s));
}

VEC3_INLINE dual v_dot(dvec a, dvec b)
{
    return d_add(d_add(d_mul(a.c[0], b.c[0]), d_mul(a.c[1], b.c[1])), d_mul(a.c[2], b.c[2]));
}

VEC3_INLINE dvec v_cross(dvec a, dvec b)
{
    return v_make(d_sub(d_mul(a.c[1], b.c[2]), d_mul(a.c[2], b.c[1])),
                  d_sub(d_mul(a.c[2], b.c[0]), d_mul(a.c[0], b.c[2])),
                  d_sub(d_mul(a.c[0], b.c[1]), d_mul(a.c[1], b.c[0])));
}

/* The matrix operations write through r, which must not be an operand:
 * a dmat returned by value is copied (1152 bytes at ten directions). */

/* r = m x */
VEC3_INLINE void m_apply(dvec *r, const dmat *m, const dvec *x)
{
    for (int i = 0; i < 3; i++)
        r->c[i] = d_add(d_add(d_mul(m->a[i][0], x->c[0]), d_mul(m->a[i][1], x->c[1])),
                        d_mul(m->a[i][2], x->c[2]));
}

/* r = p q */
VEC3_INLINE void m_mul(dmat *r, const dmat *p, const dmat *q)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r->a[i][j] = d_add(d_add(d_mul(p->a[i][0], q->a[0][j]), d_mul(p->a[i][1], q->a[1][j])),
                               d_mul(p->a[i][2], q->a[2][j]));
}

/* r = R(v, theta): right-hand rotation by theta about the unit vector v
 * (Rodrigues: R = cos t I + sin t [v]x + (1 - cos t) v v^T). */
VEC3_INLINE void m_rotation(dmat *r, const dvec *v, dual theta)
{
    dual c = d_cos(theta), s = d_sin(theta);
    dual one_c = d_sub(d_const(1.0), c);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r->a[i][j] = d_mul(one_c, d_mul(v->c[i], v->c[j]));
    for (int i = 0; i < 3; i++)
        r->a[i][i] = d_add(r->a[i][i], c);
    r->a[0][1] = d_sub(r->a[0][1], d_mul(s, v->c[2]));
    r->a[1][0] = d_add(r->a[1][0], d_mul(s, v->c[2]));
    r->a[0][2] = d_add(r->a[0][2], d_mul(s, v->c[1]));
    r->a[2][0] = d_sub(r->a[2][0], d_mul(s, v->c[1]));
    r->a[1][2] = d_sub(r->a[1][2], d_mul(s, v->c[0]));
    r->a[2][1] = d_add(r->a[2][1], d_mul(s, v->c[0]));
}

#endif
