#define BROKEN_ID "Bad Id!"
#include "broken_plugin.h"
