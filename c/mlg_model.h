/* mlg-shimmy model library: public interface.
 *
 * The dual-wheel main landing gear of Howcroft, Lowenberg, Neild and
 * Krauskopf, "Effects of freeplay on the dynamic stability of an aircraft
 * main landing gear" (sections II-III), as a first-order vector field
 * u' = f(u; p) with 10 states, its exact Jacobians, the straight-rolling
 * equilibrium and parameter validation.  Plain C11; no AUTO dependency.
 */
#ifndef MLG_MODEL_H
#define MLG_MODEL_H

#include <stddef.h>
#include "mlg_parameters.h"
#include "mlg_version.h"

/* State vector, in this order (SI units: rad, m, rad/s, m/s). */
enum mlg_state_index {
    MLG_PSI, MLG_DELTA, MLG_BETA, MLG_ETA,
    MLG_PSI_DOT, MLG_DELTA_DOT, MLG_BETA_DOT, MLG_ETA_DOT,
    MLG_LAMBDA_L, MLG_LAMBDA_R,
    MLG_NX
};

/* Continuation parameters: MLG_PAR_<name> is the 0-based index, so the
 * AUTO parameter is PAR(MLG_PAR_<name> + 1), i.e. par[MLG_PAR_<name>] in C. */
enum mlg_par_index {
#define X(name, value, unit, doc) MLG_PAR_##name,
    MLG_CONTINUATION_PARAMETERS(X)
#undef X
    MLG_NPAR
};

/* Derivative columns of mlg_rhs_jacobian: the states, then PAR(1..MLG_NPAR). */
enum { MLG_NDIR = MLG_NX + MLG_NPAR };

/* PAR slots read and written by mlg_params_set_par / _get_par: PAR(1) to
 * PAR(MLG_PAR_CONSTANTS_FILE), which hold the continuation parameters and
 * the switches with an AUTO slot (mlg_parameters.h: the PAR layout). */
enum { MLG_PAR_SLOTS = MLG_PAR_CONSTANTS_FILE };

/* Values of the eom_terms switch (docs/model.md, section 8). */
enum mlg_eom_terms {
    MLG_EOM_PRINTED = 0,     /* eqs. (1)-(4), (9), (12), (16) as printed */
    MLG_EOM_SIDESTAY = 1,    /* + the terms that vanish for p = 0 (identical at rho = mu = 0) */
    MLG_EOM_COMPLETE = 2     /* + the p-independent completions: the full Lagrangian */
};

/* The fixed constants and the switches: what the model reads as plain
 * numbers.  The continuation parameters are not in it, so the model code
 * cannot read one without its derivatives (c/model_parameters.h). */
#define MLG_CONSTANT_FIELDS                                                        \
    MLG_CONSTANTS(MLG_CONSTANT_FIELD)                                              \
    MLG_SWITCHES(MLG_SWITCH_FIELD)
#define MLG_CONSTANT_FIELD(name, value, unit, doc) double name;
#define MLG_SWITCH_FIELD(name, par, value, unit, doc) double name;
typedef struct {
    MLG_CONSTANT_FIELDS
} mlg_constants;

/* Every parameter: the continuation parameters, then mlg_constants, whose
 * fields are also members of mlg_params itself (p->r is p->constants.r). */
typedef struct {
#define X(name, value, unit, doc) double name;
    MLG_CONTINUATION_PARAMETERS(X)
#undef X
    union {
        mlg_constants constants;
        struct {
            MLG_CONSTANT_FIELDS
        };
    };
} mlg_params;

/* Status bits of an evaluation: the state lies outside the model's domain,
 * or an input or the result is not finite. */
enum mlg_status {
    MLG_OK = 0,
    MLG_ETA_OUT_OF_STROKE = 1,   /* eta <= 0 or eta >= z_tlk0: strut beyond its stroke */
    MLG_WHEEL_LIFT_OFF = 2,      /* a tyre load F_i < 0 (negative tyre deflection) */
    MLG_TYRE_BOTTOMED = 4,       /* tyre deflection d_i >= 2 r */
    MLG_NOT_FINITE = 8,          /* a state component or the result is NaN or infinite */
    MLG_BAD_PARAMETER = 16       /* a parameter is NaN or infinite, or a switch not one
                                    of its values (mlg_params_check names it) */
};

/* ---- parameter sets (parameters.c) ---- */
mlg_params mlg_params_table(void);    /* the paper as printed (Table 1 etc.) */
mlg_params mlg_params_figures(void);  /* as `table`, c_psi calibrated (docs/model.md) */
extern const double MLG_C_PSI_FIGURES;

