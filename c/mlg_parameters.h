/* Every parameter, measure and diagnostic of the MLG model, in one place.
 *
 * AUTO's PAR array (docs/model.md, section 2.1):
 *   PAR(1-10)   MLG_CONTINUATION_PARAMETERS, in this order (PAR(1) = V, ...):
 *               only quantities AUTO can continue in; all ten are taken.
 *   PAR(11)     the period of periodic orbits (AUTO's).
 *   PAR(12)     AUTO's (torus angle); never ours.
 *   PAR(13-20)  MLG_SWITCHES with an AUTO slot, and MLG_PAR_CONSTANTS_FILE.
 *   PAR(21-28)  MLG_MEASURES, written by PVLS (models/mlg.c).
 * This file is the single definition of these indices and names: AUTO's
 * `parnames` are printed from it (models/auto_names.c), the drivers read
 * them from the library (mlgshimmy.shared.mlgmodel), and overlays from
 * this file's text (mlgshimmy.shared.overlay).
 * MLG_CONSTANTS lists every fixed constant of the paper (Table 1, II.A, II.B)
 * under the paper's symbol, with its `table` value.
 * MLG_SWITCHES lists the model switches: discrete choices between variants
 * of the equations, never differentiated.  A switch with an AUTO slot
 * (par > 0) is read from PAR(par); one with par = 0 only from the constants
 * file (docs/model.md, sections 8 and 9).
 *
 * X(name, value, unit, description)
 */
#ifndef MLG_PARAMETERS_H
#define MLG_PARAMETERS_H

#define MLG_PI 3.14159265358979323846

#define MLG_CONTINUATION_PARAMETERS(X)                                              \
    X(V,        0.0,    "m/s",      "forward velocity")                          \
    X(Fstar,    1.0,    "-",        "dimensionless load F_z / (g_0 m_0)")        \
    X(yfp,      0.0,    "mm",       "torque-link freeplay y_fp")                 \
    X(eps_abs,  0.0,    "mm",       "smoothing epsilon, absolute part")          \
    X(eps_rel,  0.1,    "-",        "smoothing epsilon, part proportional to y_fp") \
    X(c_psi,    410.0,  "N m s/rad","torsional damping (Table 1; eq. 16)")       \
    X(rho,      0.0,    "rad",      "side-stay attachment inclination")          \
    X(mu,       0.0,    "rad",      "side-stay horizontal orientation")          \
    X(k_tlk,    3.90e7, "N/m",      "torque-link lateral stiffness")             \
    X(M_fric,   0.0,    "N m",      "oleo seal Coulomb friction moment about the strut axis")

/* PAR(11) is AUTO's period: the list above must fit in PAR(1-10). */
#define MLG_PAR_PERIOD 11

/* X(name, par, value, unit, description); par: AUTO PAR number, 0 for none */
#define MLG_SWITCHES(X)                                                             \
    X(eom_terms,   13, 0.0, "-",  "equations of motion: 0 as printed, 1 with the "   \
                                  "side-stay corrections, 2 complete Lagrangian")  \
    X(strut_variant, 14, 0.0, "-", "F_keta stage order: 0 monotone (swapped), 1 as "  \
                                  "printed")                                       \
    X(tyre_forces,  0, 1.0, "-",  "1: tyre forces act on the gear; 0 (tests): "     \
                                  "ideal frictionless support under the axle")    \
    X(freeplay_law, 0, 0.0, "-",  "torque-link freeplay law: its index in "          \
                                  "MLG_FREEPLAY_LAWS (c/freeplay_laws.h), 0 eq. (15)") \
    X(friction_law, 0, 0.0, "-",  "seal friction law on the twist: 0 tanh-regularised, " \
                                  "1 Coulomb with stick (modes; the simulator)")

/* PAR(15): which file of constant overrides FUNC reads (models/mlg.c):
 * k > 0 reads "mlg.constants.<k>" in the run directory, 0 reads none. */
#define MLG_PAR_CONSTANTS_FILE 15

/* Solution measures written by PVLS (models/mlg.c) into PAR(21) onwards,
 * in this order; constants/c.mlg names them and mlgshimmy.shared.mlgmodel lists
 * them (the drivers read the names from the library).
 * X(name, kind, state, unit, description); kind AMP: (max - min)/2 of the
 * state over the solution, MEAN: its mean, FREQ: 1/T (0 on equilibria). */
