// The bright pass's parameter descriptors, shared by the "bloom" and "glare" effects so both
// describe the same threshold, knee, measure and firefly clamp the same way. Functions rather than
// objects: the effects' tables are built at load time in other files, in no guaranteed order.
#pragma once

#include <pfx/params.h>

namespace pfx_bloom {

// display_default: the value display-referred frames start from (pfx_param_desc.display_default).
pfx_param_desc threshold_param(double display_default);
pfx_param_desc knee_param(double display_default);
// tooltip: the effect's own (which modes use the measure differs).
pfx_param_desc measure_param(const char* tooltip);
pfx_param_desc firefly_clamp_param();
pfx_param_desc nonfinite_param();

}  // namespace pfx_bloom