/* Look-ups by name; return NULL / -1 for an unknown name. */
int mlg_params_field_count(void);                  /* doubles in mlg_params */
const char *mlg_state_name(int index);             /* "psi", ...; NULL if out of range */
double *mlg_param_ref(mlg_params *p, const char *name);
int mlg_par_index(const char *name);               /* 0-based, or -1 */
const char *mlg_par_name(int index);               /* NULL if out of range or unused */
int mlg_par_slot_count(void);                      /* MLG_PAR_SLOTS */
const char *mlg_constant_name(int index);          /* every field of mlg_params, in order */
const char *mlg_measure_name(int index);           /* MLG_MEASURES, in order; NULL after */
/* par[0..MLG_PAR_SLOTS-1]: the continuation parameters and the AUTO switches */
void mlg_params_set_par(mlg_params *p, const double *par);
void mlg_params_get_par(const mlg_params *p, double *par);

/* 0 if physically meaningful; otherwise nonzero, with a message naming the
 * offending parameter written to msg (if msg != NULL). */
int mlg_params_check(const mlg_params *p, char *msg, size_t msg_size);
/* Apply a file of constant overrides, one "name value" per line ('#' starts
 * a comment): 0, or nonzero with a message naming the file, line or name.
 * Only constants and test switches: PAR holds the continuation parameters. */
int mlg_params_read_constants(mlg_params *p, const char *path, char *msg, size_t msg_size);
/* Text for a status value returned by the evaluations. */
const char *mlg_status_text(int status);

/* ---- vector field (vector_field_value.c, vector_field_jacobian.c) ---- */
/* f = du/dt.  Returns an mlg_status (0 = OK).  f is filled in either case
 * but is meaningless unless the status is 0. */
int mlg_rhs(const mlg_params *p, const double u[MLG_NX], double f[MLG_NX]);

/* f, dfdu (column-major, dfdu[i + MLG_NX*j] = df_i/du_j) and, if dfdp is not
 * NULL, dfdp[i + MLG_NX*k] = df_i/dPAR(k+1) in PAR units (y_fp in mm ...). */
int mlg_rhs_jacobian(const mlg_params *p, const double u[MLG_NX], double f[MLG_NX],
                     double dfdu[MLG_NX * MLG_NX], double dfdp[MLG_NX * MLG_NPAR]);

/* ---- higher derivatives, exact to rounding (vector_field_taylor.c) ---- */
/* The highest derivative: the fifth, for Kuznetsov's E of the second
 * Lyapunov coefficient */
enum { MLG_TAYLOR_ORDER = 5 };
int mlg_taylor_order(void);   /* MLG_TAYLOR_ORDER, for callers through an FFI */
/* f[i + MLG_NX*k] = d^k/dt^k f_i(u + t d) at t = 0, k = 0..MLG_TAYLOR_ORDER:
 * f, J d, D^2 f[d, d], ..., by Taylor arithmetic along d. */
int mlg_rhs_taylor(const mlg_params *p, const double u[MLG_NX], const double d[MLG_NX],
                   double f[(MLG_TAYLOR_ORDER + 1) * MLG_NX]);
/* The n-th multilinear form of f at u (1 <= n <= MLG_TAYLOR_ORDER, else
 * MLG_BAD_PARAMETER) for real arguments v[0..n-1]:
 * F_i = sum d^n f_i/du_j1..du_jn v[0]_j1 ... v[n-1]_jn (Kuznetsov's B, C, D,
 * E for n = 2..5), from 2^(n-1) calls of mlg_rhs_taylor.  Complex arguments
 * by linearity, from the real and imaginary parts. */
int mlg_form(const mlg_params *p, const double u[MLG_NX], int n, const double *const v[],
             double F[MLG_NX]);
/* mlg_form for n = 2 and 3: B(x, y) and C(x, y, z) */
int mlg_second_form(const mlg_params *p, const double u[MLG_NX], const double x[MLG_NX],
                    const double y[MLG_NX], double B[MLG_NX]);
int mlg_third_form(const mlg_params *p, const double u[MLG_NX], const double x[MLG_NX],
                   const double y[MLG_NX], const double z[MLG_NX], double C[MLG_NX]);

/* Intermediate quantities of one evaluation, for tests and reports, in SI
 * units: generated from MLG_DIAGNOSTICS (c/mlg_parameters.h); the drivers
 * read the layout through mlg_diagnostic_name / _size. */
