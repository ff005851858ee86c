#include "broken_plugin.h" /* valid: the control, it must load */
