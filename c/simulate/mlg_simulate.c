/* mlg_simulate: time simulation of the MLG model with SUNDIALS CVODE.
 *
 * Integrates u' = f(u; p) (c/mlg_model.h) from the straight-rolling equilibrium
 * plus a small perturbation, as in Fig. 8 of Howcroft et al. (section IV.A:
 * V = 300 m/s, F* = 0.2, zero freeplay, 15 s from near the unstable
 * equilibrium).  BDF with Newton iterations and a dense linear solver fed by
 * the exact Jacobian mlg_rhs_jacobian.  Writes the samples as CSV and prints
 * solver statistics and the settled oscillation over the last second.
 *
 * With the non-smooth freeplay law (14) (--param freeplay_law=1), or
 * Coulomb's stick-slip on the twist (--param friction_law=1 with M_fric > 0),
 * CVODE's root finding locates every crossing of the switching surfaces
 * (events.h) and the integration restarts there in the new mode; the
 * summary counts the mode changes per surface.
 *
 * Any evaluation outside the model's domain (nonzero mlg_status) stops the
 * run with an error message and exit status 1.
 *
 * Budgets: the summary keeps every sample of the last second in memory
 * (11 doubles, 88 bytes, each) and --out writes at most 280 bytes a sample.
 * A run whose buffer would exceed the memory budget (default 1024 MB,
 * --max-memory MB or MLG_SIMULATE_MAX_MEMORY_MB) or whose CSV would exceed
 * the output budget (default 1024 MB, --max-output MB or
 * MLG_SIMULATE_MAX_OUTPUT_MB) is refused before it starts, exit status 2,
 * naming the options and the budget (1 MB = 2^20 bytes).
 */
#define _POSIX_C_SOURCE 199309L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "events.h"
#include "mlg_model.h"

static const char *const STATE_NAMES[MLG_NX] = {
    "psi", "delta", "beta", "eta", "psi_dot", "delta_dot", "beta_dot", "eta_dot",
    "lambda_L", "lambda_R"};

/* Settings from the command line. */
typedef struct {
    mlg_params p;
    double t_end, dt_out, rtol, atol, psi0, delta0;
    double u0[MLG_NX];          /* --u0: the initial state, if has_u0 */
    int has_u0;
    double max_memory_mb, max_output_mb;    /* budgets (file comment) */
    int lmm;                    /* CV_BDF or CV_ADAMS */
    const char *out;
    const char *events_out;     /* --events: one row per switch crossed */
} options;

/* Data passed to the CVODE callbacks: the parameters, the modes and the
 * first failure. */
typedef struct {
    const mlg_params *p;
    events switching;           /* the modes and the switching functions that apply */
    int status;                 /* first nonzero mlg_status met, else 0 */
    double u_bad[MLG_NX];       /* the state where it was met */
} model;