#define MLG_MEASURES_FIRST_PAR 21
#define MLG_MEASURES(X)                                                             \
    X(psi_amp,   AMP,  MLG_PSI,   "rad", "torsional amplitude")                  \
    X(delta_amp, AMP,  MLG_DELTA, "rad", "lateral amplitude")                    \
    X(beta_mean, MEAN, MLG_BETA,  "rad", "mean longitudinal angle")              \
    X(beta_amp,  AMP,  MLG_BETA,  "rad", "longitudinal amplitude")               \
    X(eta_mean,  MEAN, MLG_ETA,   "m",   "mean strut compression")               \
    X(eta_amp,   AMP,  MLG_ETA,   "m",   "strut compression amplitude")          \
    X(freq,      FREQ, MLG_PSI,   "Hz",  "frequency 1/T; 0 on equilibria")       \
    X(psi_mean,  MEAN, MLG_PSI,   "rad", "mean torsion: the yaw of off-centre equilibria")

/* Intermediate quantities of one evaluation (mlg_diagnose: the struct
 * mlg_diagnostics, c/mlg_model.h), filled where the model computes them
 * (c/vector_field.h).  X(name, n): one double (n = 1) or a tyre pair
 * [0] = L, [1] = R (n = 2). */
#define MLG_DIAGNOSTICS(X)                                                         \
    X(F_z, 1) X(F_dyn, 1) X(cos_phi, 1) X(F_keta, 1) X(F_ceta, 1)                  \
    X(L_beta, 1) X(L_delta, 1) X(I_a, 1) X(I_beta, 1) X(I_delta, 1)                \
    X(k_delta, 1) X(c_delta, 1) X(r_tlk, 1)                                        \
    X(F, 2) X(d, 2) X(h, 2) X(L, 2) X(r_eff, 2) X(alpha, 2) X(F_y, 2) X(M_z, 2)    \
    X(M_kpsi, 1) X(M_cpsi, 1) X(M_psi, 1) X(M_delta, 1) X(M_beta, 1)               \
    X(m, 1) X(p, 1)                          /* side-stay angles (Fig. 3) */

