#include "uniform_block.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace pfx::fx {
namespace {

struct BlockShape {
  std::size_t elements = 1;  // array elements
  int rows = 1, per_row = 1;
  bool slots = false;  // each element (matrix row) in a 16-byte slot
  std::size_t align = 4;
};

BlockShape block_shape_of(const Type& t) {
  BlockShape s;
  for (int size : t.array) s.elements *= static_cast<std::size_t>(size);
  // The shape of one element: is_matrix() and its kin answer false for an array.
  const bool matrix = t.shape == Shape::kMatrix;
  s.rows = matrix ? t.rows : 1;
  s.per_row = matrix ? t.columns : t.components();
  s.slots = t.is_array() || matrix;
  s.align = s.slots || s.per_row > 2 ? 16 : s.per_row == 2 ? 8 : 4;
  return s;
}

std::uint32_t bits_of(BaseType base, double value) {
  if (base == BaseType::kBool) return value != 0 ? 1u : 0u;
  if (base == BaseType::kInt || base == BaseType::kUint) {
    if (!std::isfinite(value)) return 0;
    return static_cast<std::uint32_t>(static_cast<long long>(value));  // a uint's 4294967295 and an int's -1 alike
  }
  const float f = static_cast<float>(value);
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  return bits;
}

}  // namespace

UniformBlockLayout layout_uniform_block(const EffectModel& model) {
  UniformBlockLayout layout;
  std::size_t offset = 0;
  for (const UniformInfo& u : model.uniforms) {
    const BlockShape s = block_shape_of(u.type);
    offset = (offset + s.align - 1) / s.align * s.align;
    layout.offsets.push_back(offset);
    const std::size_t row_bytes = s.slots ? 16 : static_cast<std::size_t>(s.per_row) * 4;
    offset += s.elements * static_cast<std::size_t>(s.rows) * row_bytes;
  }
  layout.size = (offset + 15) / 16 * 16;
  return layout;
}

void pack_uniform_block(const EffectModel& model, const UniformBlockLayout& layout,
                        const std::vector<std::vector<double>>& values, std::vector<unsigned char>& bytes) {
  bytes.assign(layout.size, 0);
  for (std::size_t index = 0; index < model.uniforms.size(); ++index) {
    const Type& t = model.uniforms[index].type;
    const BlockShape s = block_shape_of(t);
    const BaseType base = t.base == BaseType::kHalf || t.base == BaseType::kDouble ? BaseType::kFloat : t.base;
    const std::vector<double>* value = index < values.size() ? &values[index] : nullptr;
    std::size_t at = layout.offsets[index], next = 0;
    for (std::size_t e = 0; e < s.elements; ++e)
      for (int r = 0; r < s.rows; ++r) {
        for (int c = 0; c < s.per_row; ++c, ++next) {
          const std::uint32_t bits = bits_of(base, value && next < value->size() ? (*value)[next] : 0.0);
          std::memcpy(bytes.data() + at + static_cast<std::size_t>(c) * 4, &bits, 4);
        }
        at += s.slots ? 16 : static_cast<std::size_t>(s.per_row) * 4;
      }
  }
}

}  // namespace pfx::fx
