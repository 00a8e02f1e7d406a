/* The switching functions h+- = r_tlk(eta) psi_s -+ y_fp of law (14):
 * exact gradients against central differences at states with side-stay
 * angles (psi_s = psi + beta sin p) over the stroke; the modes they define
 * against the vector field by state; the table's transitions. */
#include <string.h>

#include "mlg_model.h"
#include "unit.h"

int main(void)
{
    double worst = 0.0, worst_h = 0.0;
    int same = 0, drawn = 0, agree_modes = 0, inside_domain = 0;
    for (int n = 0; n < 600; n++) {
        mlg_params p = mlg_params_figures();
        p.yfp = unit_between(0.05, 2.0);
        p.rho = n % 3 ? unit_between(-0.3, 0.3) : 0.0;
        p.mu = n % 3 ? unit_between(-0.3, 0.3) : 0.0;
        p.freeplay_law = mlg_freeplay_law_index("nonsmooth");
        double u[MLG_NX];
        for (int i = 0; i < MLG_NX; i++) u[i] = unit_between(-0.01, 0.01);
        u[MLG_ETA] = unit_between(0.05, 0.55);
        double r = mlg_r_tlk(&p, u[MLG_ETA]);
        u[MLG_PSI] = unit_between(-2.0, 2.0) * 1e-3 * p.yfp / r;
        double h[MLG_NSWITCH], dh[MLG_NSWITCH * MLG_NX];
        if (mlg_switching(&p, NULL, u, h, dh) != MLG_OK) continue;
        drawn++;
        /* the value: y_tlk -+ y_fp, y_tlk from the diagnostics (p: the side-stay angle) */
        mlg_diagnostics d;
        if (mlg_diagnose(&p, u, &d) == MLG_OK) {
            double y = d.r_tlk * (u[MLG_PSI] + u[MLG_BETA] * sin(d.p));
            worst_h = fmax(worst_h, fabs(h[MLG_SWITCH_freeplay_upper] - (y - 1e-3 * p.yfp)) / 1e-3);
            worst_h = fmax(worst_h, fabs(h[MLG_SWITCH_freeplay_lower] - (y + 1e-3 * p.yfp)) / 1e-3);
            /* the vector field in the mode of the state is the field by state */
            int modes[MLG_NDISCRETE];
            double f[MLG_NX], g[MLG_NX];
            mlg_modes_at(&p, u, modes);
            mlg_rhs(&p, u, f);
            mlg_rhs_in_modes(&p, modes, u, g);
            same += memcmp(f, g, sizeof f) == 0;
            inside_domain++;
            agree_modes += (modes[MLG_DISCRETE_FREEPLAY] == MLG_MODE_GAP) ==
                           (fabs(y) < 1e-3 * p.yfp);
        }
        for (int j = 0; j < MLG_NX; j++) {
            double step = j == MLG_ETA ? 1e-6 : 1e-7, hp[MLG_NSWITCH], hm[MLG_NSWITCH];
            double v[MLG_NX];
            memcpy(v, u, sizeof v);
            v[j] = u[j] + step;
            mlg_switching(&p, NULL, v, hp, NULL);
            v[j] = u[j] - step;
            mlg_switching(&p, NULL, v, hm, NULL);
            for (int k = 0; k < MLG_NSWITCH; k++) {
                double fd = (hp[k] - hm[k]) / (2.0 * step);
                worst = fmax(worst, fabs(dh[k * MLG_NX + j] - fd) * 1e-3);  /* per mrad, mm */
            }
        }
    }
    check(drawn >= 500 && worst <= 1e-9, "switching_gradients_match_differences",
          "%d states, max |exact - fd| = %.2e m per 1e-3 of a state", drawn, worst);
    check(worst_h <= 1e-12, "switching_values_are_y_tlk_minus_plus_yfp",
          "max error %.2e mm", worst_h);
    check(inside_domain >= 400 && same == inside_domain, "field_in_mode_of_state_is_field",
          "%d of %d states bitwise equal", same, inside_domain);
    check(agree_modes == inside_domain, "modes_at_match_the_gap", "%d of %d", agree_modes,
          inside_domain);

    /* transitions: up through h+ into contact+, down through h- into contact- */
    check(mlg_switching_mode_after(MLG_SWITCH_freeplay_upper, 1) == MLG_MODE_CONTACT_POS &&
          mlg_switching_mode_after(MLG_SWITCH_freeplay_upper, -1) == MLG_MODE_GAP &&
          mlg_switching_mode_after(MLG_SWITCH_freeplay_lower, -1) == MLG_MODE_CONTACT_NEG &&
          mlg_switching_mode_after(MLG_SWITCH_freeplay_lower, 1) == MLG_MODE_GAP,
          "switching_transitions", "h+ up: contact+, h- down: contact-, back: gap");
    /* a mode only with its law; switching only where it is part of the model */
    mlg_params p = mlg_params_figures();
    p.yfp = 1.0;
    double u[MLG_NX], f[MLG_NX];
    mlg_equilibrium(&p, -1.0, u);
    int gap[MLG_NDISCRETE] = {MLG_MODE_GAP, MLG_MODE_BY_STATE};
    check(mlg_rhs_in_modes(&p, gap, u, f) == MLG_BAD_PARAMETER && !mlg_switching_applies(&p, 0),
          "mode_needs_law_14", "atan law with a mode: status %d", mlg_rhs_in_modes(&p, gap, u, f));
    p.freeplay_law = mlg_freeplay_law_index("nonsmooth");
    check(mlg_rhs_in_modes(&p, gap, u, f) == MLG_OK && mlg_switching_applies(&p, 0) &&
          mlg_switching_applies(&p, 1), "law_14_switches", "law (14) with y_fp = 1 mm");
    p.yfp = 0.0;
    check(!mlg_switching_applies(&p, 0), "no_switching_without_freeplay", "y_fp = 0");
    return unit_exit();
}
