/* Reaches up into host/: caught. */
#include "../../host/shared.h"
