/* The states of the derivative tests (test_jacobian.c, test_forms.c): straight
 * rolling of random gears (loads, speeds, freeplays, smoothing widths, side-stay
 * angles, every eom_terms level) moved off it, with the torque-link deflection
 * inside, at the edge of (within 2 epsilon of a corner of eq. 15) or outside
 * the freeplay (on its switching surface for the modes of eq. 14), every
 * freeplay law, seal friction in half of them (near stick in a quarter,
 * Coulomb's law in its modes in an eighth), and the scale of each derivative
 * direction. */
#ifndef MLG_STATE_SAMPLES_H
#define MLG_STATE_SAMPLES_H

#include <string.h>

#include "mlg_model.h"
#include "unit.h"

typedef struct {
    mlg_params p;
    double u[MLG_NX];
    const char *region;   /* inside / edge / outside the freeplay, or "zero" */
    int modes[MLG_NDISCRETE];
    int stick;            /* seal friction on, every rate near stick */
} sample;

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
    s.modes[MLG_DISCRETE_FRICTION] = MLG_MODE_BY_STATE;
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
        if (n % 8 == 3) {   /* Coulomb's law on the twist, by state or in each mode */
            s.p.friction_law = 1.0;
            s.p.F_fric = 0.0;
            s.modes[MLG_DISCRETE_FRICTION] = (n / 8) % 4 - 1;
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
    /* a parameter's step: 1e-3 of its value here, at least 1e-3 of its unit
     * (a table value may be 0), so a new one needs no line; the widths of the
     * freeplay's corners and the angles instead resolve those corners */
    double par[MLG_PAR_SLOTS], *ps = scale + MLG_NX;
    mlg_params_get_par(&s->p, par);
    for (int k = 0; k < MLG_NPAR; k++) ps[k] = 1e-3 * fmax(fabs(par[k]), 1.0);
    ps[MLG_PAR_yfp] = fmin(1e-2, 1e3 * eps);     /* mm */
    ps[MLG_PAR_eps_abs] = fmin(1e-2, 1e3 * eps);  /* mm */
    ps[MLG_PAR_eps_rel] = 1e-3;
    ps[MLG_PAR_rho] = torsion;
    ps[MLG_PAR_mu] = torsion;
}

#endif
