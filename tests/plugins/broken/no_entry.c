#define BROKEN_ID "interpolator.no-entry"
#define BROKEN_NO_ENTRY 1
#include "broken_plugin.h"
