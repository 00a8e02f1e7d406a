/* Every freeplay law of c/freeplay_laws.h: its exact derivatives (dual, in
 * y, y_fp and eps) against Richardson-extrapolated central differences at
 * points on both sides of every corner (|y| = y_fp, y_fp +- eps) and
 * between them; odd symmetry; the limit eq. (14) as eps -> 0 (error at most
 * k eps); the torque links' potential of mlg_energy, whose slope in psi must
 * be r_tlk times the law's force. */
#define DUAL_N 3
#include "freeplay_laws.h"
#include "unit.h"

enum { DY, DYFP, DEPS };

static dual law_at(int law, double y, double yfp, double eps)
{
    return torque_link_force(law, MLG_MODE_BY_STATE, d_const(3.9e7), d_var(y, DY),
                             d_var(yfp, DYFP), d_var(eps, DEPS));
}

/* central difference of the force in direction dir with step h, extrapolated */
static double difference(int law, double y, double yfp, double eps, int dir, double h)
{
    double q[2];
    for (int k = 0; k < 2; k++) {
        double s = k == 0 ? h : 0.5 * h, v[2];
        for (int sign = 0; sign < 2; sign++) {
            double d = sign ? s : -s;
            v[sign] = law_at(law, y + (dir == DY) * d, yfp + (dir == DYFP) * d,
                             eps + (dir == DEPS) * d).v;
        }
        q[k] = (v[1] - v[0]) / (2.0 * s);
    }
    return (4.0 * q[1] - q[0]) / 3.0;
}

int main(void)
{
    const double k = 3.9e7;
    /* offsets from a corner, in eps: on both sides, well beyond the step */
    static const double offsets[] = {-5.0, -1.5, -1.001, -0.999, -0.5, -1e-3, 1e-3, 0.5,
                                     0.999, 1.001, 1.5, 5.0};
    const int n_off = (int)(sizeof offsets / sizeof offsets[0]);
    for (int law = 0; law < mlg_freeplay_law_count(); law++) {
        double worst = 0.0, odd = 0.0, limit = 0.0;
        int points = 0;
        for (int c = 0; c < 3; c++) {
            double yfp = c == 0 ? 1e-3 : c == 1 ? 2e-4 : 5e-5;
            double eps = c == 0 ? 1e-4 : c == 1 ? 0.7e-4 : 1.3e-4;   /* eps < y_fp and > */
            for (int corner = -1; corner <= 1; corner++)
                for (int i = 0; i < n_off; i++)
                    for (int side = -1; side <= 1; side += 2) {
                        double y = side * (yfp + corner * eps + offsets[i] * eps);
                        dual F = law_at(law, y, yfp, eps);
                        for (int dir = DY; dir <= DEPS; dir++) {
                            double fd = difference(law, y, yfp, eps, dir, 1e-6 * eps);
                            worst = fmax(worst, fabs(d_slope(F, dir) - fd) / k);
                        }
                        odd = fmax(odd, fabs(F.v + law_at(law, -y, yfp, eps).v) / (k * eps));
                        points++;
                    }
        }
        for (int i = 0; i <= 200; i++) {   /* eq. (14) as eps -> 0 */
            double y = -3e-3 + 6e-3 * i / 200.0, eps = 1e-6;
            double exact = mlg_torque_link_force(law, k, y, 1e-3, 0.0);
            limit = fmax(limit, fabs(mlg_torque_link_force(law, k, y, 1e-3, eps) - exact) / (k * eps));
        }
        const char *name = mlg_freeplay_law_name(law);
        char what[80];
        snprintf(what, sizeof what, "law_%s_derivatives_match_differences", name);
        check(worst <= 1e-6, what, "%d points around the corners, max |exact - fd| / k_tlk "
              "= %.2e over d/dy, d/dy_fp, d/deps", points, worst);
        snprintf(what, sizeof what, "law_%s_odd", name);
        check(odd <= 1e-12, what, "max |F(y) + F(-y)| / (k eps) = %.2e", odd);
        snprintf(what, sizeof what, "law_%s_tends_to_eq14", name);
        check(limit <= 1.0, what, "max |F_eps - F_eq14| / (k eps) = %.3f at eps = 1e-3 y_fp",
              limit);
    }

    /* the potential: d V / d psi = r_tlk F(r_tlk psi) at rho = mu = 0, for every
     * law, deflections inside, at and beyond the freeplay */
    for (int law = 0; law < mlg_freeplay_law_count(); law++) {
        mlg_params p = mlg_params_figures();
        p.Fstar = 1.0;
        p.yfp = 1.0;
        p.freeplay_law = law;
        double u[MLG_NX];
        mlg_equilibrium(&p, -1.0, u);
        double r = mlg_r_tlk(&p, u[MLG_ETA]), worst = 0.0;
        for (int i = 1; i <= 40; i++) {
            double y = 2.5e-3 * (i - 0.5) / 40.0, h = 1e-7 / r;   /* no corner in a stencil */
            double v[2];
            for (int sign = 0; sign < 2; sign++) {
                double w[MLG_NX];
                mlg_energy_parts e;
                for (int j = 0; j < MLG_NX; j++) w[j] = u[j];
                w[MLG_PSI] = y / r + (sign ? h : -h);
                mlg_energy(&p, w, u[MLG_ETA], &e);
                v[sign] = e.potential;
            }
            double slope = (v[1] - v[0]) / (2.0 * h);
            double want = r * mlg_torque_link_force(law, p.k_tlk, y, 1e-3, mlg_epsilon_m(&p));
            worst = fmax(worst, fabs(slope - want) / (r * p.k_tlk * 1e-4));
        }
        char what[80];
        snprintf(what, sizeof what, "law_%s_potential_slope_is_force", mlg_freeplay_law_name(law));
        check(worst <= 1e-4, what, "max |dV/dpsi - r F| / (r k_tlk 0.1 mm) = %.2e", worst);
    }
    return unit_exit();
}
