// GL errors in messages, written the same way by libpfxhost and the programs around it.
#pragma once

#include <cstdint>
#include <string>

#include "pfx/host/api.hpp"

namespace pfx::host {

// A glGetError() value as the messages give it: "0x0502" (GL_INVALID_OPERATION).
PFX_HOST_API std::string gl_error_text(uint32_t error);

}  // namespace pfx::host
