#pragma once
// GLSL 4.50 from the checked tree, one program per pass: the functions the pass's entry points
// reach, the globals they use, and a main() that maps HLSL semantics onto GLSL's built-ins and
// interface variables.
//
// How HLSL's meaning is kept (docs/fx.md has the user's view):
//  - Matrices: HLSL floatRxC is stored as GLSL matRxC (R columns of C rows), so GLSL's m[i] is
//    HLSL's row i, constructors take their arguments in the same order, and mul() becomes a GLSL
//    product with its operands swapped. GLSL's matrices hold floats only, so an int, uint or bool
//    matrix is an array of its rows, and operators and conversions on it go row by row.
//  - Rows: FX texture coordinates start at the top of the picture, GL's textures at the bottom.
//    Every texture keeps GL's convention and the generated code flips v (and texel rows, gather
//    order, SV_Position's y and ddy's sign) where FX code meets GL.
//  - Operators and intrinsics whose HLSL meaning differs from GLSL's (fmod, %, integer division
//    and remainder, frac, lerp, vector comparisons and logic, component-wise matrix '*') are
//    written out with HLSL's meaning.
//  - What HLSL writes back (an out argument of another type, a matrix swizzle assigned to) goes
//    through temporaries the function declares at its top; a function's statics are the
//    program's, started in main().
#include <string>
#include <vector>

#include "../diagnostics.hpp"
#include "../model/effect_model.hpp"

namespace pfx::fx {

struct GeneratedPass {
  // GLSL sources: vertex and fragment for a draw, compute for a dispatch.
  std::string vertex, fragment, compute;
  // Texture unit i samples model.samplers[sampler_units[i]]; image unit i is
  // model.storages[image_units[i]].
  std::vector<int> sampler_units;
  std::vector<int> image_units;
  // Uniforms the program reads live, from the effect's uniform block (indices into
  // model.uniforms, in order). Those compiled in as constants are not here.
  std::vector<int> uniforms;
  // The pixel shader may leave a pixel unwritten (discard or clip): a pass rendering to the back
  // buffer must then start from its contents.
  bool may_discard = false;
  // Interface: the generated program reads the height of its render target from this uniform to
  // flip SV_Position (absent from programs that do not use it, and from the Vulkan dialect).
  static constexpr const char* kTargetHeightUniform = "pfx_target_height";
};

// The GLSL the generator writes: 4.50 for the GL runtime, or Vulkan GLSL 4.50 (the
// GL_KHR_vulkan_glsl rules) for SPIR-V (spirv_module.hpp). A Vulkan image keeps its top row first
// and a Vulkan framebuffer's origin is its top-left, as FX's are, so the row flips of the GL
// dialect fall away there, and the vertex position's y is negated (Vulkan's clip space points y
// down). In both dialects every uniform of the effect lives in one std140 block, in the model's
// order, in every stage of every pass (uniform_block.hpp); samplers and storages take the
// bindings below.
enum class GlslDialect { kOpenGL, kVulkan };
constexpr int kUniformBlockBinding = 0;         // GL: the uniform buffer binding; Vulkan: in descriptor set 0
constexpr int kVulkanFirstSamplerBinding = 1;   // + the sampler's unit (GeneratedPass::sampler_units)
constexpr int kVulkanFirstStorageBinding = 17;  // + the storage's unit; at most 16 samplers a pass

// Uniform values compiled into a program as constants, per model.uniforms index (the components
// as the runtime holds them: a matrix row by row, arrays element by element); an empty entry, or
// one whose value cannot be a constant (can_be_constant), keeps that uniform live. A program
// specialised this way computes what the live one computes with those values, and the driver
// folds the branches and loops they decide (ReShade's performance mode).
using UniformConstants = std::vector<std::vector<double>>;

// Whether a uniform of type `t` holding `values` can be compiled in as a constant: a number, bool
// or array of them with every component finite (glsl_constants.cpp).
bool can_be_constant(const Type& t, const std::vector<double>& values);

// Generates the program of `pass`, with `constants` (when given) in place of those uniforms.
// Errors (what GLSL cannot express) go to `diagnostics` with the FX location; the result is then
// incomplete.
GeneratedPass generate_pass(const TranslationUnit& unit, const EffectModel& model, const PassInfo& pass,
                            Diagnostics& diagnostics, const UniformConstants* constants = nullptr,
                            GlslDialect dialect = GlslDialect::kOpenGL);

}  // namespace pfx::fx
