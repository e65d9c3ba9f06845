#include "reference/dof_inputs.hpp"

#include <cmath>

#include "reference/half_float.hpp"

namespace pfx_dof {

void store_half(Texture* t) {
  for (Texel& texel : t->texels)
    for (double& v : texel) v = to_half(v);
}

Texture safe_color(const pfx_frame& frame, const float* color, int nonfinite) {
  Texture t(static_cast<int>(frame.width), static_cast<int>(frame.height));
  for (size_t i = 0; i < t.texels.size(); ++i) {
    const float* c = color + i * 4;
    for (int k = 0; k < 4; ++k) t.texels[i][k] = safe_value(c[k]);
    if (nonfinite != NONFINITE_ZERO) continue;
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) t.texels[i][0] = t.texels[i][1] = t.texels[i][2] = 0.0;
    if (!std::isfinite(c[3])) t.texels[i][3] = 0.0;
  }
  return t;
}

Lens frame_lens(const pfx_frame& frame, const Settings& settings, const float* depth) {
  return make_lens(frame, settings, focus_distance(frame, settings, depth));
}

std::vector<double> coc_image(const pfx_frame& frame, const Lens& lens, const float* depth) {
  std::vector<double> coc(static_cast<size_t>(frame.width) * frame.height);
  for (size_t i = 0; i < coc.size(); ++i) coc[i] = coc_pixels(lens, view_depth(frame, depth[i]));
  return coc;
}

}  // namespace pfx_dof