static void usage(FILE *stream)
{
    fprintf(stream,
        "usage: mlg_simulate [options]\n"
        "  --set figures|table   parameter set (default figures); give it first,\n"
        "                        the options below override its values\n"
        "  --V X                 forward velocity [m/s] (default 300)\n"
        "  --Fstar X             dimensionless load F* (default 0.2)\n"
        "  --yfp X               torque-link freeplay [mm] (default 0)\n"
        "  --eps-abs X           smoothing epsilon, absolute part [mm] (default 0)\n"
        "  --eps-rel X           smoothing epsilon, part proportional to yfp (default\n"
        "                        0.1): epsilon = eps-abs + eps-rel * yfp [mm]; giving\n"
        "                        only one of the two sets the other to 0\n"
        "  --c-psi X             torsional damping [N m s/rad]\n"
        "  --strut-variant 0|1   F_keta stage order (0 monotone, 1 as printed)\n"
        "  --param NAME=X        any parameter, constant or switch by its name in\n"
        "                        c/mlg_parameters.h (e.g. rho=0.1, eom_terms=2)\n"
        "  --t-end X             final time [s] (default 15)\n"
        "  --dt-out X            output interval [s] (default 1e-3); at most --t-end,\n"
        "                        and at most 1e8 samples up to --t-end\n"
        "  --rtol X, --atol X    CVODE tolerances (default 1e-8, 1e-10)\n"
        "  --method bdf|adams    CVODE multistep method (default bdf; adams keeps the\n"
        "                        energy of conservative runs best)\n"
        "  --psi0 X              perturbation of psi added to the equilibrium [rad]\n"
        "                        (default 1e-3)\n"
        "  --delta0 X            perturbation of delta [rad] (default 0)\n"
        "  --u0 X,X,...          the initial state itself, all 10 states in the CSV's\n"
        "                        order (e.g. a point of an AUTO orbit), instead of the\n"
        "                        equilibrium; --psi0 and --delta0 default to 0 then\n"
        "  --out FILE            CSV output (default: none)\n"
        "  --events FILE         CSV of the switches crossed (freeplay law nonsmooth):\n"
        "                        t, the switching function, its direction (+1 up),\n"
        "                        the mode after it and the state there\n"
        "  --max-memory MB       memory budget of the last second's samples (default\n"
        "                        1024, or MLG_SIMULATE_MAX_MEMORY_MB): a run needing more\n"
        "                        (88 bytes a sample) is refused before it starts\n"
        "  --max-output MB       size budget of the --out CSV (default 1024, or\n"
        "                        MLG_SIMULATE_MAX_OUTPUT_MB; at most 280 bytes a sample)\n");
}

static double parse_number(const char *option, const char *text)
{
    char *end;
    errno = 0;
    double value = strtod(text, &end);
    if (errno != 0 || end == text || *end != '\0') {
        fprintf(stderr, "mlg_simulate: %s needs a number, got '%s'\n", option, text);
        exit(2);
    }
    return value;
}

/* --u0 X,X,...: exactly MLG_NX finite numbers separated by commas */
static void parse_state(const char *option, const char *text, double u[MLG_NX])
{
    const char *at = text;
    for (int i = 0; i < MLG_NX; i++) {
        char *end;
        errno = 0;
        u[i] = strtod(at, &end);
        int last = i == MLG_NX - 1;
        if (errno != 0 || end == at || !isfinite(u[i]) || *end != (last ? '\0' : ',')) {
            fprintf(stderr, "mlg_simulate: %s needs %d finite numbers separated by commas "
                            "(%s, ..., %s), got '%s'\n", option, MLG_NX, STATE_NAMES[0],
                    STATE_NAMES[MLG_NX - 1], text);
            exit(2);
        }
        at = end + 1;
    }
}

/* --param NAME=VALUE: any field of mlg_params, by name; returns the field */
static double *set_named(mlg_params *p, const char *arg)
{
    char name[64];
    const char *eq = strchr(arg, '=');
    size_t len = eq != NULL ? (size_t)(eq - arg) : 0;
    if (len == 0 || len >= sizeof name) {
        fprintf(stderr, "mlg_simulate: --param needs NAME=VALUE, got '%s'\n", arg);
        exit(2);
    }
    memcpy(name, arg, len);
    name[len] = '\0';
    double *ref = mlg_param_ref(p, name);
    if (ref == NULL) {
        fprintf(stderr, "mlg_simulate: --param: no parameter named '%s'\n", name);
        exit(2);
    }
    *ref = parse_number("--param", eq + 1);
    return ref;
}

/* Stop with exit status 2 and a message naming the option. */
static void refuse(const char *fmt, double a, double b)
{
    fprintf(stderr, "mlg_simulate: ");
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    exit(2);
}

enum { MAX_SAMPLES = 100000000 };

/* Budgets (file comment): defaults in MB, and the bytes one sample takes in
 * the summary's buffer (tail) and at most in the CSV (write_row: "%.12g"
 * time, 19 characters at most, then 10 ",%.17e", 26 at most, and '\n'). */