#define MLG_DIAGNOSTIC_FIELD_1(name) double name;
#define MLG_DIAGNOSTIC_FIELD_2(name) double name[2];
typedef struct {
#define X(name, n) MLG_DIAGNOSTIC_FIELD_##n(name)
    MLG_DIAGNOSTICS(X)
#undef X
} mlg_diagnostics;
int mlg_diagnose(const mlg_params *p, const double u[MLG_NX], mlg_diagnostics *out);
const char *mlg_diagnostic_name(int index);   /* MLG_DIAGNOSTICS, in order; NULL after */
int mlg_diagnostic_size(int index);           /* its doubles, 1 or 2; 0 after */

/* ---- mechanical energy of the model's Lagrangian (energy.c; docs/model.md 8) ---- */
/* T and V of the reduced model; V's strut part is the integral of F_keta from
 * eta_ref.  The complete equations (eom_terms = 2) conserve T + V when the
 * tyres (tyre_forces = 0) and the dampers (c_psi, c_beta, zeta_delta, c_eta*)
 * are off.  Returns an mlg_status. */
typedef struct {
    double kinetic, potential;
} mlg_energy_parts;
int mlg_energy(const mlg_params *p, const double u[MLG_NX], double eta_ref,
               mlg_energy_parts *out);

/* ---- freeplay, in plain doubles for plots and boundaries (vector_field_value.c; epsilon in parameters.c) ---- */
double mlg_r_tlk(const mlg_params *p, double eta);                 /* m */
/* Torque-link moment divided by r_tlk, i.e. force [N], for deflection y_tlk [m]
 * under freeplay law `law` (freeplay_laws.h; 0 is eq. 15): its eps_m > 0
 * form, or the non-smooth eq. (14) if eps_m == 0; NaN for an unknown law. */
double mlg_torque_link_force(int law, double k_tlk, double y_tlk, double yfp_m, double eps_m);
/* epsilon in metres for the parameters in force: (eps_abs + eps_rel y_fp) mm */
double mlg_epsilon_m(const mlg_params *p);

/* ---- freeplay laws by name (freeplay_laws.c) ---- */
int mlg_freeplay_law_count(void);
const char *mlg_freeplay_law_name(int law);       /* "atan", ...; NULL if out of range */
int mlg_freeplay_law_index(const char *name);     /* or -1 */
int mlg_freeplay_law_uses_eps(int law);           /* 1 if its shape has the width eps */

/* ---- the non-smooth model in modes (vector_field_*.c, switching.c) ---- */
/* Discrete variables of the piecewise-smooth model: each takes a mode
 * (MLG_MODE_BY_STATE: the mode the state lies in). */
enum mlg_discrete { MLG_DISCRETE_FREEPLAY, MLG_DISCRETE_FRICTION, MLG_NDISCRETE };
/* The modes of the freeplay under eq. (14) */
enum mlg_freeplay_mode {
    MLG_MODE_BY_STATE = -1,
    MLG_MODE_GAP = 0,            /* |y_tlk| < y_fp: no torque-link force */
    MLG_MODE_CONTACT_POS = 1,    /* y_tlk >= y_fp: k_tlk (y_tlk - y_fp) */
    MLG_MODE_CONTACT_NEG = 2     /* y_tlk <= -y_fp: k_tlk (y_tlk + y_fp) */
};
/* The modes of the twist's seal friction under Coulomb's law (friction_law 1,
 * docs/model.md 10): sliding with the moment +-M_fric against the slip, or
 * stuck with the moment that holds the twist rate */
enum mlg_friction_mode {
    MLG_MODE_STICK = 0,          /* twist rate held: |holding moment| <= M_fric */
    MLG_MODE_SLIP_POS = 1,       /* twist rate > 0: +M_fric */
    MLG_MODE_SLIP_NEG = 2        /* twist rate < 0: -M_fric */
};
/* mlg_rhs and mlg_rhs_jacobian with each discrete variable held in the mode
 * modes[MLG_DISCRETE_...] (modes == NULL: all by state).  A mode other than
 * MLG_MODE_BY_STATE needs the law it belongs to (freeplay_law nonsmooth,
 * friction_law Coulomb), else MLG_BAD_PARAMETER.  Each mode's field extends
 * smoothly beyond its switching surfaces. */
int mlg_rhs_in_modes(const mlg_params *p, const int *modes, const double u[MLG_NX],
                     double f[MLG_NX]);
int mlg_rhs_jacobian_in_modes(const mlg_params *p, const int *modes, const double u[MLG_NX],
                              double f[MLG_NX], double dfdu[MLG_NX * MLG_NX],
                              double dfdp[MLG_NX * MLG_NPAR]);

