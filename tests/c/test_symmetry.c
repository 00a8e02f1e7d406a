/* Mirror symmetry of the gear for rho = mu = 0: with S the reflection Y -> -Y
 * (psi, delta, their rates and the tyre deflections change sign, left and
 * right tyres swap), f(S u) = S f(u).  With side-stay angles the mirror image
 * of the side-stay axis u_beta is the axis of (-rho, -mu), so
 * f(S u; -rho, -mu) = S f(u; rho, mu), for every eom_terms level. */
#include "mlg_model.h"
#include "near_equilibrium.h"
#include "unit.h"

static void reflect(const double *u, double *v)
{
    for (int i = 0; i < MLG_NX; i++) v[i] = u[i];
    v[MLG_PSI] = -u[MLG_PSI];
    v[MLG_DELTA] = -u[MLG_DELTA];
    v[MLG_PSI_DOT] = -u[MLG_PSI_DOT];
    v[MLG_DELTA_DOT] = -u[MLG_DELTA_DOT];
    v[MLG_LAMBDA_L] = -u[MLG_LAMBDA_R];
    v[MLG_LAMBDA_R] = -u[MLG_LAMBDA_L];
}

int main(void)
{
    double worst = 0.0;
    int n_ok = 0;
    for (int n = 0; n < 500; n++) {
        mlg_params p = mlg_params_table();
        p.Fstar = unit_between(0.1, 3.5);
        p.V = unit_between(0.0, 600.0);
        p.yfp = n % 2 ? 1.0 : 0.0;
        p.eps_rel = 0.1;
        double u[MLG_NX], su[MLG_NX], f[MLG_NX], fs[MLG_NX], sf[MLG_NX];
        near_equilibrium(&p, u);
        reflect(u, su);
        if (mlg_rhs(&p, u, f) != MLG_OK || mlg_rhs(&p, su, fs) != MLG_OK) continue;
        reflect(f, sf);
        for (int i = 0; i < MLG_NX; i++)
            worst = fmax(worst, fabs(fs[i] - sf[i]) / (fabs(f[i]) + 1e-8));
        n_ok++;
    }
    check(n_ok >= 450, "symmetry_samples", "%d states evaluated", n_ok);
    check(worst <= 1e-9, "mirror_symmetry", "max |f(Su) - S f(u)| / |f(u)| = %.2e", worst);

    /* with a side-stay angle the symmetry is broken (guards against a vacuous test) */
    mlg_params p = mlg_params_table();
    p.rho = 0.1;
    p.mu = 0.2;
    double u[MLG_NX], su[MLG_NX], f[MLG_NX], fs[MLG_NX], sf[MLG_NX];
    mlg_equilibrium(&p, -1.0, u);
    u[MLG_PSI] = 0.003;
    u[MLG_DELTA_DOT] = 0.1;
    reflect(u, su);
    mlg_rhs(&p, u, f);
    mlg_rhs(&p, su, fs);
    reflect(f, sf);
    double broken = 0.0;
    for (int i = 0; i < MLG_NX; i++) broken = fmax(broken, fabs(fs[i] - sf[i]) / (fabs(f[i]) + 1e-8));
    check(broken > 1e-3, "side_stay_breaks_symmetry", "relative asymmetry %.2e", broken);

    double worst_angles = 0.0;
    int n_angles = 0;
    for (int n = 0; n < 600; n++) {
        mlg_params a = mlg_params_table();
        a.Fstar = unit_between(0.2, 3.5);
        a.V = unit_between(0.0, 600.0);
        a.yfp = n % 2 ? 1.0 : 0.0;
        a.rho = unit_between(-0.5, 0.5);
        a.mu = unit_between(-0.5, 0.5);
        a.eom_terms = n % 3;
        mlg_params b = a;
        b.rho = -a.rho;
        b.mu = -a.mu;
        near_equilibrium(&a, u);
        reflect(u, su);
        if (mlg_rhs(&a, u, f) != MLG_OK || mlg_rhs(&b, su, fs) != MLG_OK) continue;
        reflect(f, sf);
        for (int i = 0; i < MLG_NX; i++)
            worst_angles = fmax(worst_angles, fabs(fs[i] - sf[i]) / (fabs(f[i]) + 1e-8));
        n_angles++;
    }
    check(n_angles >= 500 && worst_angles <= 1e-9, "mirror_symmetry_with_side_stay_angles",
          "%d states, max |f(Su; -rho, -mu) - S f(u; rho, mu)| / |f(u)| = %.2e", n_angles,
          worst_angles);
    return unit_exit();
}