#define DEFAULT_MAX_MEMORY_MB 1024.0
#define DEFAULT_MAX_OUTPUT_MB 1024.0
#define TAIL_SAMPLE_BYTES ((double)((1 + MLG_NX) * sizeof(double)))
#define CSV_SAMPLE_BYTES (19.0 + MLG_NX * 26.0 + 1.0)
#define MB (1024.0 * 1024.0)

/* Output samples after t = 0 (main's loop), and an upper bound on those the
 * summary keeps: the last second's, with the t = 0 sample when t_end <= 1. */
static double output_samples(double t_end, double dt_out)
{
    return ceil(t_end / dt_out - 1e-9);
}

static double tail_samples(double t_end, double dt_out)
{
    return fmin(output_samples(t_end, dt_out), floor(fmin(1.0, t_end) / dt_out) + 2.0) + 1.0;
}

/* A budget in MB: > 0 and finite, else exit status 2 naming where it came from. */
static double parse_budget(const char *what, const char *text)
{
    double value = parse_number(what, text);
    if (!(value > 0.0 && isfinite(value))) {
        fprintf(stderr, "mlg_simulate: %s %s must be > 0 and finite (MB)\n", what, text);
        exit(2);
    }
    return value;
}

static double budget_from_env(const char *name, double fallback)
{
    const char *text = getenv(name);
    return text != NULL && *text != '\0' ? parse_budget(name, text) : fallback;
}

