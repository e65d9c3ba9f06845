// The "dirty state" check: an effect created, rendered and destroyed under an engine's leftover GL
// state (dirty_gl_state.hpp) gives the picture it gives in a clean context, bit for bit, and the
// engine reads its state back as it left it.
#pragma once

#include <string>

#include "child_process.hpp"

namespace pfx::validate {

void check_dirty_state(const std::string& path, const std::string& effect_id, CheckReporter& report);

}  // namespace pfx::validate
