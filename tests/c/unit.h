/* Minimal check helpers for the C tests: one line per check,
 * "ok <name>" or "not ok <name> - <detail>" (read by tests/model/test_c_programs.py). */
#ifndef MLG_UNIT_H
#define MLG_UNIT_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

static int unit_failed;

static inline void check(int passed, const char *name, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("%s %s - ", passed ? "ok" : "not ok", name);
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
    if (!passed) unit_failed++;
}

/* |got - want| <= rel |want| */
static inline void check_rel(const char *name, double got, double want, double rel)
{
    double err = fabs(got - want) / fabs(want);
    check(err <= rel, name, "got %.8g, want %.8g, rel. error %.2e (tolerance %.1e)", got,
          want, err, rel);
}

static inline int unit_exit(void)
{
    return unit_failed ? 1 : 0;
}

/* Reproducible uniform numbers in [0, 1) (xorshift64*). */
static unsigned long long unit_seed = 0x9E3779B97F4A7C15ULL;
static inline double unit_uniform(void)
{
    unit_seed ^= unit_seed >> 12;
    unit_seed ^= unit_seed << 25;
    unit_seed ^= unit_seed >> 27;
    return (double)((unit_seed * 0x2545F4914F6CDD1DULL) >> 11) * (1.0 / 9007199254740992.0);
}

static inline double unit_between(double lo, double hi)
{
    return lo + (hi - lo) * unit_uniform();
}

#endif
