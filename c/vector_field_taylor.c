/* Higher derivatives of f, exact to rounding: the model of vector_field.h
 * on truncated Taylor polynomials (dual_taylor.h) along one direction d,
 * and the multilinear forms B, C, D, E (Kuznetsov, Elements of Applied
 * Bifurcation Theory, 3rd ed., eqs. (3.3) and (8.21)) by polarisation of
 * those directional derivatives: exact identities, no step. */
#define DUAL_TAYLOR
#include "vector_field.h"

_Static_assert(DUAL_TAYLOR_ORDER == MLG_TAYLOR_ORDER, "dual_taylor.h carries mlg_model.h's order");

int mlg_taylor_order(void) { return MLG_TAYLOR_ORDER; }

int mlg_rhs_taylor(const mlg_params *p, const double u[MLG_NX], const double d[MLG_NX],
                   double f[(MLG_TAYLOR_ORDER + 1) * MLG_NX])
{
    dual x[MLG_NX], fx[MLG_NX];
    for (int i = 0; i < MLG_NX; i++) x[i] = d_taylor_seed(u[i], d[i]);
    int status = vector_field(p, x, NULL, MLG_PARS_PLAIN, fx, NULL);   /* modes by state */
    for (int i = 0; i < MLG_NX; i++) {
        double factorial = 1.0;
        for (int k = 0; k <= MLG_TAYLOR_ORDER; k++, factorial *= k)
            f[i + MLG_NX * k] = factorial * d_coef(&fx[i], k);
    }
    return status;
}

/* F(v_1, ..., v_n) = 1 / (2^(n-1) n!) sum over the signs s_k = +-1 (s_1 = 1)
 * of s_2 ... s_n D^n f[sum_k s_k v_k], each v_k scaled to max-norm 1 first
 * (the polarisation identity of a symmetric n-linear form) */
int mlg_form(const mlg_params *p, const double u[MLG_NX], int n, const double *const v[],
             double F[MLG_NX])
{
    for (int i = 0; i < MLG_NX; i++) F[i] = 0.0;
    if (n < 1 || n > MLG_TAYLOR_ORDER) return MLG_BAD_PARAMETER;
    double scale = 1.0, size[MLG_TAYLOR_ORDER], weight = 1.0;
    for (int k = 0; k < n; k++) {
        size[k] = 0.0;
        for (int i = 0; i < MLG_NX; i++) size[k] = fmax(size[k], fabs(v[k][i]));
        if (size[k] == 0.0) size[k] = 1.0;   /* a zero argument: the form is zero either way */
        scale *= size[k];
        weight *= k == 0 ? 1.0 : 2.0 * (k + 1);   /* 2^(n-1) n! */
    }
    int status = MLG_OK;
    for (int signs = 0; signs < 1 << (n - 1); signs++) {
        double d[MLG_NX], f[(MLG_TAYLOR_ORDER + 1) * MLG_NX], sign = 1.0;
        for (int i = 0; i < MLG_NX; i++) d[i] = v[0][i] / size[0];
        for (int k = 1; k < n; k++) {
            double s = (signs >> (k - 1)) & 1 ? -1.0 : 1.0;
            sign *= s;
            for (int i = 0; i < MLG_NX; i++) d[i] += s * v[k][i] / size[k];
        }
        status |= mlg_rhs_taylor(p, u, d, f);
        for (int i = 0; i < MLG_NX; i++) F[i] += sign / weight * f[i + MLG_NX * n];
    }
    for (int i = 0; i < MLG_NX; i++) F[i] = status == MLG_OK ? scale * F[i] : 0.0;
    return status;
}

int mlg_second_form(const mlg_params *p, const double u[MLG_NX], const double x[MLG_NX],
                    const double y[MLG_NX], double B[MLG_NX])
{
    return mlg_form(p, u, 2, (const double *const[2]){x, y}, B);
}

int mlg_third_form(const mlg_params *p, const double u[MLG_NX], const double x[MLG_NX],
                   const double y[MLG_NX], const double z[MLG_NX], double C[MLG_NX])
{
    return mlg_form(p, u, 3, (const double *const[3]){x, y, z}, C);
}
