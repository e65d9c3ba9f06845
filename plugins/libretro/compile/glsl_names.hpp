#pragma once
// What a uniform of a GLSL-form shader stands for, by the names RetroArch's gl driver looks up
// (glGetUniformLocation, so a name the shader does not use is simply not set):
//   MVPMatrix; OutputSize, InputSize, TextureSize (vec2: the pass's output and its input);
//   FrameCount, FrameDirection (int); Texture (the pass's input);
//   per picture, `<base>Texture`, `<base>TextureSize`, `<base>InputSize`, where <base> is
//     Orig (the frame), Prev and Prev1..Prev6 (1 to 7 frames back), Pass1..PassN (the outputs of
//     the passes before, counted from 1), PassPrev1..PassPrevN (the same counted back from this
//     pass: PassPrev1 is the pass before; one further is Orig), a pass's alias, and Feedback (the
//     last frame's output of the preset's `feedback_pass`);
//   a lookup texture's id; a parameter's id (float).
// The names map onto the semantics of the slang form (slang_semantics.hpp), so both forms run
// through one runtime. Every picture's size is its texture's: pfx sizes each texture to its
// picture, so TextureSize and InputSize agree.
#include <optional>
#include <string>

#include "slang_semantics.hpp"

namespace pfx::libretro {

struct GlslName {
  Semantic semantic;
  bool texture = false;  // a sampler (else a value)
};

// The meaning of `name` in pass `context.pass` (0-based) of a preset whose `feedback_pass` is
// `feedback_pass` (-1: none), or nothing.
std::optional<GlslName> find_glsl_name(const std::string& name, const SemanticContext& context, int feedback_pass);

}  // namespace pfx::libretro
