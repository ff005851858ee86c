#define BROKEN_ID "interpolator.bad-kind"
#define BROKEN_KIND 42
#include "broken_plugin.h"
