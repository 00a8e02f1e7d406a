/* Parameter sets, look-up by name and validation. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "mlg_model.h"
#include "params_unusable.h"

/* c_psi of the `figures` set: the value that puts the zero-freeplay Hopf
 * point at F* = 1 at the paper's V = 346.1 m/s, found by AUTO continuation of that
 * Hopf point in (V, c_psi): `make calibrate` (mlgshimmy.studies.calibrate_c_psi). */
const double MLG_C_PSI_FIGURES = 724.0034;

mlg_params mlg_params_table(void)
{
    mlg_params p = {
#define X(name, value, unit, doc) .name = (value),
        MLG_CONTINUATION_PARAMETERS(X)
        MLG_CONSTANTS(X)
#undef X
#define X(name, par, value, unit, doc) .name = (value),
        MLG_SWITCHES(X)
#undef X
    };
    return p;
}

mlg_params mlg_params_figures(void)
{
    mlg_params p = mlg_params_table();
    p.c_psi = MLG_C_PSI_FIGURES;
    return p;
}

static const char *const par_names[MLG_NPAR] = {
#define X(name, value, unit, doc) #name,
    MLG_CONTINUATION_PARAMETERS(X)
#undef X
};

_Static_assert(MLG_NPAR < MLG_PAR_PERIOD,
               "MLG_CONTINUATION_PARAMETERS do not fit in PAR(1-10): PAR(11) is AUTO's period "
               "(move a quantity that is not continued to MLG_CONSTANTS; docs/model.md 2.1)");
/* PAR(11) and PAR(12) are AUTO's; PAR(MLG_PAR_CONSTANTS_FILE) names the constants file */
#define X(name, par, value, unit, doc)                                                   \
    _Static_assert((par) == 0 || ((par) > 12 && (par) < MLG_PAR_CONSTANTS_FILE),         \
                   "switch " #name ": its AUTO slot must lie in PAR(13-14)");
MLG_SWITCHES(X)
#undef X
_Static_assert(MLG_PAR_CONSTANTS_FILE < MLG_MEASURES_FIRST_PAR, "PAR slots overlap the measures");

int mlg_params_field_count(void)
{
    return (int)(sizeof(mlg_params) / sizeof(double));
}

const char *mlg_state_name(int index)
{
    static const char *const names[MLG_NX] = {"psi", "delta", "beta", "eta", "psi_dot",
                                              "delta_dot", "beta_dot", "eta_dot", "lambda_L",
                                              "lambda_R"};
    return index >= 0 && index < MLG_NX ? names[index] : NULL;
}

double *mlg_param_ref(mlg_params *p, const char *name)
{
#define X(field, value, unit, doc) if (strcmp(name, #field) == 0) return &p->field;
    MLG_CONTINUATION_PARAMETERS(X)
    MLG_CONSTANTS(X)
#undef X
#define X(field, par, value, unit, doc) if (strcmp(name, #field) == 0) return &p->field;
    MLG_SWITCHES(X)
#undef X
    return NULL;
}

int mlg_par_index(const char *name)
{
    for (int k = 0; k < MLG_PAR_SLOTS; k++) {
        const char *known = mlg_par_name(k);
        if (known != NULL && strcmp(name, known) == 0) return k;
    }
    return -1;
}

const char *mlg_constant_name(int index)
{
    static const char *const names[] = {
#define X(name, value, unit, doc) #name,
        MLG_CONTINUATION_PARAMETERS(X)
        MLG_CONSTANTS(X)
#undef X
#define X(name, par, value, unit, doc) #name,
        MLG_SWITCHES(X)
#undef X
    };
    return index >= 0 && index < (int)(sizeof names / sizeof names[0]) ? names[index] : NULL;
}

const char *mlg_measure_name(int index)
{
    static const char *const names[] = {
#define X(name, kind, state, unit, doc) #name,
        MLG_MEASURES(X)
#undef X
    };
    return index >= 0 && index < (int)(sizeof names / sizeof names[0]) ? names[index] : NULL;
}

const char *mlg_par_name(int index)
{
    if (index >= 0 && index < MLG_NPAR) return par_names[index];
    if (index == MLG_PAR_CONSTANTS_FILE - 1) return "constants";
#define X(name, slot, value, unit, doc) if ((slot) > 0 && index == (slot) - 1) return #name;
    MLG_SWITCHES(X)
#undef X
    return NULL;
}

int mlg_par_slot_count(void)
{
    return MLG_PAR_SLOTS;
}

void mlg_params_set_par(mlg_params *p, const double *par)
{
#define X(name, value, unit, doc) p->name = par[MLG_PAR_##name];
    MLG_CONTINUATION_PARAMETERS(X)
#undef X
#define X(name, slot, value, unit, doc) if ((slot) > 0) p->name = par[(slot) - 1];
    MLG_SWITCHES(X)
#undef X
}

void mlg_params_get_par(const mlg_params *p, double *par)
{
#define X(name, value, unit, doc) par[MLG_PAR_##name] = p->name;
    MLG_CONTINUATION_PARAMETERS(X)
#undef X
#define X(name, slot, value, unit, doc) if ((slot) > 0) par[(slot) - 1] = p->name;
    MLG_SWITCHES(X)
#undef X
}

double mlg_epsilon_m(const mlg_params *p)
{
    return 1e-3 * (p->eps_abs + p->eps_rel * p->yfp);
}

static int reject(char *msg, size_t n, const char *fmt, ...)
{
    if (msg != NULL && n > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, n, fmt, ap);
        va_end(ap);
    }
    return 1;
}

