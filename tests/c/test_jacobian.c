/* The analytic (forward-mode) Jacobians df/du and df/dp against central
 * finite differences of the plain-double vector field (jacobian_error.h:
 * row-scaled error, tolerance 1e-6) over the samples of state_samples.h.
 * Every freeplay law is drawn in turn; with law (14), each mode of the
 * freeplay too (mlg_rhs_jacobian_in_modes), a fixed mode also exactly on its
 * switching surface, where that mode's field is smooth; so is each mode of
 * the twist's Coulomb friction (stick: the holding moment's derivatives). */
#include <string.h>

#include "jacobian_error.h"
#include "jacobian_variants.h"
#include "unit.h"

#define NSAMPLES 1200

int main(void)
{
    double worst_u = 0.0, worst_p = 0.0, worst_level[3] = {0.0, 0.0, 0.0};
    int outside_domain = 0, counted = 0, per_region[4] = {0, 0, 0, 0}, angled[3] = {0, 0, 0};
    enum { LAWS = 16, MODES = 4 };    /* at most; checked below */
    double worst_law[LAWS] = {0.0}, worst_mode[MODES] = {0.0};
    int per_law[LAWS] = {0}, per_mode[MODES] = {0};
    check(mlg_freeplay_law_count() <= LAWS, "law_table_fits", "%d laws", mlg_freeplay_law_count());
    double worst_coulomb[MODES] = {0.0};
    int per_coulomb[MODES] = {0};
    int variants_compared = 0, variants_differ = 0, stick = 0;
    double worst_stick = 0.0;
    const char *worst_where = "";
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
        int coulomb = s.p.friction_law == 1.0, friction = s.modes[MLG_DISCRETE_FRICTION] + 1;
        if (coulomb) per_coulomb[friction]++;

        double err_u, err_p;
        jacobian_error(&s, &err_u, &err_p);
        double err = fmax(err_u, err_p);
        if (s.p.rho != 0.0) worst_level[level] = fmax(worst_level[level], err);
        worst_law[law] = fmax(worst_law[law], err);
        if (law == mlg_freeplay_law_index("nonsmooth"))
            worst_mode[mode] = fmax(worst_mode[mode], err);
        if (s.stick) worst_stick = fmax(worst_stick, err);
        if (coulomb) worst_coulomb[friction] = fmax(worst_coulomb[friction], err);
        if (err_u > worst_u) {
            worst_u = err_u;
            worst_where = s.region;
        }
        worst_p = fmax(worst_p, err_p);
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
    static const char *const friction_names[MODES] = {"by_state", "stick", "slip_pos",
                                                      "slip_neg"};
    for (int mode = 0; mode < MODES; mode++) {
        char name[64];
        snprintf(name, sizeof name, "jacobian_coulomb_friction_mode_%s", friction_names[mode]);
        check(per_coulomb[mode] >= 25 && worst_coulomb[mode] <= 1e-6, name,
              "%d samples of Coulomb's law on the twist, max row-scaled error %.2e",
              per_coulomb[mode], worst_coulomb[mode]);
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
