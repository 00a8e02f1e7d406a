/* The switching functions of the piecewise-smooth model (the table
 * MLG_SWITCHING_FUNCTIONS of mlg_model.h), with exact gradients: the
 * model of vector_field.h seeded on the states. */
#include "mlg_model.h"
#define DUAL_N 10    /* a literal for #if: MLG_NX */
#include "vector_field.h"

_Static_assert(DUAL_N == MLG_NX, "one derivative direction per state");

static const struct {
    const char *name;
    int variable, below, above, watched;
} table[MLG_NSWITCH] = {
#define X(name, variable, below, above, watched) {#name, variable, below, above, watched},
    MLG_SWITCHING_FUNCTIONS(X)
#undef X
};

const char *mlg_switching_name(int k)
{
    return k >= 0 && k < MLG_NSWITCH ? table[k].name : NULL;
}

int mlg_switching_variable(int k)
{
    return k >= 0 && k < MLG_NSWITCH ? table[k].variable : -1;
}

int mlg_switching_mode_after(int k, int direction)
{
    if (k < 0 || k >= MLG_NSWITCH) return MLG_MODE_BY_STATE;
    return direction > 0 ? table[k].above : table[k].below;
}

int mlg_switching_watched(int k, int mode)
{
    return k >= 0 && k < MLG_NSWITCH && mode >= 0 && (table[k].watched & MLG_IN(mode)) != 0;
}

int mlg_switching_applies(const mlg_params *p, int k)
{
    if (mlg_switching_variable(k) == MLG_DISCRETE_FREEPLAY)
        return (int)p->freeplay_law == MLG_FREEPLAY_nonsmooth && p->yfp > 0.0;
    if (mlg_switching_variable(k) == MLG_DISCRETE_FRICTION)
        return p->friction_law == 1.0 && p->M_fric > 0.0;
    return 0;
}

/* psi_s'' in a mode of the twist friction, the others as given */
static dual twist_acceleration_in(const mlg_params *p, const int *modes, int friction,
                                  const dual x[MLG_NX], dual sin_p, int *status)
{
    int in[MLG_NDISCRETE];
    for (int v = 0; v < MLG_NDISCRETE; v++) in[v] = modes ? modes[v] : MLG_MODE_BY_STATE;
    in[MLG_DISCRETE_FRICTION] = friction;
    dual f[MLG_NX];
    *status |= vector_field(p, x, in, MLG_PARS_PLAIN, f, NULL);
    return p->eom_terms >= MLG_EOM_SIDESTAY
               ? d_add(f[MLG_PSI_DOT], d_mul(f[MLG_BETA_DOT], sin_p))
               : f[MLG_PSI_DOT];
}

/* h+- = y_tlk -+ y_fp, y_tlk = r_tlk(eta) psi_s (section III); the slip
 * speed r_seal psi_s' and the twist's accelerations sliding up and down */
int mlg_switching(const mlg_params *p, const int *modes, const double u[MLG_NX],
                  double h[MLG_NSWITCH], double dh[MLG_NSWITCH * MLG_NX])
{
    dual x[MLG_NX], out[MLG_NSWITCH];
    for (int i = 0; i < MLG_NX; i++) x[i] = d_var(u[i], i);
    int status = domain_status(p, x);
    for (int k = 0; k < MLG_NSWITCH; k++) out[k] = d_const(0.0);
    if (status == MLG_OK) {
        model_parameters mp = model_parameters_seed(p, MLG_PARS_PLAIN);
        sidestay g = sidestay_geometry(&mp);
        strut_lengths l = strut_lengths_at(mp.c, x[MLG_ETA]);
        dual r_tlk = torque_link_radius(mp.c, l.z_tlk);
        dual y = d_mul(r_tlk, twist_angle(x[MLG_PSI], x[MLG_BETA], g.sin_p));
        out[MLG_SWITCH_freeplay_upper] = d_sub(y, mp.yfp);
        out[MLG_SWITCH_freeplay_lower] = d_add(y, mp.yfp);
        if (mlg_switching_applies(p, MLG_SWITCH_slip_pos)) {
            dual beta_twist = p->eom_terms >= MLG_EOM_SIDESTAY
                                  ? d_mul(x[MLG_BETA_DOT], g.sin_p) : d_const(0.0);
            dual slip = d_mulc(d_add(x[MLG_PSI_DOT], beta_twist), p->r_seal);
            out[MLG_SWITCH_slip_pos] = out[MLG_SWITCH_slip_neg] = slip;
            out[MLG_SWITCH_stick_pos] =
                twist_acceleration_in(p, modes, MLG_MODE_SLIP_POS, x, g.sin_p, &status);
            out[MLG_SWITCH_stick_neg] =
                twist_acceleration_in(p, modes, MLG_MODE_SLIP_NEG, x, g.sin_p, &status);
        }
    }
    for (int k = 0; k < MLG_NSWITCH; k++) {
        h[k] = out[k].v;
        if (dh != NULL)
            for (int j = 0; j < MLG_NX; j++) dh[k * MLG_NX + j] = d_slope(out[k], j);
    }
    return status;
}

/* Closed contact sets, as eq. (14) by state (freeplay_laws.h); a sliding
 * twist slides, one at rest sticks unless even M_fric cannot hold it, as the
 * vector field by state (vector_field.h: friction_mode, hold_twist) */
int mlg_modes_at(const mlg_params *p, const double u[MLG_NX], int modes[MLG_NDISCRETE])
{
    double h[MLG_NSWITCH];
    int status = mlg_switching(p, NULL, u, h, NULL);
    modes[MLG_DISCRETE_FREEPLAY] = h[MLG_SWITCH_freeplay_lower] <= 0.0 ? MLG_MODE_CONTACT_NEG
                                   : h[MLG_SWITCH_freeplay_upper] >= 0.0 ? MLG_MODE_CONTACT_POS
                                                                         : MLG_MODE_GAP;
    double slip = h[MLG_SWITCH_slip_pos];
    modes[MLG_DISCRETE_FRICTION] =
        !mlg_switching_applies(p, MLG_SWITCH_slip_pos) ? MLG_MODE_BY_STATE
        : slip > 0.0 || (slip == 0.0 && h[MLG_SWITCH_stick_pos] > 0.0) ? MLG_MODE_SLIP_POS
        : slip < 0.0 || (slip == 0.0 && h[MLG_SWITCH_stick_neg] < 0.0) ? MLG_MODE_SLIP_NEG
                                                                      : MLG_MODE_STICK;
    return status;
}
