/* Smoke model: Hopf normal form with the bifurcation moved to p = s, where
   s = smoke_hopf_value() = sqrt(2) comes from a separately built static
   library.

     x' = (p - s) x - y - x (x^2 + y^2)
     y' = x + (p - s) y - y (x^2 + y^2)

   The origin has eigenvalues p - s +- i: a supercritical Hopf bifurcation at
   p = s, with periodic orbits x^2 + y^2 = p - s of period 2 pi for p > s. */
#include "auto_f2c.h"
#include "shift.h"

int func(integer ndim, const doublereal *u, const integer *icp,
         const doublereal *par, integer ijac,
         doublereal *f, doublereal *dfdu, doublereal *dfdp)
{
    integer dfdu_dim1 = ndim, dfdp_dim1 = ndim;
    doublereal x = u[0], y = u[1];
    doublereal mu = par[0] - smoke_hopf_value();
    doublereal r2 = x * x + y * y;

    f[0] = mu * x - y - x * r2;
    f[1] = x + mu * y - y * r2;
    if (ijac == 0)
        return 0;

    ARRAY2D(dfdu, 0, 0) = mu - 3 * x * x - y * y;
    ARRAY2D(dfdu, 0, 1) = -1 - 2 * x * y;
    ARRAY2D(dfdu, 1, 0) = 1 - 2 * x * y;
    ARRAY2D(dfdu, 1, 1) = mu - x * x - 3 * y * y;
    if (ijac == 1)
        return 0;

    ARRAY2D(dfdp, 0, 0) = x;
    ARRAY2D(dfdp, 1, 0) = y;
    return 0;
}

int stpnt(integer ndim, doublereal t, doublereal *u, doublereal *par)
{
    par[0] = 0.0;
    u[0] = 0.0;
    u[1] = 0.0;
    return 0;
}

int bcnd(integer ndim, const doublereal *par, const integer *icp,
         integer nbc, const doublereal *u0, const doublereal *u1, integer ijac,
         doublereal *fb, doublereal *dbc)
{
    return 0;
}

int icnd(integer ndim, const doublereal *par, const integer *icp,
         integer nint, const doublereal *u, const doublereal *uold,
         const doublereal *udot, const doublereal *upold, integer ijac,
         doublereal *fi, doublereal *dint)
{
    return 0;
}

int fopt(integer ndim, const doublereal *u, const integer *icp,
         const doublereal *par, integer ijac,
         doublereal *fs, doublereal *dfdu, doublereal *dfdp)
{
    return 0;
}

/* PAR(21): maximum of x over the orbit (the amplitude sqrt(p - s)). */
int pvls(integer ndim, const doublereal *u, doublereal *par)
{
    par[20] = getp("MAX", 1, u);
    return 0;
}
