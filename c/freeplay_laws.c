/* The freeplay laws of freeplay_laws.h by name. */
#include <string.h>

#define DUAL_N 0
#include "freeplay_laws.h"

static const char *const law_names[MLG_FREEPLAY_NLAWS] = {
#define X(name, uses_eps, doc) #name,
    MLG_FREEPLAY_LAWS(X)
#undef X
};

static const int law_uses_eps[MLG_FREEPLAY_NLAWS] = {
#define X(name, uses_eps, doc) uses_eps,
    MLG_FREEPLAY_LAWS(X)
#undef X
};

int mlg_freeplay_law_count(void)
{
    return MLG_FREEPLAY_NLAWS;
}

const char *mlg_freeplay_law_name(int law)
{
    return law >= 0 && law < MLG_FREEPLAY_NLAWS ? law_names[law] : NULL;
}

int mlg_freeplay_law_index(const char *name)
{
    for (int law = 0; law < MLG_FREEPLAY_NLAWS; law++)
        if (strcmp(name, law_names[law]) == 0) return law;
    return -1;
}

int mlg_freeplay_law_uses_eps(int law)
{
    return law >= 0 && law < MLG_FREEPLAY_NLAWS ? law_uses_eps[law] : 0;
}
