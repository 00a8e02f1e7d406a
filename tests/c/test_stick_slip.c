/* Coulomb's stick-slip on the twist (friction_law 1, docs/model.md 10): the
 * field in each mode, the holding moment of the stick, the switching
 * functions (values and exact gradients against central differences), the
 * modes by state against the field by state, and the refusals. */
#include <string.h>

#include "mlg_model.h"
#include "unit.h"

/* psi_s = psi + beta sin p with eom_terms >= 1, psi as printed */
static double twist_of(const mlg_params *p, const double r[2], double sin_p)
{
    return p->eom_terms >= MLG_EOM_SIDESTAY ? r[0] + r[1] * sin_p : r[0];
}

int main(void)
{
    double worst_grad = 0.0, worst_slip = 0.0, worst_accel = 0.0, worst_held = 0.0;
    int drawn = 0, same = 0, at_rest = 0, stuck = 0, released = 0;
    for (int n = 0; n < 300; n++) {
        mlg_params p = mlg_params_figures();
        p.V = unit_between(2.0, 60.0);
        p.yfp = unit_between(0.0, 2.0);
        p.rho = n % 3 ? unit_between(-0.3, 0.3) : 0.0;
        p.mu = n % 3 ? unit_between(-0.3, 0.3) : 0.0;
        p.eom_terms = n % 3;
        p.friction_law = 1.0;
        p.M_fric = pow(10.0, unit_between(0.0, 3.5));
        double u[MLG_NX];
        if (mlg_equilibrium(&p, -1.0, u) != MLG_OK) continue;
        u[MLG_PSI] += unit_between(-3e-3, 3e-3);
        u[MLG_DELTA] += unit_between(-3e-3, 3e-3);
        u[MLG_DELTA_DOT] = unit_between(-0.05, 0.05);
        u[MLG_BETA_DOT] = unit_between(-0.01, 0.01);
        u[MLG_PSI_DOT] = unit_between(-0.05, 0.05);
        mlg_diagnostics d;
        if (mlg_diagnose(&p, u, &d) != MLG_OK) continue;
        double sin_p = sin(d.p);
        if (n % 2 == 0)   /* at rest relative to the strut: the stick decides */
            u[MLG_PSI_DOT] = p.eom_terms >= MLG_EOM_SIDESTAY ? -u[MLG_BETA_DOT] * sin_p : 0.0;
        double h[MLG_NSWITCH], dh[MLG_NSWITCH * MLG_NX];
        if (mlg_switching(&p, NULL, u, h, dh) != MLG_OK) continue;
        drawn++;

        /* the values: the slip speed, and psi_s'' of the field sliding up and down */
        int up[MLG_NDISCRETE] = {MLG_MODE_BY_STATE, MLG_MODE_SLIP_POS};
        int down[MLG_NDISCRETE] = {MLG_MODE_BY_STATE, MLG_MODE_SLIP_NEG};
        int hold[MLG_NDISCRETE] = {MLG_MODE_BY_STATE, MLG_MODE_STICK};
        double fu[MLG_NX], fd[MLG_NX], fs[MLG_NX];
        mlg_rhs_in_modes(&p, up, u, fu);
        mlg_rhs_in_modes(&p, down, u, fd);
        mlg_rhs_in_modes(&p, hold, u, fs);
        double rate[2] = {u[MLG_PSI_DOT], u[MLG_BETA_DOT]};
        double acc_up[2] = {fu[MLG_PSI_DOT], fu[MLG_BETA_DOT]};
        double acc_down[2] = {fd[MLG_PSI_DOT], fd[MLG_BETA_DOT]};
        double acc_held[2] = {fs[MLG_PSI_DOT], fs[MLG_BETA_DOT]};
        double size = fmax(fabs(twist_of(&p, acc_up, sin_p)), fabs(twist_of(&p, acc_down, sin_p)));
        worst_slip = fmax(worst_slip, fabs(h[MLG_SWITCH_slip_pos] -
                                           p.r_seal * twist_of(&p, rate, sin_p)));
        worst_accel = fmax(worst_accel, fabs(h[MLG_SWITCH_stick_pos] -
                                             twist_of(&p, acc_up, sin_p)) / size);
        worst_accel = fmax(worst_accel, fabs(h[MLG_SWITCH_stick_neg] -
                                             twist_of(&p, acc_down, sin_p)) / size);
        /* stuck, the twist's acceleration vanishes */
        worst_held = fmax(worst_held, fabs(twist_of(&p, acc_held, sin_p)) / size);

        /* by state, the field is the field in the mode the state lies in; at
         * rest that is the stick exactly when the sliding accelerations
         * straddle zero (|holding moment| <= M_fric) */
        int modes[MLG_NDISCRETE];
        double f[MLG_NX], g[MLG_NX];
        mlg_modes_at(&p, u, modes);
        modes[MLG_DISCRETE_FREEPLAY] = MLG_MODE_BY_STATE;   /* eq. (15): no modes */
        mlg_rhs(&p, u, f);
        mlg_rhs_in_modes(&p, modes, u, g);
        same += memcmp(f, g, sizeof f) == 0;
        if (n % 2 == 0 && h[MLG_SWITCH_slip_pos] == 0.0) {
            at_rest++;
            int holds = h[MLG_SWITCH_stick_pos] <= 0.0 && h[MLG_SWITCH_stick_neg] >= 0.0;
            int want = holds ? MLG_MODE_STICK
                     : h[MLG_SWITCH_stick_pos] > 0.0 ? MLG_MODE_SLIP_POS : MLG_MODE_SLIP_NEG;
            stuck += holds && modes[MLG_DISCRETE_FRICTION] == want;
            released += !holds && modes[MLG_DISCRETE_FRICTION] == want;
        }

        /* exact gradients: relative to each function's largest component */
        for (int k = MLG_SWITCH_slip_pos; k <= MLG_SWITCH_stick_neg; k++) {
            double largest = 0.0, err = 0.0;
            for (int j = 0; j < MLG_NX; j++) largest = fmax(largest, fabs(dh[k * MLG_NX + j]));
            for (int j = 0; j < MLG_NX; j++) {
                double step = j == MLG_ETA ? 1e-7 : 1e-8, v[MLG_NX];
                double hp[MLG_NSWITCH], hm[MLG_NSWITCH];
                memcpy(v, u, sizeof v);
                v[j] = u[j] + step;
                mlg_switching(&p, NULL, v, hp, NULL);
                v[j] = u[j] - step;
                mlg_switching(&p, NULL, v, hm, NULL);
                err = fmax(err, fabs(dh[k * MLG_NX + j] - (hp[k] - hm[k]) / (2.0 * step)));
            }
            worst_grad = fmax(worst_grad, err / largest);
        }
    }
    check(drawn >= 250, "stick_slip_states_drawn", "%d of 300", drawn);
    check(worst_slip <= 1e-15, "slip_functions_are_the_slip_speed",
          "max |h - r_seal psi_s'| = %.2e m/s", worst_slip);
    check(worst_accel <= 1e-14, "stick_functions_are_the_sliding_accelerations",
          "max |h - psi_s''| relative %.2e", worst_accel);
    check(worst_held <= 1e-12, "stick_holds_the_twist",
          "max |psi_s''| in the stick, relative to sliding, %.2e", worst_held);
    check(same == drawn, "field_by_state_is_field_in_its_mode", "%d of %d bitwise equal", same,
          drawn);
    check(at_rest >= 120 && stuck >= 20 && released >= 20 && stuck + released == at_rest,
          "at_rest_stick_within_M_fric",
          "%d states at rest: %d stuck, %d released, as the sliding accelerations say", at_rest,
          stuck, released);
    check(worst_grad <= 1e-6, "stick_slip_gradients_match_differences",
          "max |exact - fd| / max |exact| = %.2e", worst_grad);

    /* the table: each function watched where it can end the mode */
    check(mlg_switching_watched(MLG_SWITCH_slip_pos, MLG_MODE_SLIP_POS) &&
          !mlg_switching_watched(MLG_SWITCH_slip_pos, MLG_MODE_STICK) &&
          mlg_switching_watched(MLG_SWITCH_stick_pos, MLG_MODE_STICK) &&
          !mlg_switching_watched(MLG_SWITCH_stick_pos, MLG_MODE_SLIP_POS) &&
          mlg_switching_mode_after(MLG_SWITCH_slip_pos, -1) == MLG_MODE_STICK &&
          mlg_switching_mode_after(MLG_SWITCH_slip_neg, 1) == MLG_MODE_STICK &&
          mlg_switching_mode_after(MLG_SWITCH_stick_pos, 1) == MLG_MODE_SLIP_POS &&
          mlg_switching_mode_after(MLG_SWITCH_stick_neg, -1) == MLG_MODE_SLIP_NEG,
          "stick_slip_transitions", "slip -> stick at zero slip, stick -> slip past M_fric");

    /* the equilibrium is the regularised law's (at rest stick holds a band) */
    mlg_params p = mlg_params_figures(), q;
    p.V = 10.0, p.yfp = 1.0, p.M_fric = 5.0;
    q = p;
    q.friction_law = 1.0;
    double u0[MLG_NX], u1[MLG_NX];
    int s0 = mlg_equilibrium(&p, -1.0, u0), s1 = mlg_equilibrium(&q, -1.0, u1);
    check(s0 == MLG_OK && s1 == MLG_OK && memcmp(u0, u1, sizeof u0) == 0,
          "equilibrium_of_either_law", "status %d, %d, states %s", s0, s1,
          memcmp(u0, u1, sizeof u0) == 0 ? "bitwise equal" : "differ");
    check(mlg_switching_applies(&q, MLG_SWITCH_stick_pos) &&
          !mlg_switching_applies(&p, MLG_SWITCH_stick_pos), "switching_only_with_coulomb",
          "friction_law 1 with M_fric > 0");

    /* refusals, naming the parameter */
    char msg[256];
    mlg_params bad = q;
    bad.friction_law = 2.0;
    check(mlg_params_check(&bad, msg, sizeof msg) && strstr(msg, "friction_law = 2") != NULL,
          "friction_law_is_0_or_1", "%s", msg);
    bad = q;
    bad.F_fric = 100.0;
    check(mlg_params_check(&bad, msg, sizeof msg) && strstr(msg, "F_fric") != NULL,
          "coulomb_is_for_the_twist_only", "%s", msg);
    int stick[MLG_NDISCRETE] = {MLG_MODE_BY_STATE, MLG_MODE_STICK};
    double f[MLG_NX];
    check(mlg_rhs_in_modes(&p, stick, u0, f) == MLG_BAD_PARAMETER, "stick_needs_coulomb",
          "a friction mode under the tanh law: status %d", mlg_rhs_in_modes(&p, stick, u0, f));
    return unit_exit();
}
