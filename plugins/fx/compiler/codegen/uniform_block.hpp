#pragma once
// The uniform block of an FX effect, in both dialects: every uniform of the model, in the model's
// order, laid out by std140 (GLSL 4.50 §7.6.2.2) as the generator declares them. A scalar
// or vector sits at a multiple of its size (a three-vector of four components); each element of
// an array and each row of a matrix (a GLSL column, as the generator stores HLSL rows) takes a
// 16-byte slot; the block ends on a 16-byte boundary. Values are packed as the runtimes hold them:
// a matrix row by row, arrays element by element.
#include <cstddef>
#include <vector>

#include "../model/effect_model.hpp"

namespace pfx::fx {

struct UniformBlockLayout {
  std::vector<std::size_t> offsets;  // per model uniform
  std::size_t size = 0;              // 0: the effect has no uniforms, and no block
};

UniformBlockLayout layout_uniform_block(const EffectModel& model);

// The block's bytes for `values` (per model uniform; a missing component is 0).
void pack_uniform_block(const EffectModel& model, const UniformBlockLayout& layout, const std::vector<std::vector<double>>& values,
                        std::vector<unsigned char>& bytes);

}  // namespace pfx::fx
