#pragma once
// A pass of a GLSL-form preset (.glslp) on GL. Its code goes to GL as written (glsl_source.hpp):
// what it reads is found once it links, by GL's list of the program's active uniforms and
// attributes, named as RetroArch's gl driver names them (glsl_names.hpp); each sampler gets a
// texture unit, each value is set with glProgramUniform every frame, and a vertex array feeds the
// attributes: VertexCoord (0..1 over the target, y turned over onto the output), TexCoord and
// every `<picture>TexCoord` (0..1 over the picture: each texture is its picture's size), Color and
// COLOR (white).
#include <string>
#include <vector>

#include <glad/gl.h>
#include <pfx/cpp/program_cache.hpp>

#include "lr_passes.hpp"
#include "lr_uniform_values.hpp"

namespace pfx_libretro {

// Links the GL program of every GLSL pass of `passes` and finds what it reads (into pass.reads
// and pass.glsl_values), through `cache` (*from_cache counts the programs it gave). `vertices` is
// the buffer of glsl_vertex_data(). False with the compiler's message, lines as file:line:column,
// in *error.
bool link_glsl_passes(const LrEffectEntry& entry, std::vector<LrPass>& passes, GLuint vertices,
                      const pfx::gl::ProgramCache& cache, int* from_cache, std::string* error);

// The quads a GLSL pass draws, as two strips (vertices 0-3 into a texture of the chain, 4-7 onto
// the output): per vertex VertexCoord (x, y), TexCoord (u, v), Color.
const std::vector<float>& glsl_vertex_data();

// Sets the pass's values for this frame (MVPMatrix, sizes, FrameCount, parameters).
void set_glsl_values(const LrPass& pass, const PassValues& values);

}  // namespace pfx_libretro
