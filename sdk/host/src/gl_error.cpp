#include "pfx/host/gl_error.hpp"

#include <cstdio>

namespace pfx::host {

std::string gl_error_text(uint32_t error) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04x", static_cast<unsigned>(error));
  return text;
}

}  // namespace pfx::host