static options parse_options(int argc, char **argv)
{
    options o = {.t_end = 15.0, .dt_out = 1e-3, .rtol = 1e-8, .atol = 1e-10,
                 .psi0 = 1e-3, .delta0 = 0.0, .lmm = CV_BDF, .out = NULL};
    o.max_memory_mb = budget_from_env("MLG_SIMULATE_MAX_MEMORY_MB", DEFAULT_MAX_MEMORY_MB);
    o.max_output_mb = budget_from_env("MLG_SIMULATE_MAX_OUTPUT_MB", DEFAULT_MAX_OUTPUT_MB);
    o.p = mlg_params_figures();
    o.p.V = 300.0;
    o.p.Fstar = 0.2;
    int eps_abs_given = 0, eps_rel_given = 0, psi0_given = 0, delta0_given = 0;

    for (int k = 1; k < argc; k++) {
        const char *opt = argv[k];
        if (strcmp(opt, "--help") == 0 || strcmp(opt, "-h") == 0) {
            usage(stdout);
            exit(0);
        }
        if (k + 1 >= argc) {
            fprintf(stderr, "mlg_simulate: %s needs a value\n", opt);
            usage(stderr);
            exit(2);
        }
        const char *arg = argv[++k];
        if (strcmp(opt, "--set") == 0) {
            double V = o.p.V, Fstar = o.p.Fstar;
            if (strcmp(arg, "figures") == 0)
                o.p = mlg_params_figures();
            else if (strcmp(arg, "table") == 0)
                o.p = mlg_params_table();
            else {
                fprintf(stderr, "mlg_simulate: --set must be figures or table, got '%s'\n", arg);
                exit(2);
            }
            o.p.V = V;
            o.p.Fstar = Fstar;
        }
        else if (strcmp(opt, "--V") == 0) o.p.V = parse_number(opt, arg);
        else if (strcmp(opt, "--Fstar") == 0) o.p.Fstar = parse_number(opt, arg);
        else if (strcmp(opt, "--yfp") == 0) o.p.yfp = parse_number(opt, arg);
        else if (strcmp(opt, "--eps-abs") == 0) {
            o.p.eps_abs = parse_number(opt, arg);
            eps_abs_given = 1;
        }
        else if (strcmp(opt, "--eps-rel") == 0) {
            o.p.eps_rel = parse_number(opt, arg);
            eps_rel_given = 1;
        }
        else if (strcmp(opt, "--c-psi") == 0) o.p.c_psi = parse_number(opt, arg);
        else if (strcmp(opt, "--strut-variant") == 0) o.p.strut_variant = parse_number(opt, arg);
        else if (strcmp(opt, "--param") == 0) {
            const double *ref = set_named(&o.p, arg);
            eps_abs_given |= ref == &o.p.eps_abs;
            eps_rel_given |= ref == &o.p.eps_rel;
        }
        else if (strcmp(opt, "--method") == 0) {
            if (strcmp(arg, "bdf") != 0 && strcmp(arg, "adams") != 0) {
                fprintf(stderr, "mlg_simulate: --method must be bdf or adams, got '%s'\n", arg);
                exit(2);
            }
            o.lmm = strcmp(arg, "bdf") == 0 ? CV_BDF : CV_ADAMS;
        }
        else if (strcmp(opt, "--t-end") == 0) o.t_end = parse_number(opt, arg);
        else if (strcmp(opt, "--dt-out") == 0) o.dt_out = parse_number(opt, arg);
        else if (strcmp(opt, "--rtol") == 0) o.rtol = parse_number(opt, arg);
        else if (strcmp(opt, "--atol") == 0) o.atol = parse_number(opt, arg);
        else if (strcmp(opt, "--psi0") == 0) {
            o.psi0 = parse_number(opt, arg);
            psi0_given = 1;
        }
        else if (strcmp(opt, "--delta0") == 0) {
            o.delta0 = parse_number(opt, arg);
            delta0_given = 1;
        }
        else if (strcmp(opt, "--u0") == 0) {
            parse_state(opt, arg, o.u0);
            o.has_u0 = 1;
        }
        else if (strcmp(opt, "--out") == 0) o.out = arg;
        else if (strcmp(opt, "--events") == 0) o.events_out = arg;
        else if (strcmp(opt, "--max-memory") == 0) o.max_memory_mb = parse_budget(opt, arg);
        else if (strcmp(opt, "--max-output") == 0) o.max_output_mb = parse_budget(opt, arg);
        else {
            fprintf(stderr, "mlg_simulate: unknown option %s\n", opt);
            usage(stderr);
            exit(2);
        }
    }

    /* a given initial state is perturbed only as asked */
    if (o.has_u0 && !psi0_given) o.psi0 = 0.0;
    if (o.has_u0 && !delta0_given) o.delta0 = 0.0;
    /* epsilon is what was given: one part alone sets the other to 0 */
    if (eps_abs_given && !eps_rel_given) o.p.eps_rel = 0.0;
    if (eps_rel_given && !eps_abs_given) o.p.eps_abs = 0.0;

    char msg[256];
    if (mlg_params_check(&o.p, msg, sizeof msg) != 0) {
        fprintf(stderr, "mlg_simulate: %s\n", msg);
        exit(2);
    }
    if (!(o.t_end > 0.0 && isfinite(o.t_end))) refuse("--t-end %g must be > 0 and finite", o.t_end, 0);
    if (!(o.dt_out > 0.0 && o.dt_out <= o.t_end))
        refuse("--dt-out %g must be > 0 and at most --t-end %g: no output sample", o.dt_out,
               o.t_end);
    if (o.t_end / o.dt_out > MAX_SAMPLES)
        refuse("--t-end %g / --dt-out %g exceeds the limit of 1e8 output samples", o.t_end,
               o.dt_out);
    if (!(o.rtol > 0.0 && isfinite(o.rtol))) refuse("--rtol %g must be > 0 and finite", o.rtol, 0);
    if (!(o.atol > 0.0 && isfinite(o.atol))) refuse("--atol %g must be > 0 and finite", o.atol, 0);
    if (!isfinite(o.psi0)) refuse("--psi0 %g must be finite", o.psi0, 0);
    if (!isfinite(o.delta0)) refuse("--delta0 %g must be finite", o.delta0, 0);

    double kept = tail_samples(o.t_end, o.dt_out);
    if (kept * TAIL_SAMPLE_BYTES > o.max_memory_mb * MB) {
        fprintf(stderr, "mlg_simulate: --t-end %g with --dt-out %g keeps %.0f samples of the run's "
                        "last second in memory (%.0f MB for the settled-oscillation summary), "
                        "over the memory budget of %g MB: give a larger --dt-out, or raise "
                        "the budget with --max-memory MB (or MLG_SIMULATE_MAX_MEMORY_MB)\n",
                o.t_end, o.dt_out, kept, ceil(kept * TAIL_SAMPLE_BYTES / MB), o.max_memory_mb);
        exit(2);
    }
    double rows = output_samples(o.t_end, o.dt_out) + 1.0;
    if (o.out != NULL && rows * CSV_SAMPLE_BYTES > o.max_output_mb * MB) {
        fprintf(stderr, "mlg_simulate: --out %s with --t-end %g and --dt-out %g writes %.0f "
                        "samples, up to %.0f MB of CSV, over the output budget of %g MB: give "
                        "a larger --dt-out or a shorter --t-end, or raise the budget with "
                        "--max-output MB (or MLG_SIMULATE_MAX_OUTPUT_MB)\n",
                o.out, o.t_end, o.dt_out, rows, ceil(rows * CSV_SAMPLE_BYTES / MB),
                o.max_output_mb);
        exit(2);
    }
    return o;
}

