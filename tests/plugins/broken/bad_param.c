#define BROKEN_ID "interpolator.bad-param"
#define BROKEN_PARAM_MIN 2.0 /* min > max */
#include "broken_plugin.h"
