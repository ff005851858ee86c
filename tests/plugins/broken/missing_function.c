#define BROKEN_ID "interpolator.no-evaluate"
#define BROKEN_EVALUATE NULL
#include "broken_plugin.h"
