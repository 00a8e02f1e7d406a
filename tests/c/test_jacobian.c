/* The analytic (forward-mode) Jacobians df/du and df/dp against central
 * finite differences of the plain-double vector field.
 *
 * Error measure: row-scaled maximum norm.  With s_j the scale of variable j
 * (the finite-difference step is 1e-4 s_j), the scaled entry is
 * J_ij s_j / max_k |J_ik s_k|, and the error of a sample is the largest
 * difference of scaled entries between analytic and finite-difference
 * Jacobians.  The difference quotient is Richardson-extrapolated from steps
 * h and h/2 (truncation error O(h^4)).  Tolerance 1e-6.
 * Every freeplay law is drawn in turn; with law (14), each mode of the
 * freeplay too (mlg_rhs_jacobian_in_modes), a fixed mode also exactly on its
 * switching surface, where that mode's field is smooth. */
#include <string.h>

#include "jacobian_variants.h"
#include "unit.h"

#define NSAMPLES 1200

typedef struct {
    mlg_params p;
    double u[MLG_NX];
    const char *region;   /* inside / edge / outside the freeplay, or "zero" */
    int modes[MLG_NDISCRETE];
    int stick;            /* seal friction on, every rate near stick */
} sample;

/* Central difference of f in direction j (state j, or parameter j - MLG_NX). */
static void difference(const sample *s, int j, double h, double *df)
{
    double fp[MLG_NX], fm[MLG_NX];
    for (int sign = -1; sign <= 1; sign += 2) {
        sample t = *s;
        if (j < MLG_NX) {
            t.u[j] += sign * h;
        } else {
            double par[MLG_PAR_SLOTS];
            mlg_params_get_par(&t.p, par);
            par[j - MLG_NX] += sign * h;
            mlg_params_set_par(&t.p, par);
        }
        mlg_rhs_in_modes(&t.p, t.modes, t.u, sign > 0 ? fp : fm);
    }
    for (int i = 0; i < MLG_NX; i++) df[i] = (fp[i] - fm[i]) / (2.0 * h);
}

static void richardson(const sample *s, int j, double h, double *df)
{
    double d1[MLG_NX], d2[MLG_NX];
    difference(s, j, h, d1);
    difference(s, j, 0.5 * h, d2);
    for (int i = 0; i < MLG_NX; i++) df[i] = (4.0 * d2[i] - d1[i]) / 3.0;
}