/* CVODE right-hand side; a state outside the model's domain is fatal (-1). */
static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *data)
{
    (void)t;
    model *m = data;
    const double *u = N_VGetArrayPointer(y);
    int status = mlg_rhs_in_modes(m->p, m->switching.modes, u, N_VGetArrayPointer(ydot));
    if (status != MLG_OK) {
        m->status = status;
        memcpy(m->u_bad, u, sizeof m->u_bad);
        return -1;
    }
    return 0;
}

/* CVODE root functions: the switching functions that apply */
static int roots(sunrealtype t, N_Vector y, sunrealtype *g, void *data)
{
    (void)t;
    model *m = data;
    const double *u = N_VGetArrayPointer(y);
    int status = events_values(&m->switching, u, g);
    if (status != MLG_OK) {
        m->status = status;
        memcpy(m->u_bad, u, sizeof m->u_bad);
        return -1;
    }
    return 0;
}

/* CVODE Jacobian: the exact df/du, column-major like SUNDenseMatrix. */
static int jacobian(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *data,
                    N_Vector tmp1, N_Vector tmp2, N_Vector tmp3)
{
    (void)t; (void)fy; (void)tmp1; (void)tmp2; (void)tmp3;
    model *m = data;
    const double *u = N_VGetArrayPointer(y);
    double f[MLG_NX], dfdu[MLG_NX * MLG_NX];
    int status = mlg_rhs_jacobian_in_modes(m->p, m->switching.modes, u, f, dfdu, NULL);
    if (status != MLG_OK) {
        m->status = status;
        memcpy(m->u_bad, u, sizeof m->u_bad);
        return -1;
    }
    for (int j = 0; j < MLG_NX; j++)
        memcpy(SM_COLUMN_D(J, j), dfdu + MLG_NX * j, MLG_NX * sizeof(double));
    return 0;
}

static void check_flag(int flag, const char *call)
{
    if (flag < 0) {
        fprintf(stderr, "mlg_simulate: %s failed: %s\n", call, CVodeGetReturnFlagName(flag));
        exit(1);
    }
}

/* Samples of the last second, for the settled-oscillation summary. */
typedef struct {
    size_t n, cap;
    double *t, *u;              /* u[MLG_NX * k + i] */
} tail;

/* Room for n samples up front (the budget checked for it in parse_options),
 * so that the buffer is allocated once, not doubled. */
static void tail_reserve(tail *s, size_t n)
{
    s->t = malloc(n * sizeof *s->t);
    s->u = malloc(n * MLG_NX * sizeof *s->u);
    if (s->t == NULL || s->u == NULL) {
        fprintf(stderr, "mlg_simulate: out of memory (%zu samples of the last second)\n", n);
        exit(1);
    }
    s->cap = n;
}

