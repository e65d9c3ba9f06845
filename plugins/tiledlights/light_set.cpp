#include "light_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>

namespace pfx_tiledlights {

double light_range(const pfx_light& light, int range_rule, double cutoff) {
  if (light.range > 0) return light.range;
  const double peak = double(light.intensity) * std::max({double(light.color[0]), double(light.color[1]),
                                                          double(light.color[2])});
  if (!(peak > 0)) return 0;
  if (range_rule == RANGE_SEED) return 3.0 * std::sqrt(peak);
  // peak / (1 + d^2) = cutoff
  return peak > cutoff ? std::sqrt(peak / cutoff - 1.0) : 0.0;
}

void view_matrix(const pfx_camera& camera, double out[16]) {
  for (int i = 0; i < 16; ++i) out[i] = camera.view[i];
}

bool prepare_lights(const pfx_frame& frame, const Settings& settings, LightSet* out, std::string* error) {
  out->lights.clear();
  out->source.clear();
  out->frame_lights = frame.light_count;
  out->unreachable = 0;
  if (frame.light_count == 0) return true;
  if (!frame.lights || frame.light_struct_size < PFX_LIGHT_MIN_SIZE) {
    *error = "the frame's light array is missing or its light_struct_size is smaller than pfx_light";
    return false;
  }
  double view[16];
  view_matrix(frame.camera, view);
  out->lights.reserve(frame.light_count);
  out->source.reserve(frame.light_count);
  const auto* bytes = reinterpret_cast<const unsigned char*>(frame.lights);
  for (uint32_t i = 0; i < frame.light_count; ++i) {
    // A host of another minor version may give lights of another size (core.h's growth rule):
    // take the part this plugin knows; fields a smaller light lacks stay zero.
    pfx_light light{};
    std::memcpy(&light, bytes + size_t(i) * frame.light_struct_size,
                std::min<size_t>(frame.light_struct_size, sizeof light));
    const float* p = light.position;
    const float* c = light.color;
    char message[200] = "";
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      std::snprintf(message, sizeof message, "position is not finite (%g, %g, %g)", p[0], p[1], p[2]);
    else if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]) || c[0] < 0 || c[1] < 0 || c[2] < 0)
      std::snprintf(message, sizeof message, "colour must be finite and >= 0 (%g, %g, %g)", c[0], c[1], c[2]);
    else if (!std::isfinite(light.intensity) || light.intensity < 0)
      std::snprintf(message, sizeof message, "intensity must be finite and >= 0 (%g)", light.intensity);
    else if (std::isnan(light.range) || std::isinf(light.range))
      std::snprintf(message, sizeof message, "range must be finite (%g; <= 0 derives it)", light.range);
    if (message[0]) {
      *error = "light " + std::to_string(i) + ": " + message;
      return false;
    }
    const double range = light_range(light, settings.range_rule, settings.cutoff);
    if (!(range > 0)) {
      ++out->unreachable;
      continue;
    }
    GpuLight g{};
    for (int k = 0; k < 3; ++k) {
      g.world[k] = p[k];
      g.radiance[k] = static_cast<float>(double(c[k]) * light.intensity);
      g.view[k] = static_cast<float>(view[k] * p[0] + view[4 + k] * p[1] + view[8 + k] * p[2] + view[12 + k]);
    }
    g.range = static_cast<float>(range);
    const double distance = std::sqrt(double(g.view[0]) * g.view[0] + double(g.view[1]) * g.view[1] +
                                      double(g.view[2]) * g.view[2]);
    g.cull_radius = static_cast<float>(range * (1 + kCullRelativeMargin) + kCullAbsoluteMargin * (1 + distance));
    out->lights.push_back(g);
    out->source.push_back(i);
  }
  return true;
}

}  // namespace pfx_tiledlights
