/* Example: the MLG model's vector field f and its Jacobian at straight
 * rolling, through the installed library.
 *
 *   cc evaluate.c $(pkg-config --cflags --libs mlg) -o evaluate
 *   ./evaluate [V [Fstar]]       (defaults: V = 100 m/s, F* = 1)
 *
 * It takes the `figures` parameter set, finds the straight-rolling
 * equilibrium u* (f(u*) = 0), evaluates f and df/du there, prints them, and
 * checks the exact Jacobian against central differences of f.  The states
 * are in SI units (rad, m, rad/s, m/s); docs/c-library.md describes the
 * interface. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <mlg_model.h>

int main(int argc, char **argv)
{
    mlg_params p = mlg_params_figures();
    p.V = argc > 1 ? atof(argv[1]) : 100.0;
    p.Fstar = argc > 2 ? atof(argv[2]) : 1.0;
    char why[256];
    if (mlg_params_check(&p, why, sizeof why) != 0) {
        fprintf(stderr, "evaluate: %s\n", why);
        return 1;
    }
    printf("mlg %s (library %s)\n", MLG_VERSION, mlg_version());
    printf("parameters: figures, V = %g m/s, F* = %g, c_psi = %.4f N m s/rad\n", p.V, p.Fstar,
           p.c_psi);

    double u[MLG_NX];
    int status = mlg_equilibrium(&p, -1.0, u);
    if (status != 0) {
        fprintf(stderr, "evaluate: no straight-rolling equilibrium (status %d)\n", status);
        return 1;
    }
    printf("straight rolling u*:\n");
    for (int i = 0; i < MLG_NX; i++) printf("  %-10s = % .10e\n", mlg_state_name(i), u[i]);

    double f[MLG_NX], J[MLG_NX * MLG_NX];
    status = mlg_rhs_jacobian(&p, u, f, J, NULL);
    if (status != MLG_OK) {
        fprintf(stderr, "evaluate: %s\n", mlg_status_text(status));
        return 1;
    }
    double fmax = 0.0;
    for (int i = 0; i < MLG_NX; i++) fmax = fmax > fabs(f[i]) ? fmax : fabs(f[i]);
    printf("max |f(u*)| = %.3e\n", fmax);

    /* column-major: J[i + MLG_NX * j] = df_i/du_j */
    printf("Jacobian df_i/du_j at u* (row i = d/dt of):\n  %-10s", "");
    for (int j = 0; j < MLG_NX; j++) printf(" %11s", mlg_state_name(j));
    printf("\n");
    for (int i = 0; i < MLG_NX; i++) {
        printf("  %-10s", mlg_state_name(i));
        for (int j = 0; j < MLG_NX; j++) printf(" % 11.4e", J[i + MLG_NX * j]);
        printf("\n");
    }

    /* Central differences, column by column, relative to the column's largest
     * entry.  At eta_dot = 0 the difference is only first order in the step:
     * the oleo damper's sign(eta') eta'^2 has no second derivative there. */
    printf("Jacobian against central differences (step 1e-6 (1 + |u_j|)), "
           "relative to each column's largest entry:\n");
    for (int j = 0; j < MLG_NX; j++) {
        double h = 1e-6 * (1.0 + fabs(u[j])), up[MLG_NX], um[MLG_NX], fp[MLG_NX], fm[MLG_NX];
        for (int k = 0; k < MLG_NX; k++) up[k] = um[k] = u[k];
        up[j] += h;
        um[j] -= h;
        if (mlg_rhs(&p, up, fp) != MLG_OK || mlg_rhs(&p, um, fm) != MLG_OK) {
            fprintf(stderr, "evaluate: a difference step left the model's domain\n");
            return 1;
        }
        double size = 0.0, diff = 0.0;
        for (int i = 0; i < MLG_NX; i++) {
            double d = (fp[i] - fm[i]) / (2.0 * h), exact = J[i + MLG_NX * j];
            size = size > fabs(exact) ? size : fabs(exact);
            diff = diff > fabs(exact - d) ? diff : fabs(exact - d);
        }
        printf("  %-10s %.1e%s\n", mlg_state_name(j), size > 0.0 ? diff / size : diff,
               j == MLG_ETA_DOT ? "  (first order here: the damper's sign(eta') eta'^2)" : "");
    }
    return 0;
}
