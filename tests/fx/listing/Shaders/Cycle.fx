// An #include cycle: refused with a message, not a hang.
#include "Cycle.fx"
technique Cycle { pass { } }
