/* The builds of vector_field_jacobian.c: mlg_rhs_jacobian (jacobian_dispatch.c)
 * calls the AVX2 one on CPUs that have AVX2, the generic x86-64 one elsewhere.
 * Both round every operation alike (no FMA: -std=c11 keeps a*b + c as two
 * roundings), so their results are bitwise equal (tests/c/test_jacobian.c). */
#ifndef MLG_JACOBIAN_VARIANTS_H
#define MLG_JACOBIAN_VARIANTS_H

#include "mlg_model.h"

int mlg_rhs_jacobian_generic(const mlg_params *p, const int *modes, const double u[MLG_NX],
                             double f[MLG_NX], double dfdu[MLG_NX * MLG_NX],
                             double dfdp[MLG_NX * MLG_NPAR]);

#ifdef MLG_HAVE_AVX2_VARIANT
int mlg_rhs_jacobian_avx2(const mlg_params *p, const int *modes, const double u[MLG_NX],
                          double f[MLG_NX], double dfdu[MLG_NX * MLG_NX],
                          double dfdp[MLG_NX * MLG_NPAR]);
#endif

#endif
