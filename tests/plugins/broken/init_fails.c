#define BROKEN_ID "interpolator.init-fails"
#define BROKEN_INIT_CODE ANI_ERR_FAILED
#include "broken_plugin.h"
