#include <math.h>

#include "shift.h"

double smoke_hopf_value(void)
{
    return sqrt(2.0);
}
