/* The vector field in plain doubles (the model of vector_field.h, DUAL_N = 0). */
#define DUAL_N 0
#include "vector_field.h"

static void load_state(const double u[MLG_NX], dual x[MLG_NX])
{
    for (int i = 0; i < MLG_NX; i++) x[i] = d_const(u[i]);
}

int mlg_rhs_in_modes(const mlg_params *p, const int *modes, const double u[MLG_NX],
                     double f[MLG_NX])
{
    dual x[MLG_NX], fx[MLG_NX];
    load_state(u, x);
    int status = vector_field(p, x, modes, MLG_PARS_PLAIN, fx, NULL);
    for (int i = 0; i < MLG_NX; i++) f[i] = fx[i].v;
    return status;
}

int mlg_rhs(const mlg_params *p, const double u[MLG_NX], double f[MLG_NX])
{
    return mlg_rhs_in_modes(p, NULL, u, f);
}

int mlg_diagnose(const mlg_params *p, const double u[MLG_NX], mlg_diagnostics *out)
{
    dual x[MLG_NX], fx[MLG_NX];
    load_state(u, x);
    return vector_field(p, x, NULL, MLG_PARS_PLAIN, fx, out);
}

/* the drivers read mlg_diagnostics as a flat array of doubles */
#define X(name, n) + (n)
_Static_assert(sizeof(mlg_diagnostics) == (0 MLG_DIAGNOSTICS(X)) * sizeof(double),
               "mlg_diagnostics is not a packed array of doubles");
#undef X

const char *mlg_diagnostic_name(int index)
{
    static const char *const names[] = {
#define X(name, n) #name,
        MLG_DIAGNOSTICS(X)
#undef X
    };
    return index >= 0 && index < (int)(sizeof names / sizeof names[0]) ? names[index] : NULL;
}

int mlg_diagnostic_size(int index)
{
    static const int sizes[] = {
#define X(name, n) n,
        MLG_DIAGNOSTICS(X)
#undef X
    };
    return index >= 0 && index < (int)(sizeof sizes / sizeof sizes[0]) ? sizes[index] : 0;
}

double mlg_r_tlk(const mlg_params *p, double eta)
{
    return torque_link_radius(&p->constants, d_const(p->z_tlk0 - eta)).v;
}

double mlg_torque_link_force(int law, double k_tlk, double y_tlk, double yfp_m, double eps_m)
{
    if (law < 0 || law >= MLG_FREEPLAY_NLAWS) return NAN;
    return torque_link_force(law, MLG_MODE_BY_STATE, d_const(k_tlk), d_const(y_tlk),
                             d_const(yfp_m), d_const(eps_m)).v;
}
