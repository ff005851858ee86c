#define BROKEN_ID "interpolator.wrong-major"
#define BROKEN_ABI_MAJOR (ANI_ABI_MAJOR + 1)
#include "broken_plugin.h"
