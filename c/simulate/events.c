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

/* 1 if switching function k is a root function in the present modes */
static int watched(const events *e, int k)
{
    return mlg_switching_watched(k, e->modes[mlg_switching_variable(k)]);
}

int events_values(const events *e, const double u[MLG_NX], double *g)
{
    double h[MLG_NSWITCH];
    int status = mlg_switching(e->p, e->modes, u, h, NULL);
    for (int i = 0; i < e->count; i++)   /* a constant: no crossing while unwatched */
        g[i] = watched(e, e->index[i]) ? h[e->index[i]] : 1.0;
    return status;
}

/* A mode entered holds while every function watched in it lies on its side;
 * one that does not (stick entered where even M_fric cannot hold the twist)
 * hands on to the mode on the side it lies.  Each pass leaves a mode for
 * good (stick -> slip, never back at the same state), so MLG_NSWITCH passes
 * bound it. */
static int settle(events *e, const double u[MLG_NX])
{
    int moved = 0;
    for (int pass = 0; pass < MLG_NSWITCH; pass++) {
        double h[MLG_NSWITCH];
        int status = mlg_switching(e->p, e->modes, u, h, NULL), changed = 0;
        if (status != MLG_OK) return -status;
        for (int i = 0; i < e->count && !changed; i++) {
            int k = e->index[i], v = mlg_switching_variable(k);
            if (!watched(e, k) || h[k] == 0.0) continue;
            int side = mlg_switching_mode_after(k, h[k] > 0.0 ? 1 : -1);
            if (side != e->modes[v]) {
                e->modes[v] = side;
                e->crossings[k]++;
                changed = moved = 1;
            }
        }
        if (!changed) return moved;
    }
    return moved;
}

int events_cross(events *e, const int *rootsfound, const double u[MLG_NX])
{
    int crossed = 0;
    for (int i = 0; i < e->count; i++) {
        if (rootsfound[i] == 0) continue;
        int k = e->index[i];
        e->modes[mlg_switching_variable(k)] = mlg_switching_mode_after(k, rootsfound[i]);
        e->crossings[k]++;
        crossed++;
    }
    int moved = settle(e, u);
    return moved < 0 ? moved : crossed + moved;
}
