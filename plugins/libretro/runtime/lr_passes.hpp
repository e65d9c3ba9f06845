#pragma once
// A preset's passes compiled for GL, as an instance makes them at create. A slang pass: its shader
// read (slang_source.hpp), both stages compiled to SPIR-V by glslang, reflected against the preset's
// names (its aliases, lookup textures and parameters) and turned into GLSL 4.50 by SPIRV-Cross,
// then built into a GL program with a uniform buffer for its uniform block and one for its push
// constants. A GLSL-form pass: its shader read (glsl_source.hpp) and left to GL (lr_glsl_pass.hpp).
// Errors name the preset and the shader's file and line.
#include <string>
#include <vector>

#include <glad/gl.h>
#include <pfx/cpp/program_cache.hpp>

#include "lr_catalog.hpp"
#include "slang_gl.hpp"
#include "slang_reflection.hpp"
#include "slang_source.hpp"

namespace pfx_libretro {

// A value a GLSL-form pass reads, at its uniform location.
struct GlslValue {
  GLint location = -1;
  pfx::libretro::Semantic semantic;
};

struct LrPass {
  std::string name;  // `#pragma name`, or "" (the preset's alias wins)
  std::string format;
  pfx::libretro::PassInterface reads;
  pfx::libretro::GlPassCode code;
  GLuint program = 0;
  GLuint uniform_buffer = 0, push_buffer = 0;            // 0 where the pass has no such block
  std::vector<unsigned char> uniform_bytes, push_bytes;  // what the buffers hold
  // The GLSL form (.glslp): `code` is the shader as GL compiles it, linked by link_glsl_passes
  // (lr_glsl_pass.hpp), which fills `reads.samplers` (each binding a texture unit) and these.
  bool glsl = false;
  std::vector<GlslValue> glsl_values;
  GLuint glsl_vao = 0;  // the attributes it reads
};

// Compiles every pass of the entry's preset to GLSL (CPU only): a GLSL-form pass is only read.
// False with why in *error.
bool compile_passes(const LrEffectEntry& entry, std::vector<LrPass>* passes, std::string* error);

// Builds the GL programs and buffers of the slang passes, the programs through `cache`
// (*from_cache counts the programs it gave). The pass that draws into the host's output
// (`to_output`) reads gl_FragCoord with an upper-left origin, as every other pass does in its own
// texture.
bool build_pass_programs(std::vector<LrPass>& passes, bool last_to_output, const pfx::gl::ProgramCache& cache,
                         int* from_cache, std::string* error);

// The cache of compiled programs: $XDG_CACHE_HOME/pfx/libretro-programs, at most 256 MiB;
// PFX_LIBRETRO_CACHE=0 turns it off. A context must be current.
pfx::gl::ProgramCache libretro_program_cache();
void release_pass_programs(std::vector<LrPass>& passes);

}  // namespace pfx_libretro
