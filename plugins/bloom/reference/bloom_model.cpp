#include "reference/bloom_model.hpp"

#include <algorithm>
#include <cstddef>

namespace pfx_bloom {

void evaluate_model(const Settings& s, uint32_t width, uint32_t height, const float* color, float* output,
                    ModelTrace* trace) {
  ModelTrace ignored;
  ModelTrace& t = trace ? *trace : ignored;
  t = ModelTrace{};
  if (s.is_noop()) {  // the host copies the frame unchanged
    std::copy(color, color + static_cast<size_t>(width) * height * 4, output);
    return;
  }
  switch (s.mode) {
    case MODE_GAUSSIAN: evaluate_gaussian_model(s, width, height, color, output, t); break;
    case MODE_MGF: evaluate_mgf_model(s, width, height, color, output, t); break;
    default: evaluate_chain_model(s, width, height, color, output, t); break;
  }
}

}  // namespace pfx_bloom