static void tail_add(tail *s, double t, const double *u)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 1024;
        s->t = realloc(s->t, s->cap * sizeof *s->t);
        s->u = realloc(s->u, s->cap * MLG_NX * sizeof *s->u);
        if (s->t == NULL || s->u == NULL) {
            fprintf(stderr, "mlg_simulate: out of memory\n");
            exit(1);
        }
    }
    s->t[s->n] = t;
    memcpy(s->u + MLG_NX * s->n, u, MLG_NX * sizeof *u);
    s->n++;
}

/* Mean and half peak-to-peak of one state over the samples.  While the
 * amplitude still grows the mean drifts (beta and eta in Fig. 8), and the
 * half peak-to-peak includes that drift. */
typedef struct {
    double mean, amplitude;
} oscillation;

static oscillation tail_oscillation(const tail *s, int i)
{
    double lo = INFINITY, hi = -INFINITY, sum = 0.0;
    for (size_t k = 0; k < s->n; k++) {
        double v = s->u[MLG_NX * k + i];
        lo = fmin(lo, v);
        hi = fmax(hi, v);
        sum += v;
    }
    return (oscillation){sum / (double)s->n, 0.5 * (hi - lo)};
}

/* Frequency from the upward zero crossings of psi - mean (linear
 * interpolation between samples); 0 if fewer than two crossings. */
static double tail_frequency(const tail *s, double psi_mean)
{
    double first = 0.0, last = 0.0;
    int crossings = 0;
    for (size_t k = 1; k < s->n; k++) {
        double a = s->u[MLG_NX * (k - 1) + MLG_PSI] - psi_mean;
        double b = s->u[MLG_NX * k + MLG_PSI] - psi_mean;
        if (a < 0.0 && b >= 0.0) {
            double tc = s->t[k - 1] + (s->t[k] - s->t[k - 1]) * a / (a - b);
            if (crossings == 0)
                first = tc;
            last = tc;
            crossings++;
        }
    }
    return crossings >= 2 ? (crossings - 1) / (last - first) : 0.0;
}

/* CVODE's counters, summed over the restarts at switches */
typedef struct {
    long steps, rhs_evals, jac_evals, ls_rhs_evals, setups, err_fails, conv_fails;
} statistics;

static void add_statistics(void *cvode, statistics *s)
{
    long n;
    CVodeGetNumSteps(cvode, &n), s->steps += n;
    CVodeGetNumRhsEvals(cvode, &n), s->rhs_evals += n;
    CVodeGetNumJacEvals(cvode, &n), s->jac_evals += n;
    CVodeGetNumLinRhsEvals(cvode, &n), s->ls_rhs_evals += n;
    CVodeGetNumLinSolvSetups(cvode, &n), s->setups += n;
    CVodeGetNumErrTestFails(cvode, &n), s->err_fails += n;
    CVodeGetNumNonlinSolvConvFails(cvode, &n), s->conv_fails += n;
}

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void write_row(FILE *csv, double t, const double *u)
{
    fprintf(csv, "%.12g", t);
    for (int i = 0; i < MLG_NX; i++)
        fprintf(csv, ",%.17e", u[i]);
    fputc('\n', csv);
}

