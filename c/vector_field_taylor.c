/* Higher derivatives of f, exact to rounding: the model of vector_field.h
 * on truncated Taylor polynomials (dual_taylor.h) along one direction d,
 * and the multilinear forms B and C (Kuznetsov, Elements of Applied
 * Bifurcation Theory, 3rd ed., eq. (3.3)) by polarisation of those
 * directional derivatives: exact identities, no step. */
#define DUAL_TAYLOR
#include "vector_field.h"

int mlg_rhs_taylor(const mlg_params *p, const double u[MLG_NX], const double d[MLG_NX],
                   double f[4 * MLG_NX])
{
    dual x[MLG_NX], fx[MLG_NX];
    for (int i = 0; i < MLG_NX; i++) x[i] = d_taylor_seed(u[i], d[i]);
    int status = vector_field(p, x, NULL, MLG_PARS_PLAIN, fx, NULL);   /* modes by state */
    static const double factorial[3] = {1.0, 2.0, 6.0};
    for (int i = 0; i < MLG_NX; i++) {
        f[i] = fx[i].v;
        for (int k = 1; k <= 3; k++) f[i + MLG_NX * k] = factorial[k - 1] * fx[i].t[k - 1];
    }
    return status;
}

/* D^order f(u)[d, ..., d] along d = sum_k sign[k] v[k] / |v[k]|_max, added
 * into out with weight w; *scale gets the product of the |v[k]|_max */
static int polarise(const mlg_params *p, const double u[MLG_NX], int n,
                    const double *const v[], const int sign[], double w, double out[MLG_NX],
                    double *scale)
{
    double d[MLG_NX] = {0.0}, f[4 * MLG_NX];
    *scale = 1.0;
    for (int k = 0; k < n; k++) {
        double size = 0.0;
        for (int i = 0; i < MLG_NX; i++) size = fmax(size, fabs(v[k][i]));
        if (size == 0.0) size = 1.0;   /* a zero argument: the form is zero either way */
        *scale *= size;
        for (int i = 0; i < MLG_NX; i++) d[i] += sign[k] * v[k][i] / size;
    }
    int status = mlg_rhs_taylor(p, u, d, f);
    for (int i = 0; i < MLG_NX; i++) out[i] += w * f[i + MLG_NX * n];
    return status;
}

/* B(x, y) = (D^2 f[x + y] - D^2 f[x - y]) / 4, x and y scaled to max-norm 1 */
int mlg_second_form(const mlg_params *p, const double u[MLG_NX], const double x[MLG_NX],
                    const double y[MLG_NX], double B[MLG_NX])
{
    const double *v[2] = {x, y};
    double scale = 1.0;
    int status = MLG_OK;
    for (int i = 0; i < MLG_NX; i++) B[i] = 0.0;
    for (int s = -1; s <= 1; s += 2)
        status |= polarise(p, u, 2, v, (const int[2]){1, s}, 0.25 * s, B, &scale);
    for (int i = 0; i < MLG_NX; i++) B[i] = status == MLG_OK ? scale * B[i] : 0.0;
    return status;
}

/* C(x, y, z) = sum over s, r = +-1 of s r D^3 f[x + s y + r z] / 24 */
int mlg_third_form(const mlg_params *p, const double u[MLG_NX], const double x[MLG_NX],
                   const double y[MLG_NX], const double z[MLG_NX], double C[MLG_NX])
{
    const double *v[3] = {x, y, z};
    double scale = 1.0;
    int status = MLG_OK;
    for (int i = 0; i < MLG_NX; i++) C[i] = 0.0;
    for (int s = -1; s <= 1; s += 2)
        for (int r = -1; r <= 1; r += 2)
            status |= polarise(p, u, 3, v, (const int[3]){1, s, r}, s * r / 24.0, C, &scale);
    for (int i = 0; i < MLG_NX; i++) C[i] = status == MLG_OK ? scale * C[i] : 0.0;
    return status;
}
