/* A plugin: sdk/ only, but its compile command names host/ (caught). */
#include "../sdk/api.h"
