#pragma once
// SPIR-V for Vulkan: the code generator's Vulkan GLSL (GlslDialect::kVulkan) compiled by glslang,
// Khronos' reference GLSL compiler (Debian's glslang-dev). HLSL's meaning is written once, by
// the GLSL writer; this turns its Vulkan dialect into SPIR-V 1.0 modules for Vulkan 1.0.
#include <cstdint>
#include <string>
#include <vector>

namespace pfx::fx {

enum class SpirvStage { kVertex, kFragment, kCompute };

// The module of one stage. False with glslang's messages in `log` when it does not compile (a
// compiler bug: the generator's GLSL is meant to be valid).
bool compile_spirv(const std::string& vulkan_glsl, SpirvStage stage, std::vector<std::uint32_t>& words, std::string& log);
// Frees glslang's tables (the next compile makes them again). For a library about to be unloaded
// (the FX plugin's deinit), with no compile running: unloaded with them, they would be lost.
void release_spirv_compiler();

}  // namespace pfx::fx
