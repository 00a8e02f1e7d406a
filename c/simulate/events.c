/* Event location (events.h). */
#include "events.h"

int events_init(events *e, const mlg_params *p, const double u0[MLG_NX])
{
    int at[MLG_NDISCRETE], switched[MLG_NDISCRETE] = {0};
    e->p = p;
    e->count = 0;
    for (int k = 0; k < MLG_NSWITCH; k++) {
        e->crossings[k] = 0;
        if (mlg_switching_applies(p, k)) {
            e->index[e->count++] = k;
            switched[mlg_switching_variable(k)] = 1;
        }
    }
    int status = mlg_modes_at(p, u0, at);
    for (int v = 0; v < MLG_NDISCRETE; v++)
        e->modes[v] = switched[v] ? at[v] : MLG_MODE_BY_STATE;
    return status;
}

int events_values(const events *e, const double u[MLG_NX], double *g)
{
    double h[MLG_NSWITCH];
    int status = mlg_switching(e->p, u, h, NULL);
    for (int i = 0; i < e->count; i++) g[i] = h[e->index[i]];
    return status;
}

int events_cross(events *e, const int *rootsfound)
{
    int crossed = 0;
    for (int i = 0; i < e->count; i++) {
        if (rootsfound[i] == 0) continue;
        int k = e->index[i];
        e->modes[mlg_switching_variable(k)] = mlg_switching_mode_after(k, rootsfound[i]);
        e->crossings[k]++;
        crossed++;
    }
    return crossed;
}
