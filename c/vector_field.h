/* Assembly of the vector field: generalised moments (eqs. 10-12) and the
 * accelerations of eqs. (1)-(4); tyre states from eqs. (5)-(6).
 * Included by vector_field_value.c (DUAL_N = 0) and vector_field_jacobian.c
 * (DUAL_N = MLG_NDIR); see dual.h. */
#ifndef MLG_VECTOR_FIELD_H
#define MLG_VECTOR_FIELD_H

#include "freeplay.h"
#include "geometry.h"
#include "gyroscopic.h"
#include "strut.h"
#include "tyres.h"

/* Forces of both tyres, reduced to sums so that the moment about any point
 * Q is  sum_PxF - Q x sum_F + sum_G. */
typedef struct {
    dvec sum_F;      /* sum of F_i e_Z + F_klambda,i */
    dvec sum_PxF;    /* sum of P_iC x (F_i e_Z + F_klambda,i) */
    dvec sum_G;      /* sum of the free moments -M_kalpha,i - M_gyr,i */
} tyre_loads;

static inline dual moment_about(const tyre_loads *t, dvec Q, dvec axis)
{
    dvec m = v_add(v_sub(t->sum_PxF, v_cross(Q, t->sum_F)), t->sum_G);
    return v_dot(m, axis);
}

/* I_a (d' sin ta + b' cos ta cos p)(d' cos ta - b' sin ta cos p): eqs. (1), (3) */
static inline dual axle_coupling(dual I_a, dual delta_dot, dual beta_dot, dual s_ta, dual c_ta,
                                 dual cos_p)
{
    dual bc = d_mul(beta_dot, cos_p);
    return d_mul(I_a, d_mul(d_add(d_mul(delta_dot, s_ta), d_mul(bc, c_ta)),
                            d_sub(d_mul(delta_dot, c_ta), d_mul(bc, s_ta))));
}

static inline void fill_zero(dual f[MLG_NX])
{
    for (int i = 0; i < MLG_NX; i++) f[i] = d_const(0.0);
}

