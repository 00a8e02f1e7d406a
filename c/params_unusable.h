/* The parameters an evaluation cannot read (parameters.c). */
#ifndef MLG_PARAMS_UNUSABLE_H
#define MLG_PARAMS_UNUSABLE_H

#include "mlg_model.h"

/* What every evaluation checks before it reads the parameters (it casts
 * eom_terms to int): 0 if every value is finite and every switch one of its
 * values, else 1 with a message naming the parameter (if msg != NULL; none
 * is formatted otherwise).  mlg_params_check's first test. */
int mlg_params_unusable(const mlg_params *p, char *msg, size_t msg_size);

#endif
