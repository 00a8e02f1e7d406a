/* Assembly of the vector field u' = f(u; p), in the order of sections II-III:
 * geometry, structure, torque links, eq. (4)'s dynamic load, the tyres
 * (eqs. 5-9), the generalised moments (eqs. 10-12) and eqs. (1)-(4).
 * Included by vector_field_value.c (DUAL_N = 0) and vector_field_jacobian.c
 * (DUAL_N = 10); see dual.h. */
#ifndef MLG_VECTOR_FIELD_H
#define MLG_VECTOR_FIELD_H

#include "equations_of_motion.h"
#include "params_unusable.h"

static inline int domain_status(const mlg_params *p, const dual u[MLG_NX])
{
    if (mlg_params_unusable(p, NULL, 0)) return MLG_BAD_PARAMETER;
    int status = MLG_OK;
    for (int i = 0; i < MLG_NX; i++)
        if (!isfinite(u[i].v)) status |= MLG_NOT_FINITE;
    if (!(u[MLG_ETA].v > 0.0 && u[MLG_ETA].v < p->z_tlk0)) status |= MLG_ETA_OUT_OF_STROKE;
    return status;
}

static inline void describe(const gear_state *x, dual F_dyn, dual F_keta, dual F_ceta,
                            const dual M[3], mlg_diagnostics *d);
static inline void describe_tyre(const tyre_contact *t, int i, dual F, mlg_diagnostics *d);

/* The freeplay's mode: MLG_MODE_BY_STATE, or a mode of eq. (14) when that
 * law is selected; -2 for a mode that cannot be used */
static inline int freeplay_mode(const mlg_params *p, const int *modes)
{
    int mode = modes != NULL ? modes[MLG_DISCRETE_FREEPLAY] : MLG_MODE_BY_STATE;
    if (mode == MLG_MODE_BY_STATE) return mode;
    int known = mode >= MLG_MODE_GAP && mode <= MLG_MODE_CONTACT_NEG;
    return known && (int)p->freeplay_law == MLG_FREEPLAY_nonsmooth ? mode : -2;
}

/* The twist friction's mode: MLG_MODE_BY_STATE under tanh (friction_law 0);
 * under Coulomb's law (1) the mode given, or by state the sign of the twist
 * rate, MLG_MODE_STICK at rest (hold_twist resolves it); -2 for a mode that
 * cannot be used */
static inline int friction_mode(const mlg_params *p, const int *modes, dual twist_rate)
{
    int mode = modes != NULL ? modes[MLG_DISCRETE_FRICTION] : MLG_MODE_BY_STATE;
    if (p->friction_law == 0.0) return mode == MLG_MODE_BY_STATE ? mode : -2;
    if (mode != MLG_MODE_BY_STATE)
        return mode >= MLG_MODE_STICK && mode <= MLG_MODE_SLIP_NEG ? mode : -2;
    return twist_rate.v > 0.0 ? MLG_MODE_SLIP_POS
         : twist_rate.v < 0.0 ? MLG_MODE_SLIP_NEG : MLG_MODE_STICK;
}

/* psi_s'' = d/dt (psi' + beta_twist): the twist's acceleration relative to
 * the strut, whose rate the friction acts on */
static inline dual twist_acceleration(const gear_state *x, const dual acc[4])
{
    return x->eom >= MLG_EOM_SIDESTAY ? d_add(acc[0], d_mul(acc[2], x->g->sin_p)) : acc[0];
}

/* Coulomb's stick (docs/model.md 10): the friction moment that holds the
 * twist, psi_s'' = 0.  The accelerations are affine in M_cpsi (eqs. 1-4), so
 * two evaluations, friction 0 (acc on entry) and a trial moment, give it
 * exactly; the trial I_psi psi_s''(0), the hold at eom_terms 0, keeps the
 * difference of the two free of cancellation.  By state (clip) a holding
 * moment beyond +-M_fric slides at that level. */
