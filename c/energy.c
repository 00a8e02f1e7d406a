/* Mechanical energy of the model's Lagrangian (docs/model.md, section 8):
 * the quantity that the complete equations (eom_terms = 2) conserve when
 * the tyres and all dampers are switched off. */
#include "mlg_model.h"
#define DUAL_N 0
#include "vector_field.h"

/* The integral of force(ctx, x) from a to b: 5-point Gauss-Legendre on
 * equal panels no wider than `panel` (at most 1e6 of them); the integrands
 * here have no elementary antiderivative, or none for every law. */
static double integral(double (*force)(const void *, double), const void *ctx, double a,
                       double b, double panel)
{
    static const double node[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                   0.5384693101056831, 0.9061798459386640};
    static const double weight[5] = {0.2369268850561891, 0.4786286704993665,
                                     0.5688888888888889, 0.4786286704993665,
                                     0.2369268850561891};
    int panels = 1 + (int)fmin(fabs(b - a) / panel, 1e6);
    double h = (b - a) / panels, sum = 0.0;
    for (int k = 0; k < panels; k++) {
        double mid = a + (k + 0.5) * h;
        for (int j = 0; j < 5; j++) sum += weight[j] * force(ctx, mid + 0.5 * h * node[j]);
    }
    return 0.5 * h * sum;
}

static double strut_force(const void *c, double eta)
{
    return strut_spring_force(c, d_const(eta)).v;
}

static double link_force(const void *mp, double y)
{
    const model_parameters *m = mp;
    return torque_link_force((int)m->c->freeplay_law, MLG_MODE_BY_STATE, m->k_tlk, d_const(y),
                             m->yfp, m->eps).v;
}

/* The torque links' potential: the integral of the law's force from 0 to y,
 * split where a law may bend (|y| = y_fp, y_fp +- eps) so that each piece
 * is smooth, on panels of eps/16 */
static double link_potential(const model_parameters *mp, double y)
{
    double yfp = mp->yfp.v, eps = mp->eps.v, s = y < 0.0 ? -1.0 : 1.0;
    double bends[4] = {yfp - eps, yfp, yfp + eps, fabs(y)}, from = 0.0, sum = 0.0;
    double panel = eps > 0.0 ? eps / 16.0 : fmax(fabs(y), 1e-300);
    for (int k = 0; k < 4; k++) {
        double to = fmin(fmax(bends[k], from), fabs(y));
        sum += integral(link_force, mp, s * from, s * to, panel);
        from = to;
    }
    return sum;
}

int mlg_energy(const mlg_params *p, const double u[MLG_NX], double eta_ref,
               mlg_energy_parts *out)
{
    const double psi = u[MLG_PSI], delta = u[MLG_DELTA], beta = u[MLG_BETA], eta = u[MLG_ETA];
    const double psi_dot = u[MLG_PSI_DOT], delta_dot = u[MLG_DELTA_DOT];
    const double beta_dot = u[MLG_BETA_DOT], eta_dot = u[MLG_ETA_DOT];
    dual x[MLG_NX];
    for (int i = 0; i < MLG_NX; i++) x[i] = d_const(u[i]);
    int status = domain_status(p, x);
    if (status != MLG_OK) return status;
    if (!(eta_ref > 0.0 && eta_ref < p->z_tlk0)) return MLG_ETA_OUT_OF_STROKE;
    model_parameters mp = model_parameters_seed(p, MLG_PARS_PLAIN);
    sidestay g = sidestay_geometry(&mp);
    double sin_p = g.sin_p.v, cos_p = g.cos_p.v;
    double psi_s = psi + beta * sin_p, theta_a = psi_s + g.m.v;       /* after eq. (6) */
    strut_lengths l = strut_lengths_at(mp.c, d_const(eta));
    structure s = structure_at(mp.c, &g, &l, d_const(eta), d_const(theta_a));
    pose q;
    pose_at(&q, &mp, &g, &l, d_const(psi), d_const(delta), d_const(beta));
    double I_a = s.I_a.v, L_beta = l.L_beta.v;

    /* kinetic: torsion, strut bending about u_delta and about u_beta, the axle's
     * rotation W normal to itself in the plane normal to the strut, modal mass */
    double I_delta_strut = s.I_delta.v - I_a * cos(theta_a) * cos(theta_a);
    double W = delta_dot * cos(theta_a) - beta_dot * sin(theta_a) * cos_p;
    double H_dot = -eta_dot * q.cos_phi.v + L_beta * q.dcos_phi.v * beta_dot;
    out->kinetic = 0.5 * (p->I_psi * psi_dot * psi_dot + I_delta_strut * delta_dot * delta_dot
                          + s.I_beta.v * beta_dot * beta_dot + I_a * W * W
                          + p->M * H_dot * H_dot);

    /* potential: lateral and longitudinal springs, torque links, oleo, load F_z at height H */
    double r_tlk = torque_link_radius(mp.c, l.z_tlk).v;
    double links = link_potential(&mp, r_tlk * psi_s);
    double strut = integral(strut_force, mp.c, eta_ref, eta, 1e-4);   /* 0.1 mm panels */
    out->potential = 0.5 * (s.k_delta.v * delta * delta + p->k_beta * beta * beta) + links
                     + strut + mp.F_z.v * L_beta * q.cos_phi.v;
    return isfinite(out->kinetic) && isfinite(out->potential) ? MLG_OK : MLG_NOT_FINITE;
}