/* The switching functions, one table (switching.c): X(name, discrete
 * variable, mode below, mode above, watched): crossing the surface h = 0
 * upwards puts the variable in `mode above`, downwards in `mode below`; h is
 * a root function while the variable is in a mode of `watched` (a mask of
 * MLG_IN(mode)), and a mode entered at a crossing is kept only if every
 * function watched in it lies on its side (mlg_switching_mode_after of
 * sign h is that mode).
 * h+- = r_tlk(eta) psi_s -+ y_fp (section III), psi_s = psi + beta sin p.
 * slip_pos, slip_neg: the twist's slip speed r_seal psi_s'; stick_pos,
 * stick_neg: the twist's acceleration psi_s'' in the mode SLIP_POS, SLIP_NEG
 * (above 0 in SLIP_POS, even M_fric cannot hold the twist: it slides up). */
#define MLG_IN(mode) (1 << (mode))
#define MLG_SWITCHING_FUNCTIONS(X)                                                        \
    X(freeplay_upper, MLG_DISCRETE_FREEPLAY, MLG_MODE_GAP, MLG_MODE_CONTACT_POS,          \
      MLG_IN(MLG_MODE_GAP) | MLG_IN(MLG_MODE_CONTACT_POS))                                \
    X(freeplay_lower, MLG_DISCRETE_FREEPLAY, MLG_MODE_CONTACT_NEG, MLG_MODE_GAP,          \
      MLG_IN(MLG_MODE_CONTACT_NEG) | MLG_IN(MLG_MODE_GAP))                                \
    X(slip_pos, MLG_DISCRETE_FRICTION, MLG_MODE_STICK, MLG_MODE_SLIP_POS,                  \
      MLG_IN(MLG_MODE_SLIP_POS))                                                          \
    X(slip_neg, MLG_DISCRETE_FRICTION, MLG_MODE_SLIP_NEG, MLG_MODE_STICK,                  \
      MLG_IN(MLG_MODE_SLIP_NEG))                                                          \
    X(stick_pos, MLG_DISCRETE_FRICTION, MLG_MODE_STICK, MLG_MODE_SLIP_POS,                 \
      MLG_IN(MLG_MODE_STICK))                                                             \
    X(stick_neg, MLG_DISCRETE_FRICTION, MLG_MODE_SLIP_NEG, MLG_MODE_STICK,                 \
      MLG_IN(MLG_MODE_STICK))
enum mlg_switching_index {
#define X(name, variable, below, above, watched) MLG_SWITCH_##name,
    MLG_SWITCHING_FUNCTIONS(X)
#undef X
    MLG_NSWITCH
};
const char *mlg_switching_name(int k);             /* NULL if out of range */
int mlg_switching_variable(int k);                 /* enum mlg_discrete, or -1 */
/* The mode after crossing h_k = 0 in direction +1 (upwards) or -1 */
int mlg_switching_mode_after(int k, int direction);
/* 1 if h_k is a root function while its variable is in `mode`, else 0 */
int mlg_switching_watched(int k, int mode);
/* 1 if the parameters make switching function k part of the model (the law
 * it belongs to is selected, with nonzero freeplay or friction), else 0 */
int mlg_switching_applies(const mlg_params *p, int k);
/* h[k] and, if dh != NULL, its gradient dh[k * MLG_NX + j] = dh_k/du_j,
 * exact (forward mode), for every k (0 for the friction's where they do not
 * apply), the other discrete variables in `modes` (NULL: by state);
 * returns an mlg_status. */
int mlg_switching(const mlg_params *p, const int *modes, const double u[MLG_NX],
                  double h[MLG_NSWITCH], double dh[MLG_NSWITCH * MLG_NX]);
/* The modes of the discrete variables at the state u (modes[MLG_NDISCRETE]). */
int mlg_modes_at(const mlg_params *p, const double u[MLG_NX], int modes[MLG_NDISCRETE]);

/* ---- straight-rolling equilibrium (equilibrium.c) ---- */
/* Newton on f(u) = 0 from psi = delta = lambda = rates = 0 and the axial
 * static balance.  eta_guess <= 0 picks the smallest-eta root of the static
 * axial balance (the branch reached by loading from F* = 0).  Returns 0 on
 * convergence, else an mlg_status bit or -1 (no convergence) with u holding
 * the last iterate. */
int mlg_equilibrium(const mlg_params *p, double eta_guess, double u[MLG_NX]);

#endif
