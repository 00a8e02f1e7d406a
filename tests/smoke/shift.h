/* Extra library for the smoke model: stands in for the real model library
   (build/lib/libmlg.a) to test that a model linked against a static library
   is what AUTO runs. */
#ifndef SMOKE_SHIFT_H
#define SMOKE_SHIFT_H

/* Parameter value of the Hopf bifurcation of the smoke model: sqrt(2). */
double smoke_hopf_value(void);

#endif
