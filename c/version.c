/* The library's version (c/mlg_version.h). */
#include "mlg_model.h"

const char *mlg_version(void)
{
    return MLG_VERSION;
}