static sample draw(int n)
{
    static const double freeplays[4] = {0.0, 0.05, 1.0, 2.0};   /* mm */
    static const char *regions[3] = {"inside", "edge", "outside"};
    sample s;
    s.p = mlg_params_table();
    s.p.Fstar = unit_between(0.05, 3.5);
    s.p.V = n % 10 == 0 ? 0.0 : unit_between(0.0, 600.0);
    s.p.yfp = freeplays[n % 4];
    double ratio = pow(10.0, unit_between(-1.0, 1.0));       /* y_fp / epsilon in [0.1, 10] */
    double eps_mm = s.p.yfp > 0.0 ? s.p.yfp / ratio : unit_between(0.01, 0.2);
    double share = unit_uniform();                         /* split into abs and rel parts */
    s.p.eps_abs = share * eps_mm;
    s.p.eps_rel = s.p.yfp > 0.0 ? (1.0 - share) * eps_mm / s.p.yfp : unit_between(0.0, 0.2);
    s.p.c_psi = unit_between(410.0, 730.0);
    if (n % 3 != 0) {
        s.p.rho = unit_between(-0.3, 0.3);
        s.p.mu = unit_between(-0.3, 0.3);
    }
    s.p.strut_variant = (n / 7) % 2;
    s.p.eom_terms = (n / 3) % 3;              /* every level with and without side-stay angles */
    s.p.tyre_forces = n % 13 == 5 ? 0.0 : 1.0;
    s.p.freeplay_law = (n / 11) % mlg_freeplay_law_count();
    int nonsmooth = s.p.freeplay_law == mlg_freeplay_law_index("nonsmooth");
    s.modes[MLG_DISCRETE_FREEPLAY] = nonsmooth ? (n / 2) % 4 - 1 : MLG_MODE_BY_STATE;
    mlg_equilibrium(&s.p, -1.0, s.u);

    /* place the torque-link deflection inside, at the edge of, or outside the freeplay */
    double r = mlg_r_tlk(&s.p, s.u[MLG_ETA]), yfp = 1e-3 * s.p.yfp, eps = mlg_epsilon_m(&s.p);
    int region = (n / 4) % 3;
    double y;
    if (s.p.yfp == 0.0) {
        y = unit_between(-2e-3, 2e-3);
        s.region = "zero";
    } else {
        double side = unit_uniform() < 0.5 ? -1.0 : 1.0;
        if (region == 0) y = unit_between(-0.9, 0.9) * yfp;
        else if (region == 1 && s.modes[MLG_DISCRETE_FREEPLAY] != MLG_MODE_BY_STATE && n % 3 == 0)
            y = side * yfp;                          /* on the switching surface */
        else if (region == 1) y = side * (yfp + unit_between(-2.0, 2.0) * eps);
        else y = side * (yfp + eps * unit_between(3.0, 30.0));
        s.region = regions[region];
    }
    mlg_diagnostics d;
    mlg_diagnose(&s.p, s.u, &d);
    s.u[MLG_PSI] = y / r - s.u[MLG_BETA] * sin(d.p);
    s.u[MLG_DELTA] += unit_between(-0.01, 0.01);
    s.u[MLG_BETA] += unit_between(-0.005, 0.005);
    s.u[MLG_ETA] += unit_between(-1.0, 1.0) * fmin(0.02, 0.5 * s.u[MLG_ETA]);
    s.u[MLG_PSI_DOT] = unit_between(-1.0, 1.0);
    s.u[MLG_DELTA_DOT] = unit_between(-0.5, 0.5);
    s.u[MLG_BETA_DOT] = unit_between(-0.2, 0.2);
    s.u[MLG_ETA_DOT] = unit_between(-0.1, 0.1);
    s.u[MLG_LAMBDA_L] = unit_between(-0.02, 0.02);
    s.u[MLG_LAMBDA_R] = unit_between(-0.02, 0.02);

    /* seal friction in half the samples; in half of those every rate is within
     * 3 v_fric of stick, where tanh turns */
    s.stick = 0;
    if (n % 2 == 1) {
        s.p.M_fric = unit_between(0.0, 3000.0);
        s.p.F_fric = unit_between(0.0, 3e4);
        s.p.v_fric = pow(10.0, unit_between(-4.0, -2.0));
        if (n % 4 == 1) {
            double twist = s.p.v_fric / s.p.r_seal;
            s.u[MLG_PSI_DOT] = unit_between(-3.0, 3.0) * twist;
            s.u[MLG_BETA_DOT] = unit_between(-3.0, 3.0) * twist;
            s.u[MLG_ETA_DOT] = unit_between(-3.0, 3.0) * s.p.v_fric;
            s.stick = 1;
        }
    }
    return s;
}

/* Scale of each direction: states, then PAR(1..MLG_NPAR). */
static void scales(const sample *s, double *scale)
{
    double r = mlg_r_tlk(&s->p, s->u[MLG_ETA]);
    double eps = mlg_epsilon_m(&s->p);
    double torsion = s->p.yfp > 0.0 ? fmin(1e-3, eps / r) : 1e-3;   /* resolve the corners */
    const double base[MLG_NX] = {torsion, 1e-3, 1e-3, 1e-3, 1e-2, 1e-2, 1e-2, 1e-2, 1e-4, 1e-4};
    memcpy(scale, base, sizeof base);
    if (s->p.rho != 0.0 || s->p.mu != 0.0) scale[MLG_BETA] = fmin(scale[MLG_BETA], torsion);
    if (s->p.M_fric > 0.0 || s->p.F_fric > 0.0) {
        /* resolve the seal friction's tanh near stick: rates on the scale of v_fric */
        double twist_rate = s->p.v_fric / s->p.r_seal;
        scale[MLG_PSI_DOT] = fmin(scale[MLG_PSI_DOT], twist_rate);
        scale[MLG_BETA_DOT] = fmin(scale[MLG_BETA_DOT], twist_rate);
        scale[MLG_ETA_DOT] = fmin(scale[MLG_ETA_DOT], s->p.v_fric);
    }
    double *ps = scale + MLG_NX;
    for (int k = 0; k < MLG_NPAR; k++) ps[k] = NAN;   /* a parameter left out fails below */
    ps[MLG_PAR_V] = 1.0;
    ps[MLG_PAR_Fstar] = 1e-2;
    ps[MLG_PAR_yfp] = fmin(1e-2, 1e3 * eps);     /* mm */
    ps[MLG_PAR_eps_abs] = fmin(1e-2, 1e3 * eps);  /* mm */
    ps[MLG_PAR_eps_rel] = 1e-3;
    ps[MLG_PAR_c_psi] = 1.0;
    ps[MLG_PAR_rho] = torsion;
    ps[MLG_PAR_mu] = torsion;
    ps[MLG_PAR_k_tlk] = 1e4;
    ps[MLG_PAR_M_fric] = 1.0;
}

