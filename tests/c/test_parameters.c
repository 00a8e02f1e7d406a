/* Parameter validation, look-up by name, and the domain status of evaluations. */
#define _POSIX_C_SOURCE 200809L   /* mkstemp, fdopen */
#include <stdlib.h>
#include <string.h>

#include "mlg_model.h"
#include "unit.h"

static void expect_rejected(const char *name, mlg_params p, const char *needle)
{
    char msg[256];
    int bad = mlg_params_check(&p, msg, sizeof msg);
    check(bad && strstr(msg, needle) != NULL, name, "message \"%s\" (expected to contain \"%s\")",
          msg, needle);
}

int main(void)
{
    char msg[256];
    mlg_params table = mlg_params_table(), figures = mlg_params_figures();
    check(mlg_params_check(&table, msg, sizeof msg) == 0, "table_set_valid", "%s", msg);
    check(mlg_params_check(&figures, msg, sizeof msg) == 0, "figures_set_valid", "%s", msg);
    check(table.c_psi == 410.0 && figures.c_psi == MLG_C_PSI_FIGURES, "named_sets_c_psi",
          "table %.1f, figures %.3f", table.c_psi, figures.c_psi);

    mlg_params p = table;
    p.yfp = -0.5;
    expect_rejected("negative_freeplay", p, "parameter yfp = -0.5 mm");
    p = table;
    p.yfp = 1.0;
    p.eps_abs = 0.0;
    p.eps_rel = 0.0;
    expect_rejected("zero_smoothing_with_freeplay", p, "eps_abs/eps_rel");
    p = table;
    p.Fstar = -0.1;
    expect_rejected("negative_load", p, "parameter Fstar = -0.1");
    p = table;
    p.V = NAN;
    expect_rejected("nan_velocity", p, "parameter V is not finite");
    p = table;
    p.k_beta = INFINITY;
    expect_rejected("infinite_constant", p, "parameter k_beta is not finite");
    p = table;
    p.rho = 2.0;
    expect_rejected("rho_out_of_range", p, "parameter rho = 2");
    p = table;
    p.mu = -1.6;
    expect_rejected("mu_out_of_range", p, "parameter mu = -1.6");
    p = table;
    p.rho = 1.5;
    expect_rejected("degenerate_side_stay", p, "degenerate");
    p = table;
    p.strut_variant = 0.5;
    expect_rejected("strut_variant_not_a_switch", p, "parameter strut_variant = 0.5");
    p = table;
    p.freeplay_law = mlg_freeplay_law_count();
    expect_rejected("freeplay_law_unknown", p, "parameter freeplay_law = 5");
    p = table;
    p.freeplay_law = 1.5;
    expect_rejected("freeplay_law_not_an_index", p, "parameter freeplay_law = 1.5");
    p = table;
    p.yfp = 1.0;
    p.eps_rel = 0.0;
    expect_rejected("smoothed_law_needs_eps", p, "freeplay law atan needs epsilon > 0");
    p.freeplay_law = mlg_freeplay_law_index("nonsmooth");
    {
        char msg[256];
        check(mlg_params_check(&p, msg, sizeof msg) == 0, "law_14_needs_no_eps", "%s", msg);
    }
    p = table;
    p.eta_stage = -0.1;
    expect_rejected("eta_stage_outside_stroke", p, "parameter eta_stage = -0.1 m");
    p = table;
    p.eta_stage = 0.7;
    expect_rejected("eta_stage_beyond_stroke", p, "parameter eta_stage = 0.7 m");
    p = table;
    p.eom_terms = 3.0;
    expect_rejected("eom_terms_out_of_range", p, "parameter eom_terms = 3");
    p = table;
    p.tyre_forces = 0.5;
    expect_rejected("tyre_forces_not_a_switch", p, "parameter tyre_forces = 0.5");
    p = table;
    p.rho = 0.5;
    p.mu = -1.4;     /* sin p = sin(rho) cos(phi0) - cos(rho) sin(mu) sin(phi0) = 0.36: valid */
    check(mlg_params_check(&p, msg, sizeof msg) == 0, "large_valid_angles_accepted", "%s", msg);
    p.rho = 1.52;    /* side-stay axis almost along the strut: |sin p| = 0.991 */
    p.mu = 0.0;
    expect_rejected("side_stay_along_strut", p, "parameters rho = 1.52");
    p = table;
    p.c_psi = -1.0;
    expect_rejected("negative_damping", p, "parameter c_psi = -1");
    p = table;
    p.yfp = 0.0;
    p.eps_abs = 0.0;
    p.eps_rel = 0.0;
    check(mlg_params_check(&p, msg, sizeof msg) == 0, "zero_freeplay_zero_smoothing_valid",
          "%s", msg);

    /* names and PAR indices */
    check(mlg_par_index("V") == 0 && mlg_par_index("Fstar") == 1 && mlg_par_index("yfp") == 2,
          "par_indices", "V %d, Fstar %d, yfp %d", mlg_par_index("V"), mlg_par_index("Fstar"),
          mlg_par_index("yfp"));
    check(mlg_par_index("nonsense") == -1 && mlg_param_ref(&p, "nonsense") == NULL,
          "unknown_names", "unknown names give -1 / NULL");
    double *k = mlg_param_ref(&p, "k_tlk"), *ad = mlg_param_ref(&p, "a_d");
    check(k == &p.k_tlk && ad == &p.a_d && *ad == 4.221e-4, "param_ref_by_name",
          "k_tlk and a_d reachable by name");
    double par[MLG_PAR_SLOTS];
    p = table;
    p.c_psi = 555.0;
    mlg_params_get_par(&p, par);
    check(par[MLG_PAR_c_psi] == 555.0 && strcmp(mlg_par_name(MLG_PAR_c_psi), "c_psi") == 0,
          "par_round_trip", "PAR(%d) = %g", MLG_PAR_c_psi + 1, par[MLG_PAR_c_psi]);
    /* the switch eom_terms lives in PAR(13); PAR(11), PAR(12) (AUTO's) have no name */
    p.eom_terms = 2.0;
    par[10] = par[11] = -7.0;
    mlg_params_get_par(&p, par);
    mlg_params q = table;
    mlg_params_set_par(&q, par);
    check(mlg_par_index("eom_terms") == 12 && par[12] == 2.0 && q.eom_terms == 2.0 &&
          par[10] == -7.0 && mlg_par_name(10) == NULL && mlg_par_name(11) == NULL &&
          mlg_par_index("tyre_forces") == -1, "switch_par_slot",
          "eom_terms at index %d, PAR(13) = %g", mlg_par_index("eom_terms"), par[12]);
    /* PAR(1-10) hold continuation parameters only: the other switch is PAR(14) */
    check(mlg_par_index("strut_variant") == 13 && mlg_par_index("constants") == 14 &&
          MLG_NPAR <= 10 && mlg_par_name(MLG_NPAR) == NULL, "par_layout",
          "strut_variant at index %d, constants at %d, %d continuation parameters",
          mlg_par_index("strut_variant"), mlg_par_index("constants"), MLG_NPAR);
    /* a file of constant overrides: constants only, never a PAR slot */
    {
        char path[] = "/tmp/mlg_test_constants_XXXXXX";
        int fd = mkstemp(path);
        FILE *out = fd >= 0 ? fdopen(fd, "w") : NULL;
        if (out != NULL) {
            fputs("# comment\nk_relax 0.9   # relaxation\n\nI_psi 151\n", out);
            fclose(out);
        }
        q = table;
        int bad = mlg_params_read_constants(&q, path, msg, sizeof msg);
        check(!bad && q.k_relax == 0.9 && q.I_psi == 151.0, "constants_file_read", "%s", msg);
        out = fopen(path, "w");
        if (out != NULL) {
            fputs("k_relax 0.9\nyfp 1\n", out);
            fclose(out);
        }
        bad = mlg_params_read_constants(&q, path, msg, sizeof msg);
        check(bad && strstr(msg, "line 2: yfp is PAR(3)") != NULL, "constants_file_refuses_par",
              "%s", msg);
        remove(path);
    }

    /* states outside the model's domain give a status, never NaN */
    double u[MLG_NX], f[MLG_NX], J[MLG_NX * MLG_NX];
    p = table;
    mlg_equilibrium(&p, -1.0, u);
    u[MLG_ETA] = -0.01;
    int st = mlg_rhs(&p, u, f);
    int finite = 1;
    for (int i = 0; i < MLG_NX; i++) finite &= isfinite(f[i]);
    check(st == MLG_ETA_OUT_OF_STROKE && finite, "eta_nonpositive_flagged", "status %d (%s)", st,
          mlg_status_text(st));
    mlg_equilibrium(&p, -1.0, u);
    u[MLG_ETA_DOT] = -4.0;     /* the damper unloads the gear: F_dyn < 0 */
    st = mlg_rhs_jacobian(&p, u, f, J, NULL);
    check(st == MLG_WHEEL_LIFT_OFF, "wheel_lift_off_flagged", "status %d (%s)", st,
          mlg_status_text(st));
    mlg_equilibrium(&p, -1.0, u);
    u[MLG_PSI] = NAN;
    st = mlg_rhs(&p, u, f);
    check(st == MLG_NOT_FINITE, "nan_state_flagged", "status %d (%s)", st, mlg_status_text(st));
    return unit_exit();
}
