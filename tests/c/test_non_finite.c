/* Nothing non-finite passes as "ok": a NaN or infinite state, parameter or
 * result gives a non-zero status from every evaluation (and f of zeros), a
 * switch is checked before the model casts it, and a constants file with
 * "nan" or "inf" is refused. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mlg_model.h"
#include "unit.h"

static int all_finite(const double *x, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

/* every evaluation at (p, u): each must give a non-zero status and no NaN in f */
static void check_refused(const char *name, const mlg_params *p, const double u[MLG_NX])
{
    double f[MLG_NX], J[MLG_NX * MLG_NX], P[MLG_NX * MLG_NPAR];
    mlg_diagnostics d;
    mlg_energy_parts e;
    char what[96];
    int st = mlg_rhs(p, u, f);
    snprintf(what, sizeof what, "%s_rhs", name);
    check(st != MLG_OK && all_finite(f, MLG_NX), what, "status %d (%s)", st, mlg_status_text(st));
    st = mlg_rhs_jacobian(p, u, f, J, P);
    snprintf(what, sizeof what, "%s_jacobian", name);
    check(st != MLG_OK && all_finite(f, MLG_NX), what, "status %d (%s)", st, mlg_status_text(st));
    st = mlg_diagnose(p, u, &d);
    snprintf(what, sizeof what, "%s_diagnose", name);
    check(st != MLG_OK, what, "status %d (%s)", st, mlg_status_text(st));
    st = mlg_energy(p, u, u[MLG_ETA] > 0.0 && u[MLG_ETA] < 0.6 ? u[MLG_ETA] : 0.3, &e);
    snprintf(what, sizeof what, "%s_energy", name);
    check(st != MLG_OK, what, "status %d (%s)", st, mlg_status_text(st));
}

static int read_one(const char *line, char *msg, size_t n)
{
    const char *path = "test_non_finite.constants";
    FILE *out = fopen(path, "w");
    if (out == NULL) return -1;
    fputs(line, out);
    fclose(out);
    mlg_params q = mlg_params_table();
    int bad = mlg_params_read_constants(&q, path, msg, n);
    remove(path);
    return bad;
}

int main(void)
{
    const mlg_params base = mlg_params_figures();
    double u0[MLG_NX], u[MLG_NX], f[MLG_NX];
    mlg_params p = base;
    p.V = 100.0;
    int st = mlg_equilibrium(&p, -1.0, u0);
    check(st == MLG_OK && mlg_rhs(&p, u0, f) == MLG_OK, "equilibrium_ok", "status %d", st);
    const mlg_params good = p;

    /* a non-finite state component */
    const double bad_values[] = {NAN, INFINITY, -INFINITY};
    for (int i = 0; i < MLG_NX; i++)
        for (int k = 0; k < 3; k++) {
            memcpy(u, u0, sizeof u);
            u[i] = bad_values[k];
            char name[64];
            snprintf(name, sizeof name, "state_%s_%g", mlg_state_name(i), bad_values[k]);
            check_refused(name, &good, u);
        }

    /* a non-finite parameter, a switch not one of its values (cast to int) */
    const char *names[] = {"V", "Fstar", "k_tlk", "I_psi", "z_tlk0", "k_beta", "eta_stage",
                           "eom_terms", "strut_variant", "tyre_forces"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        for (int k = 0; k < 3; k++) {
            p = good;
            *mlg_param_ref(&p, names[i]) = bad_values[k];
            char name[64];
            snprintf(name, sizeof name, "parameter_%s_%g", names[i], bad_values[k]);
            check_refused(name, &p, u0);
        }
    const double switch_values[] = {1e300, -1e300, 3.0, 0.5, 2147483648.0};
    for (int k = 0; k < 5; k++) {
        p = good;
        p.eom_terms = switch_values[k];
        char name[64];
        snprintf(name, sizeof name, "eom_terms_%g", switch_values[k]);
        check_refused(name, &p, u0);
        p = good;
        p.strut_variant = switch_values[k];
        snprintf(name, sizeof name, "strut_variant_%g", switch_values[k]);
        check_refused(name, &p, u0);
    }

    /* finite inputs whose result overflows */
    p = good;
    p.I_psi = 1e-320;
    memcpy(u, u0, sizeof u);
    u[MLG_PSI] = 0.01;
    st = mlg_rhs(&p, u, f);
    check(st == MLG_NOT_FINITE && all_finite(f, MLG_NX), "overflowing_result_rhs",
          "status %d (%s)", st, mlg_status_text(st));
    double J[MLG_NX * MLG_NX];
    st = mlg_rhs_jacobian(&p, u, f, J, NULL);
    check(st == MLG_NOT_FINITE && all_finite(f, MLG_NX), "overflowing_result_jacobian",
          "status %d (%s)", st, mlg_status_text(st));

    /* the equilibrium's inputs */
    p = good;
    p.Fstar = NAN;
    st = mlg_equilibrium(&p, -1.0, u);
    check(st != MLG_OK, "equilibrium_nan_Fstar", "status %d", st);
    p = good;
    p.eom_terms = NAN;
    st = mlg_equilibrium(&p, -1.0, u);
    check(st != MLG_OK, "equilibrium_nan_eom_terms", "status %d", st);
    st = mlg_equilibrium(&good, NAN, u);
    check(st != MLG_OK, "equilibrium_nan_eta_guess", "status %d", st);
    st = mlg_equilibrium(&good, INFINITY, u);
    check(st != MLG_OK, "equilibrium_infinite_eta_guess", "status %d", st);

    /* mlg_energy: eta_ref */
    mlg_energy_parts e;
    st = mlg_energy(&good, u0, NAN, &e);
    check(st != MLG_OK, "energy_nan_eta_ref", "status %d", st);
    /* a stroke whose panel count (of the strut's potential) is no int: the
     * spring force overflows there */
    p = good;
    p.z_tlk0 = 1e300;
    memcpy(u, u0, sizeof u);
    u[MLG_ETA] = 1e299;
    st = mlg_energy(&p, u, u0[MLG_ETA], &e);
    check(st == MLG_NOT_FINITE, "energy_beyond_int_panels", "status %d (%s)", st,
          mlg_status_text(st));

    /* a constants file */
    const char *refused[] = {"k_relax nan\n", "k_relax NAN\n", "I_psi inf\n", "I_psi -inf\n",
                             "I_psi infinity\n", "I_psi 1e999\n", "eom_terms nan\n"};
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
        char msg[256] = "";
        int bad = read_one(refused[i], msg, sizeof msg);
        check(bad == 1 && strstr(msg, "line 1") != NULL && strstr(msg, "not finite") != NULL,
              "constants_file_refuses_non_finite", "%.*s: %s", (int)strcspn(refused[i], "\n"),
              refused[i], msg);
    }
    char msg[256] = "";
    check(read_one("I_psi 151\n", msg, sizeof msg) == 0, "constants_file_finite_read", "%s", msg);
    return unit_exit();
}