static inline void hold_twist(gear_state *x, const dual M[3], dual F_dyn, dual damping,
                              int clip, dual acc[4])
{
    dual at_zero = twist_acceleration(x, acc);
    double trial = at_zero.v != 0.0 ? at_zero.v * x->mp->c->I_psi : 1.0;
    x->M_cpsi = d_addc(damping, trial);
    accelerations(x, M, F_dyn, acc);
    dual hold = d_mulc(d_div(at_zero, d_sub(at_zero, twist_acceleration(x, acc))), trial);
    dual limit = x->mp->par.M_fric;
    if (clip && hold.v > limit.v) hold = limit;
    if (clip && hold.v < -limit.v) hold = d_neg(limit);
    x->M_cpsi = d_add(damping, hold);
    accelerations(x, M, F_dyn, acc);
}

/* u: the states, seeded by the caller; modes: those of the discrete
 * variables (NULL: by state); PAR(1) is derivative direction dir_par1
 * (model_parameters_seed) */
static inline int vector_field(const mlg_params *p, const dual u[MLG_NX], const int *modes,
                               int dir_par1, dual f[MLG_NX], mlg_diagnostics *diag)
{
    for (int i = 0; i < MLG_NX; i++) f[i] = d_const(0.0);
    int status = domain_status(p, u);
    if (status != MLG_OK) return status;
    int mode = freeplay_mode(p, modes);
    if (mode == -2) return MLG_BAD_PARAMETER;
    const dual psi = u[MLG_PSI], delta = u[MLG_DELTA], beta = u[MLG_BETA], eta = u[MLG_ETA];
    model_parameters mp = model_parameters_seed(p, dir_par1);
    gear_rates w = {.psi_dot = u[MLG_PSI_DOT], .delta_dot = u[MLG_DELTA_DOT],
                    .beta_dot = u[MLG_BETA_DOT], .eta_dot = u[MLG_ETA_DOT]};
    gear_state x = {.mp = &mp, .eom = (int)p->eom_terms, .delta = delta, .beta = beta, .eta = eta};

    /* section II: side stay (Fig. 3), strut lengths and structure (II.A), pose */
    sidestay g = sidestay_geometry(&mp);
    x.psi_s = twist_angle(psi, beta, g.sin_p);
    x.theta_a = d_add(x.psi_s, g.m);
    x.theta_a_dot = d_add(w.psi_dot, d_mul(w.beta_dot, g.sin_p));
    /* psi_s' = psi' + beta_twist is the axle's rate relative to the strut; as
     * printed, eqs. (9), (16) and V_iCF use psi' (beta_twist = 0) */
    w.beta_twist = x.eom >= MLG_EOM_SIDESTAY ? d_mul(w.beta_dot, g.sin_p) : d_const(0.0);
    strut_lengths l = strut_lengths_at(mp.c, eta);
    structure s = structure_at(mp.c, &g, &l, eta, x.theta_a);
    pose q;
    pose_at(&q, &mp, &g, &l, psi, delta, beta);
    dual twist_rate = d_add(w.psi_dot, w.beta_twist);
    w.Omega = axle_angular_velocity(twist_rate, q.u_psi, w.delta_dot, q.u_delta, w.beta_dot,
                                    g.u_beta);
    x.g = &g, x.l = &l, x.s = &s, x.q = &q, x.w = &w;

    /* section III: torque links, eqs. (14)-(16) */
    x.r_tlk = torque_link_radius(mp.c, l.z_tlk);
    x.M_kpsi = torsional_stiffness_moment(&mp, x.r_tlk, x.psi_s, mode);
    int friction = friction_mode(p, modes, twist_rate);
    if (friction == -2) return MLG_BAD_PARAMETER;
    dual damping = torsional_damping_moment(&mp, twist_rate);
    x.M_cpsi = d_add(damping, friction == MLG_MODE_BY_STATE
                                  ? seal_friction_moment(&mp, twist_rate)
                                  : coulomb_friction_moment(&mp, friction));

    /* eq. (4): the strut's axial load and the tyres' share of it (II.B.1) */
    dual F_keta = strut_spring_force(mp.c, eta);
    dual F_ceta = d_add(strut_damper_force(mp.c, eta, w.eta_dot),
                        seal_friction_force(&mp, w.eta_dot));
    dual F_dyn = dynamic_load(&x, F_keta, F_ceta), F[2];
    status |= tyre_load_split(mp.c, F_dyn, q.u_a.c[2], F);

    /* eqs. (5)-(9): each tyre's slip and loads */
    tyre_loads loads = {v_const(0, 0, 0), v_const(0, 0, 0), v_const(0, 0, 0)};
    for (int i = 0; i < 2 && status == MLG_OK; i++) {
        tyre_contact t = tyre_contact_at(&mp, &g, &q, &w, i, F[i], u[MLG_LAMBDA_L + i], &status);
        f[MLG_LAMBDA_L + i] = t.lambda_dot;
        if (p->tyre_forces != 0.0) add_tyre_load(&loads, &t);
        if (diag != NULL) describe_tyre(&t, i, F[i], diag);
    }
    if (status != MLG_OK) {
        for (int i = 0; i < MLG_NX; i++) f[i] = d_const(0.0);
        return status;
    }

    /* eqs. (10)-(12), then (1)-(4) */
    dual M[3], acc[4];
    generalised_moments(&x, &loads, M);
    accelerations(&x, M, F_dyn, acc);
    if (friction == MLG_MODE_STICK)
        hold_twist(&x, M, F_dyn, damping, modes == NULL || modes[MLG_DISCRETE_FRICTION] ==
                                          MLG_MODE_BY_STATE, acc);
    for (int i = 0; i < 4; i++) {
        f[MLG_PSI + i] = u[MLG_PSI_DOT + i];
        f[MLG_PSI_DOT + i] = acc[i];
    }
    if (diag != NULL) describe(&x, F_dyn, F_keta, F_ceta, M, diag);
    /* finite inputs can still overflow */
    for (int i = 0; i < MLG_NX; i++)
        if (!d_finite(f[i])) {
            for (int j = 0; j < MLG_NX; j++) f[j] = d_const(0.0);
            return MLG_NOT_FINITE;
        }
    return MLG_OK;
}

