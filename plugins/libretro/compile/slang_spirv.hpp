#pragma once
// A slang shader's stage (Vulkan GLSL 4.50, slang_source.hpp) compiled to SPIR-V for Vulkan 1.0 by
// Debian's glslang, the Khronos reference compiler that RetroArch and librashader compile slang
// with. Its messages name the files and lines the code was written at (the stage's #line
// directives). The SPIR-V is what the reflection reads and what a Vulkan runtime would run.
#include <cstdint>
#include <string>
#include <vector>

namespace pfx::libretro {

enum class SlangStage { kVertex, kFragment };

// False with glslang's messages in *log.
bool compile_slang_stage(const std::string& code, SlangStage stage, std::vector<std::uint32_t>* words,
                         std::string* log);

// Frees glslang's tables (made at the first compile); for a library about to be unloaded.
void release_slang_compiler();

}  // namespace pfx::libretro
