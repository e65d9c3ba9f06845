#pragma once
// A libretro shader in the GLSL form (.glsl, what .glslp presets name): one file for both stages,
// compiled twice as RetroArch's gl driver compiles it, once with `#define VERTEX` and once with
// `#define FRAGMENT`, each time with `#define PARAMETER_UNIFORM` ahead of the code.
// `#pragma parameter` lines describe the shader's parameters as in slang and are blanked (their
// quotes are not GLSL). The form has no includes, names or formats.
//
// The version: a file written for GLSL 1.40 or later keeps its `#version`. One without a
// `#version` line, or with an older one (1.10 to 1.30, written for GL 2 and compatibility
// contexts, which a core context refuses), is compiled as GLSL 3.30 core, as RetroArch compiles a
// file without one on a GL 3.3 core context: the collections' `#if __VERSION__ >= 130` branches
// then choose `in`/`out` and `texture()`. 3.30, not 4.50, since 4.00 reserves words (`sample`,
// `patch`, `subroutine`) that such shaders use as names. GL_ARB_shading_language_420pack is enabled
// where the driver has it, for the C-style initialisers compatibility contexts take.
#include <string>

#include "preset_file.hpp"
#include "slang_source.hpp"

namespace pfx::libretro {

constexpr int kGlslCoreVersion = 330;  // what a shader without a usable #version is compiled as

// The shader at `path`, read into the description a slang shader gets (each stage's code, its
// parameters; no name or format). Each stage's code starts with its `#version` and defines and
// then `#line 1`, so the compiler's line numbers are the file's. False with "file:line: why" in
// *error.
bool read_glsl(const std::string& path, const TextReader& read, SlangSource* out, std::string* error);

}  // namespace pfx::libretro
