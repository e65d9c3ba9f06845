/* A host tool: may use sdk/. */
#include "../sdk/api.h"