#define MLG_CONSTANTS(X)                                                            \
    /* Table 1: geometry */                                                          \
    X(phi0,     -0.1222, "rad",     "initial rake angle")                        \
    X(e,        0.0,     "m",       "caster length")                             \
    X(a,        0.46,    "m",       "half track width")                          \
    X(l_tlk,    0.35,    "m",       "torque link length")                        \
    X(a_tlk,    0.15,    "m",       "upper torque link offset")                  \
    X(b_tlk,    0.14,    "m",       "lower torque link offset")                  \
    X(r,        0.58,    "m",       "undeflected tyre radius")                   \
    /* Table 1: structure */                                                         \
    X(M,        3.0e4,   "kg",      "vertical modal mass")                       \
    X(I_psi,    150.0,   "kg m^2",  "torsional inertia")                         \
    X(I_0,      11.0,    "kg m^2",  "wheel yaw inertia")                         \
    X(I,        19.0,    "kg m^2",  "wheel polar inertia (per wheel)")           \
    X(c_beta,   3100.0,  "N m s/rad","longitudinal damping")                     \
    X(k_beta,   1.0e7,   "N m/rad", "longitudinal stiffness")                    \
    /* II.A: F* scale, F_z = F* g_0 m_0 */                                           \
    X(g_0,      9.807,   "m/s^2",   "gravity in the F* definition")              \
    X(m_0,      3.0e4,   "kg",      "nominal mass in the F* definition")         \
    /* II.A: eta-dependent lengths and inertias */                                   \
    X(z_tlk0,   0.605,   "m",       "z_tlk = z_tlk0 - eta")                      \
    X(L_beta0,  2.915,   "m",       "L_beta = L_beta0 - eta")                    \
    X(L_delta0, 1.266,   "m",       "L_delta = L_delta0 - eta")                  \
    X(I_beta2,  640.0,   "kg",      "I_beta quadratic coefficient")              \
    X(I_beta1,  -100.0,  "kg m",    "I_beta linear coefficient")                 \
    X(I_beta0,  260.0,   "kg m^2",  "I_beta constant")                           \
    X(I_delta2, 630.0,   "kg",      "I_delta quadratic coefficient")             \
    X(I_delta1, -140.0,  "kg m",    "I_delta linear coefficient")                \
    X(I_delta0, 60.0,    "kg m^2",  "I_delta constant")                          \
    X(I_a2,     440.0,   "kg",      "I_a = I_a2 a^2 + I_a0 + 2 I_0")             \
    X(I_a0,     5.0,     "kg m^2",  "I_a constant")                              \
    /* II.A: lateral stiffness k_delta and damping c_delta */                        \
    X(a_kdelta, 1.649,   "m",       "k_delta fit a")                             \
    X(b_kdelta, 0.611,   "m",       "k_delta fit b")                             \
    X(c_kdelta0, 0.655,  "m",       "k_delta fit c = c_kdelta0 - eta")           \
    X(K_kdelta, 6.067e6, "N m^2",   "k_delta fit K")                             \
    X(R_kdelta, 8.0 / 3.0, "-",     "k_delta fit R")                             \
    X(zeta_delta, 1.66e-2, "-",     "c_delta / sqrt(I_delta k_delta) (printed 1.66e7)") \
    /* II.A: strut spring F_keta and damper F_ceta */                                \
    X(a_keta,   612.4,   "N",       "F_keta stage fit a")                        \
    X(b_keta,   16.72,   "1/m",     "F_keta stage fit b")                        \
    X(c_keta,   2483.0,  "N",       "F_keta stage fit c")                        \
    X(d_keta,   0.3851,  "N",       "F_keta stage fit d")                        \
    X(e_keta,   31.39,   "1/m",     "F_keta stage fit e")                        \
    X(f_keta,   1.885e5, "N",       "F_keta stage fit f")                        \
    X(eta_stage, 0.34,   "m",       "F_keta stage switch position")              \
    X(k_stage,  1.0e5,   "1/m",     "F_keta stage switch steepness")             \
    X(F_topout, 40.0,    "N m",     "F_keta top-out term F_topout / eta")        \
    X(c_eta2a,  4.0e4,   "N s^2/m^2", "F_ceta quadratic, switched part")        \
    X(k_eta2,   1.0e4,   "1/m",     "F_ceta switch steepness")                   \
    X(eta_orifice, 0.18, "m",       "F_ceta switch position")                    \
    X(c_eta2b,  7.5e4,   "N s^2/m^2", "F_ceta quadratic, constant part")        \
    X(c_eta1,   1000.0,  "N s/m",   "F_ceta linear part")                        \
    /* II.B: tyre deflection, radius, patch, relaxation */                           \
    X(a_d,      4.221e-4, "m/N^0.5", "tyre deflection fit a_d")                  \
    X(b_d,      5.107e4, "N",       "tyre deflection fit b_d")                   \
    X(k_reff,   0.2,     "-",       "r_eff = r - k_reff d")                      \
    X(k_patch,  0.85,    "-",       "patch length / chord length")               \
    X(k_relax,  0.7,     "-",       "relaxation length / patch length")          \
    X(F_tyre_min, 0.0,   "N",       "tyre laws held at this load below it (0: as printed)") \
    /* II.B.5: Magic Formula, lateral force (eq. 7) */                              \
    X(C_F,      1.34,    "-",       "C_Fklambda")                                \
    X(a1_F,     -2.828e4, "N",      "a1_Fklambda")                               \
    X(a2_F,     7.9978e8, "N^2",    "a2_Fklambda")                               \
    X(a3_F,     7.7459e4, "N",      "a3_Fklambda")                               \
    X(a4_F,     6.789e5, "N/rad",   "a4_Fklambda")                               \
    X(a5_F,     4.126e4, "N",       "a5_Fklambda")                               \
    X(a6_F,     -1.486e-11, "1/N^2", "a6_Fklambda")                              \
    X(a7_F,     -7.036e-6, "1/N",   "a7_Fklambda")                               \
    X(E0_F,     0.95,    "-",       "constant of E_Fklambda")                    \
    /* II.B.5: Magic Formula, aligning moment (eq. 8) */                            \
    X(C_M,      3.6,     "-",       "C_Mkalpha")                                 \
    X(a1_M,     9.524e-8, "m/N",    "a1_Mkalpha")                                \
    X(a2_M,     9.364e-3, "m",      "a2_Mkalpha")                                \
    X(a3_M,     1.167e-6, "1/(N rad)", "a3_Mkalpha")                             \
    X(a4_M,     1.39e-1, "1/rad",   "a4_Mkalpha")                                \
    X(a5_M,     -3.1e-11, "1/N^2",  "a5_Mkalpha")                                \
    X(a6_M,     2.34e-5, "1/N",     "a6_Mkalpha")                                \
    X(E0_M,     0.95,    "-",       "constant of E_Mkalpha")                     \
    X(k_M_exp,  1.0e-6,  "1/N",     "exponent scale in B_Mkalpha")              \
    /* beyond the paper: oleo seal friction, regularised (docs/model.md 9) */       \
    X(F_fric,   0.0,     "N",       "oleo seal Coulomb friction force along the strut") \
    X(v_fric,   1.0e-3,  "m/s",     "seal friction regularisation speed")        \
    X(r_seal,   0.1,     "m",       "seal radius: torsional slip speed = r_seal * twist rate")

#endif
