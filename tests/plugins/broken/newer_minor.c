#define BROKEN_ID "interpolator.newer-minor"
#define BROKEN_ABI_MINOR (ANI_ABI_MINOR + 1)
#include "broken_plugin.h"
