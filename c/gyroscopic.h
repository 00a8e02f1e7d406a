/* Gyroscopic moment of a spinning wheel and brake assembly (II.B.6, eq. 9). */
#ifndef MLG_GYROSCOPIC_H
#define MLG_GYROSCOPIC_H

#include "vec3.h"

/* Omega = psi' u_psi + delta' u_delta + beta' u_beta (axle angular velocity) */
static inline dvec axle_angular_velocity(dual psi_dot, dvec u_psi, dual delta_dot, dvec u_delta,
                                         dual beta_dot, dvec u_beta)
{
    return v_add(v_add(v_scale(u_psi, psi_dot), v_scale(u_delta, delta_dot)),
                 v_scale(u_beta, beta_dot));
}

/* M_gyr,i = Omega x I omega_i, omega_i = (V_iCF . u_f) / r_eff,i u_a  (eq. 9) */
static inline dvec gyroscopic_moment(dvec Omega, double I, dual rolling_speed, dual r_eff,
                                     dvec u_a)
{
    dual spin = d_mulc(d_div(rolling_speed, r_eff), I);
    return v_cross(Omega, v_scale(u_a, spin));
}

#endif
