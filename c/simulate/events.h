/* Event location for the piecewise-smooth model: the switching functions of
 * mlg_model.h (MLG_SWITCHING_FUNCTIONS) that apply at the parameters, given
 * to CVODE as root functions, and the modes of the discrete variables they
 * change.  The integration restarts at each crossing in the new mode: each
 * mode's field is smooth, so no step straddles a switch.  A mechanism with
 * switching functions (freeplay law (14), the twist's Coulomb stick-slip)
 * joins through the library's table alone: its rows say which functions are
 * watched in which mode. */
#ifndef MLG_SIMULATE_EVENTS_H
#define MLG_SIMULATE_EVENTS_H

#include "mlg_model.h"

typedef struct {
    const mlg_params *p;
    int modes[MLG_NDISCRETE];    /* MLG_MODE_BY_STATE where no switching applies */
    int count;                   /* the switching functions that apply ... */
    int index[MLG_NSWITCH];      /* ... and their indices in the table */
    long crossings[MLG_NSWITCH]; /* mode changes, per switching function */
} events;

/* The switching functions that apply at p, and the modes of the state u0. */
int events_init(events *e, const mlg_params *p, const double u0[MLG_NX]);
/* CVODE's root functions g[0..count-1] at u (1 where not watched in the
 * present modes); an mlg_status */
int events_values(const events *e, const double u[MLG_NX], double *g);
/* After CVODE located roots at u (its rootsfound: +1 upwards, -1 downwards,
 * 0 none): the new modes, settled; returns the number of mode changes, or
 * minus an mlg_status */
int events_cross(events *e, const int *rootsfound, const double u[MLG_NX]);

#endif