int mlg_params_unusable(const mlg_params *p, char *msg, size_t n)
{
    /* every value finite */
#define X(name, value, unit, doc)                                               \
    if (!isfinite(p->name))                                                     \
        return reject(msg, n, "parameter %s is not finite (%g)", #name, p->name);
    MLG_CONTINUATION_PARAMETERS(X)
    MLG_CONSTANTS(X)
#undef X
#define X(name, par, value, unit, doc)                                          \
    if (!isfinite(p->name))                                                     \
        return reject(msg, n, "parameter %s is not finite (%g)", #name, p->name);
    MLG_SWITCHES(X)
#undef X
    if (p->eom_terms != MLG_EOM_PRINTED && p->eom_terms != MLG_EOM_SIDESTAY &&
        p->eom_terms != MLG_EOM_COMPLETE)
        return reject(msg, n, "parameter eom_terms = %g must be 0 (as printed), 1 (side-stay "
                      "corrections) or 2 (complete Lagrangian)", p->eom_terms);
    if (p->tyre_forces != 0.0 && p->tyre_forces != 1.0)
        return reject(msg, n, "parameter tyre_forces = %g must be 0 or 1", p->tyre_forces);
    if (p->strut_variant != 0.0 && p->strut_variant != 1.0)
        return reject(msg, n, "parameter strut_variant = %g must be 0 (monotone) or 1 "
                      "(as printed)", p->strut_variant);
    if (!(p->freeplay_law >= 0.0 && p->freeplay_law < mlg_freeplay_law_count() &&
          p->freeplay_law == (int)p->freeplay_law))
        return reject(msg, n, "parameter freeplay_law = %g must be the index of a law in "
                      "c/freeplay_laws.h (0 to %d)", p->freeplay_law,
                      mlg_freeplay_law_count() - 1);
    if (p->friction_law != 0.0 && p->friction_law != 1.0)
        return reject(msg, n, "parameter friction_law = %g must be 0 (tanh-regularised) or 1 "
                      "(Coulomb with stick)", p->friction_law);
    return 0;
}

int mlg_params_check(const mlg_params *p, char *msg, size_t n)
{
    if (mlg_params_unusable(p, msg, n)) return 1;
    if (!(p->k_tlk > 0.0))
        return reject(msg, n, "parameter k_tlk = %g N/m: stiffness must be > 0", p->k_tlk);
    /* every continuation parameter but an angle is a size, speed, load or
     * coefficient: >= 0 (the table's unit and description make the message) */
#define X(name, value, unit, doc)                                                   \
    if (strcmp(unit, "rad") != 0 && p->name < 0.0)                                  \
        return reject(msg, n, "parameter %s = %g%s%s: %s must be >= 0", #name, p->name, \
                      strcmp(unit, "-") != 0 ? " " : "", strcmp(unit, "-") != 0 ? unit : "", doc);
    MLG_CONTINUATION_PARAMETERS(X)
#undef X
    if (p->yfp > 0.0 && !(mlg_epsilon_m(p) > 0.0) &&
        mlg_freeplay_law_uses_eps((int)p->freeplay_law))
        return reject(msg, n,
                      "parameter eps_abs/eps_rel: smoothing epsilon = %g mm must be > 0 "
                      "when yfp = %g mm > 0 (freeplay law %s needs epsilon > 0)",
                      p->eps_abs + p->eps_rel * p->yfp, p->yfp,
                      mlg_freeplay_law_name((int)p->freeplay_law));
    if (fabs(p->rho) >= 0.5 * MLG_PI)
        return reject(msg, n, "parameter rho = %g rad: side-stay inclination must lie in "
                      "(-pi/2, pi/2)", p->rho);
    if (fabs(p->mu) >= 0.5 * MLG_PI)
        return reject(msg, n, "parameter mu = %g rad: side-stay orientation must lie in "
                      "(-pi/2, pi/2)", p->mu);
    {
        /* sin p (docs/model.md 4.13); |p| -> pi/2 makes I_beta = 0 (degenerate) */
        double sp = sin(p->rho) * cos(p->phi0) - cos(p->rho) * sin(p->mu) * sin(p->phi0);
        if (fabs(sp) > 0.99)
            return reject(msg, n, "parameters rho = %g, mu = %g rad: side-stay angle p = %g "
                          "rad makes the gear geometry degenerate (cos p ~ 0)",
                          p->rho, p->mu, asin(fmax(-1.0, fmin(1.0, sp))));
    }
    if (p->F_fric < 0.0)
        return reject(msg, n, "parameter F_fric = %g N must be >= 0", p->F_fric);
    if (p->friction_law == 1.0 && p->F_fric != 0.0)   /* stick-slip is built for the twist */
        return reject(msg, n, "parameter F_fric = %g N must be 0 with friction_law = 1: "
                      "Coulomb's law with stick acts on the twist only", p->F_fric);
    if (p->F_tyre_min < 0.0)
        return reject(msg, n, "parameter F_tyre_min = %g N must be >= 0", p->F_tyre_min);
    if (!(p->eta_stage >= 0.0 && p->eta_stage < p->z_tlk0))   /* a position in the stroke */
        return reject(msg, n, "parameter eta_stage = %g m: the strut's stage switch must lie "
                      "in the stroke [0, z_tlk0 = %g m)", p->eta_stage, p->z_tlk0);
#define POSITIVE(name)                                                            \
    if (!(p->name > 0.0)) return reject(msg, n, "parameter %s = %g must be > 0", #name, p->name);
    POSITIVE(a) POSITIVE(l_tlk) POSITIVE(r) POSITIVE(M) POSITIVE(I_psi) POSITIVE(I)
    POSITIVE(k_beta) POSITIVE(g_0) POSITIVE(m_0) POSITIVE(a_d) POSITIVE(b_d)
    POSITIVE(v_fric) POSITIVE(r_seal)
#undef POSITIVE
    if (!(p->phi0 > -0.5 * MLG_PI && p->phi0 < 0.5 * MLG_PI))
        return reject(msg, n, "parameter phi0 = %g rad: rake angle must lie in (-pi/2, pi/2)",
                      p->phi0);
    if (msg != NULL && n > 0) msg[0] = '\0';
    return 0;
}

int mlg_params_read_constants(mlg_params *p, const char *path, char *msg, size_t n)
{
    FILE *in = fopen(path, "r");
    if (in == NULL) return reject(msg, n, "cannot read %s", path);
    char line[256];
    int number = 0, bad = 0;
    while (!bad && fgets(line, sizeof line, in) != NULL) {
        number++;
        char name[64], extra[2];
        double value;
        char *hash = strchr(line, '#');
        if (hash != NULL) *hash = '\0';
        int fields = sscanf(line, "%63s %lf %1s", name, &value, extra);
        if (fields == EOF) continue;                          /* blank or comment */
        double *ref = mlg_param_ref(p, name);
        if (fields != 2)
            bad = reject(msg, n, "%s line %d: expected \"name value\"", path, number);
        else if (ref == NULL)
            bad = reject(msg, n, "%s line %d: no constant named %s", path, number, name);
        else if (!isfinite(value))
            bad = reject(msg, n, "%s line %d: %s = %g is not finite", path, number, name, value);
        else if (mlg_par_index(name) >= 0)
            bad = reject(msg, n, "%s line %d: %s is PAR(%d): set it there", path, number, name,
                         mlg_par_index(name) + 1);
        else
            *ref = value;
    }
    fclose(in);
    return bad;
}

const char *mlg_status_text(int status)
{
    if (status == MLG_OK) return "ok";
    if (status & MLG_BAD_PARAMETER)
        return "a parameter is not finite or a switch not one of its values (mlg_params_check "
               "names it)";
    if (status & MLG_NOT_FINITE) return "the state or the result is not finite";
    if (status & MLG_ETA_OUT_OF_STROKE) return "strut compression eta outside (0, z_tlk0)";
    if (status & MLG_WHEEL_LIFT_OFF) return "a wheel lifts off (negative tyre load)";
    if (status & MLG_TYRE_BOTTOMED) return "tyre deflection exceeds the tyre diameter";
    return "unknown status";
}