static inline void describe_tyre(const tyre_contact *t, int i, dual F, mlg_diagnostics *d)
{
    d->F[i] = F.v;
    d->d[i] = t->shape.d.v;
    d->h[i] = t->shape.h.v;
    d->L[i] = t->shape.L.v;
    d->r_eff[i] = t->shape.r_eff.v;
    d->alpha[i] = t->alpha.v;
    d->F_y[i] = t->F_y.v;
    d->M_z[i] = t->M_z.v;
}

static inline void describe(const gear_state *x, dual F_dyn, dual F_keta, dual F_ceta,
                            const dual M[3], mlg_diagnostics *d)
{
    d->F_z = x->mp->F_z.v;
    d->F_dyn = F_dyn.v;
    d->cos_phi = x->q->cos_phi.v;
    d->F_keta = F_keta.v;
    d->F_ceta = F_ceta.v;
    d->L_beta = x->l->L_beta.v;
    d->L_delta = x->l->L_delta.v;
    d->I_a = x->s->I_a.v;
    d->I_beta = x->s->I_beta.v;
    d->I_delta = x->s->I_delta.v;
    d->k_delta = x->s->k_delta.v;
    d->c_delta = x->s->c_delta.v;
    d->r_tlk = x->r_tlk.v;
    d->M_kpsi = x->M_kpsi.v;
    d->M_cpsi = x->M_cpsi.v;
    d->M_psi = M[0].v;
    d->M_delta = M[1].v;
    d->M_beta = M[2].v;
    d->m = x->g->m.v;
    d->p = asin(x->g->sin_p.v);
}

#endif
