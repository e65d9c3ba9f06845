#pragma once
// A slang pass's SPIR-V as GLSL 4.50 for an OpenGL 4.5 context, by SPIRV-Cross, as RetroArch's
// glcore driver and librashader's GL runtime run slang. GL has no push constants, so the push
// constant block becomes a uniform block of its own at `push_binding`; the uniform block, the
// samplers (texture units) and the stage's inputs and outputs keep the bindings and locations the
// shader gives them. (GL_ARB_gl_spirv would take the SPIR-V itself, but not its push constants.)
#include <cstdint>
#include <string>
#include <vector>

#include "slang_reflection.hpp"

namespace pfx::libretro {

struct GlPassCode {
  std::string vertex, fragment;
  std::uint32_t push_binding = 0;  // the uniform block binding the push constants are read from
};

// False with SPIRV-Cross's message in *error.
bool slang_pass_for_gl(const std::vector<std::uint32_t>& vertex, const std::vector<std::uint32_t>& fragment,
                       const PassInterface& pass, GlPassCode* out, std::string* error);

}  // namespace pfx::libretro
