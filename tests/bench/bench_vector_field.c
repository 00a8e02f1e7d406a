/* Benchmark (not a test): CPU time of one evaluation of f, of f + df/du, of
 * f + df/du + df/dp, of f and five derivatives along a direction (Taylor),
 * and of the forms B(x, y), C(x, y, z), D and E, at representative states; ratios
 * from the same run. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "mlg_model.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);   /* CPU time: waiting for a core is not counted */
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

enum { NSTATES = 16 };
static mlg_params params;
static double states[NSTATES][MLG_NX];
static double directions[5][MLG_NX];
static volatile double sink;

enum { F, JACOBIAN, JACOBIAN_P, TAYLOR, SECOND_FORM, THIRD_FORM, FOURTH_FORM, FIFTH_FORM, NKINDS };

/* Seconds per call of one kind over about 0.05 s */
static double time_per_call(int kind)
{
    double f[(MLG_TAYLOR_ORDER + 1) * MLG_NX], J[MLG_NX * MLG_NX], P[MLG_NX * MLG_NPAR];
    const double *x = directions[0], *y = directions[1], *z = directions[2];
    const double *const v[5] = {x, y, z, directions[3], directions[4]};
    long calls = 0;
    double start = now(), elapsed;
    do {
        for (int r = 0; r < 256; r++, calls++) {
            const double *u = states[calls % NSTATES];
            if (kind == F) mlg_rhs(&params, u, f);
            else if (kind == TAYLOR) mlg_rhs_taylor(&params, u, x, f);
            else if (kind == SECOND_FORM) mlg_second_form(&params, u, x, y, f);
            else if (kind == THIRD_FORM) mlg_third_form(&params, u, x, y, z, f);
            else if (kind == FOURTH_FORM) mlg_form(&params, u, 4, v, f);
            else if (kind == FIFTH_FORM) mlg_form(&params, u, 5, v, f);
            else mlg_rhs_jacobian(&params, u, f, J, kind == JACOBIAN_P ? P : NULL);
            sink += f[MLG_PSI_DOT];
        }
        elapsed = now() - start;
    } while (elapsed < 0.05);
    return elapsed / calls;
}

/* The kinds in turn, ROUNDS times; the fastest round of each, so that
 * what load from other processes still costs (caches) drops out of the ratios. */
enum { ROUNDS = 20 };
static void time_all(double best[NKINDS])
{
    for (int kind = 0; kind < NKINDS; kind++) best[kind] = INFINITY;
    for (int round = 0; round < ROUNDS; round++)
        for (int kind = 0; kind < NKINDS; kind++) best[kind] = fmin(best[kind], time_per_call(kind));
}

int main(void)
{
    params = mlg_params_figures();
    params.V = 100.0;
    params.yfp = 1.0;
    params.eps_rel = 0.1;
    double u[MLG_NX];
    mlg_equilibrium(&params, -1.0, u);
    for (int k = 0; k < NSTATES; k++) {      /* around straight rolling, inside and outside the freeplay */
        for (int i = 0; i < MLG_NX; i++) states[k][i] = u[i];
        states[k][MLG_PSI] = (k - NSTATES / 2) * 3e-4;
        states[k][MLG_DELTA] = 1e-3 * (k % 3 - 1);
        states[k][MLG_PSI_DOT] = 0.1 * (k % 5 - 2);
        states[k][MLG_LAMBDA_L] = 1e-3 * (k % 4 - 1.5);
        states[k][MLG_LAMBDA_R] = -1e-3 * (k % 4 - 1.5);
    }
    for (int k = 0; k < 5; k++)   /* unit directions of mixed sign, as a Hopf eigenvector's parts */
        for (int i = 0; i < MLG_NX; i++) directions[k][i] = cos(1.0 + 2.0 * i + 3.0 * k);
    double best[NKINDS];
    time_all(best);
    double t_f = best[F], t_fj = best[JACOBIAN], t_fjp = best[JACOBIAN_P];
    printf("bench_vector_field: F* = 1, V = 100 m/s, y_fp = 1 mm, %d states\n", NSTATES);
    printf("  f                  %8.3f us\n", 1e6 * t_f);
    printf("  f + df/du          %8.3f us   (%.1f x f)\n", 1e6 * t_fj, t_fj / t_f);
    printf("  f + df/du + df/dp  %8.3f us   (%.1f x f)\n", 1e6 * t_fjp, t_fjp / t_f);
    printf("  f, D^1..5 f along d %7.3f us   (%.1f x f)\n", 1e6 * best[TAYLOR],
           best[TAYLOR] / t_f);
    printf("  B(x, y), exact     %8.3f us   (%.1f x f)\n", 1e6 * best[SECOND_FORM],
           best[SECOND_FORM] / t_f);
    printf("  C(x, y, z), exact  %8.3f us   (%.1f x f)\n", 1e6 * best[THIRD_FORM],
           best[THIRD_FORM] / t_f);
    printf("  D(x, y, z, w), exact %6.3f us   (%.1f x f)\n", 1e6 * best[FOURTH_FORM],
           best[FOURTH_FORM] / t_f);
    printf("  E(x, ..., v), exact %7.3f us   (%.1f x f)\n", 1e6 * best[FIFTH_FORM],
           best[FIFTH_FORM] / t_f);
    printf("  finite-difference df/du would cost %d f-evaluations (%.1f x f with one-sided steps)\n",
           MLG_NX + 1, (double)(MLG_NX + 1));
    return 0;
}