static inline int vector_field(const mlg_params *c, const dual u[MLG_NX], dual f[MLG_NX],
                               mlg_diagnostics *diag)
{
    int status = MLG_OK;
    for (int i = 0; i < MLG_NX; i++)
        if (!isfinite(u[i].v)) status |= MLG_NOT_FINITE;
    if (!(u[MLG_ETA].v > 0.0 && u[MLG_ETA].v < c->z_tlk0)) status |= MLG_ETA_OUT_OF_STROKE;
    if (status != MLG_OK) {
        fill_zero(f);
        return status;
    }
    const dual psi = u[MLG_PSI], delta = u[MLG_DELTA], beta = u[MLG_BETA], eta = u[MLG_ETA];
    const dual psi_dot = u[MLG_PSI_DOT], delta_dot = u[MLG_DELTA_DOT];
    const dual beta_dot = u[MLG_BETA_DOT], eta_dot = u[MLG_ETA_DOT];

    model_parameters mp = model_parameters_seed(c);
    sidestay g = sidestay_geometry(&mp);
    const int eom = (int)c->eom_terms;       /* enum mlg_eom_terms; docs/model.md 8 */
    dual theta_a = d_add(d_add(psi, d_mul(beta, g.sin_p)), g.m);     /* after eq. (6) */
    dual theta_a_dot = d_add(psi_dot, d_mul(beta_dot, g.sin_p));
    dual psi_s = d_add(psi, d_mul(beta, g.sin_p));
    /* psi_s' = psi' + beta_twist is the axle's rate relative to the strut; as
     * printed, eqs. (9), (16) and V_iCF use psi' (beta_twist = 0) */
    dual beta_twist = eom >= MLG_EOM_SIDESTAY ? d_mul(beta_dot, g.sin_p) : d_const(0.0);
    dual twist_rate = d_add(psi_dot, beta_twist);
    strut_geometry s = strut_geometry_at(&mp, &g, eta, theta_a);
    pose q = pose_at(&mp, &g, &s, psi, delta, beta);

    /* torque links: eqs. (15), (16) */
    dual r_tlk = torque_link_radius(c, s.z_tlk);
    dual M_kpsi = torsional_stiffness_moment(&mp, r_tlk, psi_s);
    dual M_cpsi = torsional_damping_moment(&mp, twist_rate);

    /* eq. (4) solved for the dynamic load: F_dyn = M H'' + F_z (docs/model.md 4.6) */
    dual F_keta = strut_spring_force(c, eta), F_ceta = strut_damper_force(c, eta, eta_dot);
    dual axial = d_add(F_keta, F_ceta);
    axial = d_sub(axial, d_mulc(d_mul(s.dI_beta_deta, d_sq(beta_dot)), 0.5));
    axial = d_sub(axial, d_mulc(d_mul(s.dI_delta_deta, d_sq(delta_dot)), 0.5));
    if (eom == MLG_EOM_COMPLETE) {
        /* d/deta of the potentials 1/2 k_delta(eta) delta^2 and of the torque links,
         * whose apex deflection r_tlk(eta) psi_s gives M_kpsi psi_s (dr_tlk/deta) / r_tlk */
        axial = d_add(axial, d_mulc(d_mul(s.dk_delta_deta, d_sq(delta)), 0.5));
        dual dr_deta = d_neg(torque_link_radius_slope(c, s.z_tlk));
        axial = d_add(axial, d_mul(M_kpsi, d_mul(psi_s, d_div(dr_deta, r_tlk))));
    }
    dual F_dyn = d_div(axial, q.cos_phi);
    dual MH_ddot = d_sub(F_dyn, mp.F_z);

    dual F[2];
    status |= tyre_load_split(c, F_dyn, q.u_a.c[2], F);
    if (status != MLG_OK) {
        fill_zero(f);
        return status;
    }

    dvec Omega = axle_angular_velocity(twist_rate, q.u_psi, delta_dot, q.u_delta, beta_dot,
                                       g.u_beta);
    dvec e_Z = v_const(0.0, 0.0, 1.0);
    tyre_loads loads = {v_const(0, 0, 0), v_const(0, 0, 0), v_const(0, 0, 0)};
    for (int i = 0; i < 2; i++) {
        tyre_shape t = tyre_shape_at(c, F[i], &status);
        if (status != MLG_OK) break;
        dvec P_C = v_add(q.P_wheel[i], v_scale(q.u_r, d_addc(d_neg(t.d), c->r)));
        dvec P_CF = v_add(P_C, v_scale(q.u_f, d_mulc(t.h, 0.5)));
        /* contact-point velocities V*_iCF and V_iCF (after eq. 6); V* leaves out
         * the yaw psi' of the torsional DoF, not the twist that beta carries */
        dvec twist_arm = v_cross(q.u_psi, v_sub(P_CF, q.P_0));
        dvec V_star = v_add(v_scale(v_cross(q.u_delta, P_CF), delta_dot),
                            v_scale(v_cross(g.u_beta, v_sub(P_CF, q.P_beta)), beta_dot));
        V_star = v_add(V_star, v_scale(q.u_eta, eta_dot));
        V_star.c[0] = d_add(V_star.c[0], mp.V);
        V_star = v_add(V_star, v_scale(twist_arm, beta_twist));
        dvec V_CF = v_add(V_star, v_scale(twist_arm, psi_dot));
        dual rolling = v_dot(V_CF, q.u_f);
        dual lambda = u[MLG_LAMBDA_L + i];
        /* eqs. (5), (6) */
        f[MLG_LAMBDA_L + i] = d_neg(d_add(d_div(d_mul(rolling, lambda), t.L),
                                          v_dot(V_star, q.u_lambda)));
        dual alpha = d_atan(d_div(lambda, t.L));
        dual F_y = tyre_lateral_force(c, F[i], alpha);
        dual M_z = tyre_aligning_moment(c, F[i], alpha);
        dvec M_gyr = gyroscopic_moment(Omega, c->I, rolling, t.r_eff, q.u_a);
        if (c->tyre_forces != 0.0) {
            dvec force = v_add(v_scale(e_Z, F[i]), v_scale(q.u_lambda, F_y));
            loads.sum_F = v_add(loads.sum_F, force);
            loads.sum_PxF = v_add(loads.sum_PxF, v_cross(P_C, force));
            loads.sum_G = v_sub(loads.sum_G, v_add(v_scale(e_Z, M_z), M_gyr));
        }
        if (diag != NULL) {
            diag->F[i] = F[i].v;
            diag->d[i] = t.d.v;
            diag->h[i] = t.h.v;
            diag->L[i] = t.L.v;
            diag->r_eff[i] = t.r_eff.v;
            diag->alpha[i] = alpha.v;
            diag->F_y[i] = F_y.v;
            diag->M_z[i] = M_z.v;
        }
    }
    if (status != MLG_OK) {
        fill_zero(f);
        return status;
    }

    /* generalised moments, eqs. (10)-(12); P_delta is the origin.  Eq. (12)
     * turns beta with psi held, i.e. twists the axle by sin p per unit beta;
     * as printed it uses -u_beta . u_psi for sin p, exact only at delta = 0 */
    dual M_psi = moment_about(&loads, q.P_0, q.u_psi);
    dual M_delta = moment_about(&loads, v_const(0, 0, 0), q.u_delta);
    dual twist_per_beta = eom == MLG_EOM_COMPLETE ? g.sin_p : d_neg(v_dot(g.u_beta, q.u_psi));
    dual M_beta = d_add(moment_about(&loads, q.P_beta, g.u_beta), d_mul(M_psi, twist_per_beta));

    dual s_ta = d_sin(theta_a), c_ta = d_cos(theta_a);
    dual cos_2ta = d_addc(d_mulc(d_sq(c_ta), 2.0), -1.0);            /* 2 cos^2 ta - 1 */
    dual sc2 = d_mulc(d_mul(s_ta, c_ta), 2.0);                        /* 2 sin ta cos ta */
    dual coupling = axle_coupling(s.I_a, delta_dot, beta_dot, s_ta, c_ta, g.cos_p);

    /* eq. (1) */
    dual rhs_psi = d_sub(d_sub(d_sub(M_psi, coupling), M_cpsi), M_kpsi);
    dual psi_ddot = d_mulc(rhs_psi, 1.0 / c->I_psi);

    /* eq. (2) */
    dual gyro_delta = d_mul(s.I_a, d_mul(d_add(d_mul(d_mul(beta_dot, cos_2ta), g.cos_p),
                                                d_mul(delta_dot, sc2)), theta_a_dot));
    dual rhs_delta = d_add(M_delta, gyro_delta);
    rhs_delta = d_sub(rhs_delta, d_mul(s.dI_delta_deta, d_mul(eta_dot, delta_dot)));
    rhs_delta = d_sub(rhs_delta, d_add(d_mul(s.c_delta, delta_dot), d_mul(s.k_delta, delta)));

    /* eq. (3), with the printed "sin theta_s" read as sin theta_a; the theta_a'
     * bracket carries cos p in the derived equations (it is d/dt of -I_a W sin ta cos p) */
    dual bracket = d_sub(d_mul(delta_dot, cos_2ta), d_mul(d_mul(beta_dot, sc2), g.cos_p));
    if (eom >= MLG_EOM_SIDESTAY) bracket = d_mul(bracket, g.cos_p);
    dual gyro_beta = d_mul(s.I_a, d_mul(bracket, theta_a_dot));
    dual rhs_beta = d_add(d_sub(M_beta, d_mul(coupling, g.sin_p)), gyro_beta);
    /* the vertical load's moment about the side-stay axis, arm dH/dbeta = L_beta cos'(phi):
     * as printed, eq. (3) adds M H'' there although F_dyn = M H'' + F_z already acts in
     * M_beta (counted twice, docs/model.md 4.16); an ideal support carries F_dyn on that arm */
    dual beta_load = eom == MLG_EOM_COMPLETE ? d_const(0.0) : MH_ddot;
    if (c->tyre_forces == 0.0) beta_load = d_add(beta_load, F_dyn);
    rhs_beta = d_sub(rhs_beta, d_mul(beta_load, d_mul(s.L_beta, q.dcos_phi)));
    rhs_beta = d_sub(rhs_beta, d_mul(s.dI_beta_deta, d_mul(eta_dot, beta_dot)));
    rhs_beta = d_sub(rhs_beta, d_add(d_mulc(beta_dot, c->c_beta), d_mul(M_cpsi, g.sin_p)));
    rhs_beta = d_sub(rhs_beta, d_add(d_mulc(beta, c->k_beta), d_mul(M_kpsi, g.sin_p)));

    dual delta_ddot, beta_ddot;
    if (eom == MLG_EOM_COMPLETE) {
        /* the axle's kinetic energy 1/2 I_a W^2, W = delta' cos ta - beta' sin ta cos p,
         * couples the accelerations: [I_delta, -k; -k, I_beta + I_a sin^2 ta cos^2 p] */
        dual k = d_mul(s.I_a, d_mul(d_mul(s_ta, c_ta), g.cos_p));
        dual m_bb = d_add(s.I_beta, d_mul(s.I_a, d_sq(d_mul(s_ta, g.cos_p))));
        dual det = d_sub(d_mul(s.I_delta, m_bb), d_sq(k));
        delta_ddot = d_div(d_add(d_mul(m_bb, rhs_delta), d_mul(k, rhs_beta)), det);
        beta_ddot = d_div(d_add(d_mul(s.I_delta, rhs_beta), d_mul(k, rhs_delta)), det);
    } else {
        delta_ddot = d_div(rhs_delta, s.I_delta);
        beta_ddot = d_div(rhs_beta, s.I_beta);
    }

    /* H'' = cos'(phi)(L_b b'' - 2 eta' b') + cos''(phi) L_b b'^2 - eta'' cos(phi)
     * (docs/model.md 4.5: the printed last term eta' is eta''), solved for eta'' */
    dual H_ddot = d_mulc(MH_ddot, 1.0 / c->M);
    dual eta_rhs = d_mul(q.dcos_phi, d_sub(d_mul(s.L_beta, beta_ddot),
                                           d_mulc(d_mul(eta_dot, beta_dot), 2.0)));
    eta_rhs = d_add(eta_rhs, d_mul(d_mul(q.d2cos_phi, s.L_beta), d_sq(beta_dot)));
    dual eta_ddot = d_div(d_sub(eta_rhs, H_ddot), q.cos_phi);

    f[MLG_PSI] = psi_dot;
    f[MLG_DELTA] = delta_dot;
    f[MLG_BETA] = beta_dot;
    f[MLG_ETA] = eta_dot;
    f[MLG_PSI_DOT] = psi_ddot;
    f[MLG_DELTA_DOT] = delta_ddot;
    f[MLG_BETA_DOT] = beta_ddot;
    f[MLG_ETA_DOT] = eta_ddot;

    if (diag != NULL) {
        diag->F_z = mp.F_z.v;
        diag->F_dyn = F_dyn.v;
        diag->cos_phi = q.cos_phi.v;
        diag->F_keta = F_keta.v;
        diag->F_ceta = F_ceta.v;
        diag->L_beta = s.L_beta.v;
        diag->L_delta = s.L_delta.v;
        diag->I_a = s.I_a.v;
        diag->I_beta = s.I_beta.v;
        diag->I_delta = s.I_delta.v;
        diag->k_delta = s.k_delta.v;
        diag->c_delta = s.c_delta.v;
        diag->r_tlk = r_tlk.v;
        diag->M_kpsi = M_kpsi.v;
        diag->M_cpsi = M_cpsi.v;
        diag->M_psi = M_psi.v;
        diag->M_delta = M_delta.v;
        diag->M_beta = M_beta.v;
        diag->m = g.m.v;
        diag->p = asin(g.sin_p.v);
    }
    return MLG_OK;
}

#endif