int main(int argc, char **argv)
{
    options o = parse_options(argc, argv);

    double u0[MLG_NX];
    if (o.has_u0) {
        memcpy(u0, o.u0, sizeof u0);
    } else {
        int eq = mlg_equilibrium(&o.p, 0.0, u0);
        if (eq != 0) {
            fprintf(stderr, "mlg_simulate: no straight-rolling equilibrium at V = %g, F* = %g "
                            "(code %d: %s)\n", o.p.V, o.p.Fstar, eq,
                    eq > 0 ? mlg_status_text(eq) : "Newton did not converge");
            return 1;
        }
        printf("equilibrium_beta_rad %.10e\nequilibrium_eta_m %.10e\n", u0[MLG_BETA],
               u0[MLG_ETA]);
    }
    u0[MLG_PSI] += o.psi0;
    u0[MLG_DELTA] += o.delta0;

    FILE *csv = NULL;
    if (o.out != NULL) {
        csv = fopen(o.out, "w");
        if (csv == NULL) {
            fprintf(stderr, "mlg_simulate: cannot write %s: %s\n", o.out, strerror(errno));
            return 1;
        }
        fputs("t", csv);
        for (int i = 0; i < MLG_NX; i++)
            fprintf(csv, ",%s", STATE_NAMES[i]);
        fputc('\n', csv);
        write_row(csv, 0.0, u0);
    }

    FILE *crossed = NULL;
    if (o.events_out != NULL) {
        crossed = fopen(o.events_out, "w");
        if (crossed == NULL) {
            fprintf(stderr, "mlg_simulate: cannot write %s: %s\n", o.events_out,
                    strerror(errno));
            return 1;
        }
        fputs("t,switch,direction,mode", crossed);
        for (int i = 0; i < MLG_NX; i++)
            fprintf(crossed, ",%s", STATE_NAMES[i]);
        fputc('\n', crossed);
    }

    model m = {.p = &o.p, .status = MLG_OK};
    if (events_init(&m.switching, &o.p, u0) != MLG_OK) {
        fprintf(stderr, "mlg_simulate: the initial state lies outside the model's domain\n");
        return 1;
    }
    SUNContext ctx;
    if (SUNContext_Create(NULL, &ctx) != 0) {
        fprintf(stderr, "mlg_simulate: SUNContext_Create failed\n");
        return 1;
    }
    N_Vector y = N_VNew_Serial(MLG_NX, ctx);
    memcpy(N_VGetArrayPointer(y), u0, sizeof u0);
    SUNMatrix J = SUNDenseMatrix(MLG_NX, MLG_NX, ctx);
    SUNLinearSolver LS = SUNLinSol_Dense(y, J, ctx);
    void *cvode = CVodeCreate(o.lmm, ctx);    /* default nonlinear solver: Newton */
    if (y == NULL || J == NULL || LS == NULL || cvode == NULL) {
        fprintf(stderr, "mlg_simulate: cannot create the CVODE solver\n");
        return 1;
    }
    check_flag(CVodeInit(cvode, rhs, 0.0, y), "CVodeInit");
    check_flag(CVodeSStolerances(cvode, o.rtol, o.atol), "CVodeSStolerances");
    check_flag(CVodeSetUserData(cvode, &m), "CVodeSetUserData");
    check_flag(CVodeSetLinearSolver(cvode, LS, J), "CVodeSetLinearSolver");
    check_flag(CVodeSetJacFn(cvode, jacobian), "CVodeSetJacFn");
    check_flag(CVodeSetMaxNumSteps(cvode, 1000000), "CVodeSetMaxNumSteps");
    check_flag(CVodeSetStopTime(cvode, o.t_end), "CVodeSetStopTime");
    if (m.switching.count > 0)
        check_flag(CVodeRootInit(cvode, m.switching.count, roots), "CVodeRootInit");

    statistics stats = {0};
    tail settled = {0};
    tail_reserve(&settled, (size_t)tail_samples(o.t_end, o.dt_out));
    double t_tail = fmax(0.0, o.t_end - 1.0);
    if (t_tail == 0.0)
        tail_add(&settled, 0.0, u0);

    double start = seconds_now();
    long n_out = (long)output_samples(o.t_end, o.dt_out);
    for (long k = 1; k <= n_out; k++) {
        double t_want = fmin(k * o.dt_out, o.t_end), t;
        int flag = CVode(cvode, t_want, y, &t, CV_NORMAL);
        while (flag == CV_ROOT_RETURN) {   /* a switch: on in the new mode */
            int found[MLG_NSWITCH];
            check_flag(CVodeGetRootInfo(cvode, found), "CVodeGetRootInfo");
            int changed = events_cross(&m.switching, found, N_VGetArrayPointer(y));
            if (changed < 0) {
                fprintf(stderr, "mlg_simulate: switching failed at t = %.6g s: %s\n", t,
                        mlg_status_text(-changed));
                return 1;
            }
            for (int i = 0; crossed != NULL && i < m.switching.count; i++) {
                if (found[i] == 0) continue;
                int k = m.switching.index[i];
                fprintf(crossed, "%.17e,%s,%d,%d", t, mlg_switching_name(k), found[i],
                        m.switching.modes[mlg_switching_variable(k)]);
                for (int j = 0; j < MLG_NX; j++)
                    fprintf(crossed, ",%.17e", N_VGetArrayPointer(y)[j]);
                fputc('\n', crossed);
            }
            add_statistics(cvode, &stats);     /* CVodeReInit zeroes CVODE's own */
            check_flag(CVodeReInit(cvode, t, y), "CVodeReInit");
            flag = CVode(cvode, t_want, y, &t, CV_NORMAL);
        }
        if (flag < 0) {
            if (m.status != MLG_OK) {
                fprintf(stderr, "mlg_simulate: model evaluation failed near t = %.6g s: %s\n",
                        t, mlg_status_text(m.status));
                fprintf(stderr, "  state:");
                for (int i = 0; i < MLG_NX; i++)
                    fprintf(stderr, " %s=%.6g", STATE_NAMES[i], m.u_bad[i]);
                fputc('\n', stderr);
            } else {
                fprintf(stderr, "mlg_simulate: CVode failed at t = %.6g s: %s\n",
                        t, CVodeGetReturnFlagName(flag));
            }
            if (csv != NULL)
                fclose(csv);
            return 1;
        }
        const double *u = N_VGetArrayPointer(y);
        if (csv != NULL)
            write_row(csv, t, u);
        if (t >= t_tail - 1e-12)
            tail_add(&settled, t, u);
    }
    double wall = seconds_now() - start;
    if (csv != NULL && fclose(csv) != 0) {
        fprintf(stderr, "mlg_simulate: error writing %s\n", o.out);
        return 1;
    }

    if (crossed != NULL && fclose(crossed) != 0) {
        fprintf(stderr, "mlg_simulate: error writing %s\n", o.events_out);
        return 1;
    }
    add_statistics(cvode, &stats);

    oscillation osc[MLG_ETA + 1];
    for (int i = MLG_PSI; i <= MLG_ETA; i++)
        osc[i] = tail_oscillation(&settled, i);

    /* key value lines, read by mlgshimmy.figures.fig08 and tests/model/test_simulate.py */
    printf("V %.10g\nFstar %.10g\nyfp %.10g\nc_psi %.10g\n", o.p.V, o.p.Fstar, o.p.yfp, o.p.c_psi);
    printf("epsilon_mm %.10g\n", 1e3 * mlg_epsilon_m(&o.p));
    printf("t_end %.10g\n", o.t_end);
    printf("steps %ld\nrhs_evals %ld\njac_evals %ld\nfd_rhs_evals %ld\n",
           stats.steps, stats.rhs_evals, stats.jac_evals, stats.ls_rhs_evals);
    printf("lin_setups %ld\nerr_test_fails %ld\nnonlin_conv_fails %ld\n",
           stats.setups, stats.err_fails, stats.conv_fails);
    printf("wall_time_s %.6f\n", wall);
    printf("window_start_s %.10g\nwindow_samples %zu\n", t_tail, settled.n);
    for (int i = MLG_PSI; i <= MLG_ETA; i++) {
        const char *unit = i == MLG_ETA ? "m" : "rad";
        printf("%s_mean_%s %.10e\n", STATE_NAMES[i], unit, osc[i].mean);
        printf("%s_amplitude_%s %.10e\n", STATE_NAMES[i], unit, osc[i].amplitude);
    }
    printf("frequency_hz %.8f\n", tail_frequency(&settled, osc[MLG_PSI].mean));
    for (int i = 0; i < m.switching.count; i++) {
        int k = m.switching.index[i];
        printf("crossings_%s %ld\n", mlg_switching_name(k), m.switching.crossings[k]);
    }

    free(settled.t);
    free(settled.u);
    CVodeFree(&cvode);
    SUNLinSolFree(LS);
    SUNMatDestroy(J);
    N_VDestroy(y);
    SUNContext_Free(&ctx);
    return 0;
}