int main(void)
{
    double worst_u = 0.0, worst_p = 0.0, worst_level[3] = {0.0, 0.0, 0.0};
    int outside_domain = 0, counted = 0, per_region[4] = {0, 0, 0, 0}, angled[3] = {0, 0, 0};
    enum { LAWS = 16, MODES = 4 };    /* at most; checked below */
    double worst_law[LAWS] = {0.0}, worst_mode[MODES] = {0.0};
    int per_law[LAWS] = {0}, per_mode[MODES] = {0};
    check(mlg_freeplay_law_count() <= LAWS, "law_table_fits", "%d laws", mlg_freeplay_law_count());
    int variants_compared = 0, variants_differ = 0, stick = 0;
    double worst_stick = 0.0;
    const char *worst_where = "";
    {   /* every continuation parameter has a df/dp scale, so its column is checked */
        sample s = draw(0);
        double scale[MLG_NDIR];
        scales(&s, scale);
        for (int k = 0; k < MLG_NPAR; k++) {
            char name[80];
            snprintf(name, sizeof name, "dfdp_scale_of_%s", mlg_par_name(k));
            check(scale[MLG_NX + k] > 0.0, name, "scale %g (tests/c/test_jacobian.c scales())",
                  scale[MLG_NX + k]);
        }
    }
    for (int n = 0; n < NSAMPLES; n++) {
        sample s = draw(n);
        double f[MLG_NX], J[MLG_NX * MLG_NX], P[MLG_NX * MLG_NPAR], Jx[MLG_NX * MLG_NX];
        double f2[MLG_NX];
        /* a random perturbation at light load can lift a wheel: outside the
         * model's domain (the status is tested in test_parameters), skipped */
        if (mlg_rhs_jacobian_in_modes(&s.p, s.modes, s.u, f, J, P) != MLG_OK) {
            outside_domain++;
            continue;
        }
        /* the state-only Jacobian is the same computation with fewer directions */
        mlg_rhs_jacobian_in_modes(&s.p, s.modes, s.u, f2, Jx, NULL);
        if (memcmp(J, Jx, sizeof J) != 0 || memcmp(f, f2, sizeof f) != 0) worst_u = INFINITY;
#ifdef MLG_HAVE_AVX2_VARIANT
        if (__builtin_cpu_supports("avx2")) {   /* the two builds round alike */
            double fg[MLG_NX], Jg[MLG_NX * MLG_NX], Pg[MLG_NX * MLG_NPAR];
            double fa[MLG_NX], Ja[MLG_NX * MLG_NX], Pa[MLG_NX * MLG_NPAR];
            mlg_rhs_jacobian_generic(&s.p, s.modes, s.u, fg, Jg, Pg);
            mlg_rhs_jacobian_avx2(&s.p, s.modes, s.u, fa, Ja, Pa);
            variants_compared++;
            if (memcmp(fg, fa, sizeof fg) != 0 || memcmp(Jg, Ja, sizeof Jg) != 0 ||
                memcmp(Pg, Pa, sizeof Pg) != 0)
                variants_differ++;
        }
#endif
        counted++;
        int level = (int)s.p.eom_terms;
        if (s.p.rho != 0.0) angled[level]++;
        stick += s.stick;
        per_region[s.region[0] == 'i' ? 0 : s.region[0] == 'e' ? 1 : s.region[0] == 'o' ? 2 : 3]++;
        int law = (int)s.p.freeplay_law, mode = s.modes[MLG_DISCRETE_FREEPLAY] + 1;
        per_law[law]++;
        if (law == mlg_freeplay_law_index("nonsmooth")) per_mode[mode]++;

        double scale[MLG_NDIR], fd[MLG_NDIR][MLG_NX], row[MLG_NX];
        scales(&s, scale);
        for (int j = 0; j < MLG_NDIR; j++)
            if (scale[j] > 0.0) richardson(&s, j, 1e-4 * scale[j], fd[j]);
        for (int i = 0; i < MLG_NX; i++) {
            row[i] = 0.0;
            for (int j = 0; j < MLG_NDIR; j++) {
                double an = j < MLG_NX ? J[i + MLG_NX * j] : P[i + MLG_NX * (j - MLG_NX)];
                row[i] = fmax(row[i], fabs(an) * scale[j]);
            }
        }
        for (int i = 0; i < MLG_NX; i++) {
            if (row[i] == 0.0) continue;
            for (int j = 0; j < MLG_NDIR; j++) {
                if (scale[j] == 0.0) continue;
                double an = j < MLG_NX ? J[i + MLG_NX * j] : P[i + MLG_NX * (j - MLG_NX)];
                double err = fabs(an - fd[j][i]) * scale[j] / row[i];
                if (s.p.rho != 0.0) worst_level[level] = fmax(worst_level[level], err);
                worst_law[law] = fmax(worst_law[law], err);
                if (law == mlg_freeplay_law_index("nonsmooth"))
                    worst_mode[mode] = fmax(worst_mode[mode], err);
                if (s.stick) worst_stick = fmax(worst_stick, err);
                if (j < MLG_NX && err > worst_u) {
                    worst_u = err;
                    worst_where = s.region;
                }
                if (j >= MLG_NX && err > worst_p) worst_p = err;
            }
        }
    }
    printf("# %d samples: %d inside, %d at the edge of, %d outside the freeplay, %d zero "
           "freeplay; %d drawn outside the model's domain and skipped\n",
           counted, per_region[0], per_region[1], per_region[2], per_region[3], outside_domain);
    check(counted >= 1000, "at_least_1000_samples", "%d samples", counted);
    check(per_region[0] > 200 && per_region[1] > 200 && per_region[2] > 200,
          "all_freeplay_regions_sampled", "inside %d, edge %d, outside %d", per_region[0],
          per_region[1], per_region[2]);
    for (int level = 0; level < 3; level++) {
        char name[64];
        snprintf(name, sizeof name, "jacobian_at_side_stay_angles_eom_terms_%d", level);
        check(angled[level] > 200 && worst_level[level] <= 1e-6, name,
              "eom_terms %d: %d samples with rho, mu != 0, max row-scaled error %.2e (df/du "
              "and df/dp)", level, angled[level], worst_level[level]);
    }
    for (int law = 0; law < mlg_freeplay_law_count(); law++) {
        char name[64];
        snprintf(name, sizeof name, "jacobian_freeplay_law_%s", mlg_freeplay_law_name(law));
        check(per_law[law] >= 150 && worst_law[law] <= 1e-6, name,
              "%d samples, max row-scaled error %.2e (df/du and df/dp)", per_law[law],
              worst_law[law]);
    }
    static const char *const mode_names[MODES] = {"by_state", "gap", "contact_pos",
                                                  "contact_neg"};
    for (int mode = 0; mode < MODES; mode++) {
        char name[64];
        snprintf(name, sizeof name, "jacobian_eq14_mode_%s", mode_names[mode]);
        check(per_mode[mode] >= 40 && worst_mode[mode] <= 1e-6, name,
              "%d samples of law (14), max row-scaled error %.2e", per_mode[mode],
              worst_mode[mode]);
    }
    check(stick > 200 && worst_stick <= 1e-6, "jacobian_near_seal_friction_stick",
          "%d samples with every rate within 3 v_fric of stick, max row-scaled error %.2e (df/du "
          "and df/dp)", stick, worst_stick);
    check(worst_u <= 1e-6, "dfdu_matches_finite_differences",
          "max row-scaled error %.2e (worst sample: %s)", worst_u, worst_where);
    check(worst_p <= 1e-6, "dfdp_matches_finite_differences", "max row-scaled error %.2e",
          worst_p);
    if (variants_compared > 0)
        check(variants_differ == 0, "avx2_and_generic_jacobians_bitwise_equal",
              "%d of %d samples differ", variants_differ, variants_compared);
    else
        printf("# AVX2 build of the Jacobian not built or not supported here: not compared\n");
    return unit_exit();
}
