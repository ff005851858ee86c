/* declares the id of the .ani plugin, which is already loaded */
#define BROKEN_ID "format.ani"
#include "broken_plugin.h"
