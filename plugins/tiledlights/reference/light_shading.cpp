#include "reference/light_shading.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <pfx/depth.h>

#include "light_set.hpp"
#include "view_frustum.hpp"

namespace pfx_tiledlights {
namespace {

struct Light {
  double position[3];
  double radiance[3];
  double range;  // windowed only
};

// A colour channel as the nonfinite setting reads it (the shading pass's finite_sample).
float finite_sample(float v, int nonfinite) {
  if (std::isfinite(v)) return v;
  if (nonfinite == NONFINITE_CLAMP && std::isinf(v)) return v > 0 ? 65504.0f : -65504.0f;
  return 0.0f;
}

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::min(std::max((x - edge0) / (edge1 - edge0), 0.0), 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace

bool shade_reference(const pfx_frame& frame, const Settings& settings, const GBufferImages& images, bool windowed,
                     float* output, std::string* error) {
  LightSet set;
  if (!prepare_lights(frame, settings, &set, error)) return false;
  Perspective perspective;
  if (!perspective_of(frame.camera, &perspective, error)) return false;
  double view[16], inverse_view[16];
  view_matrix(frame.camera, view);
  if (!invert_matrix(view, inverse_view)) {
    *error = "the camera's view matrix is not invertible";
    return false;
  }
  // The lights straight from the frame in double precision: windowed, those with a range;
  // unwindowed, every light.
  std::vector<Light> lights;
  const auto* bytes = reinterpret_cast<const unsigned char*>(frame.lights);
  for (uint32_t i = 0; i < frame.light_count; ++i) {
    const pfx_light& l = *reinterpret_cast<const pfx_light*>(bytes + size_t(i) * frame.light_struct_size);
    Light light;
    light.range = light_range(l, settings.range_rule, settings.cutoff);
    if (windowed && !(light.range > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      light.position[k] = l.position[k];
      light.radiance[k] = double(l.color[k]) * double(l.intensity);
    }
    lights.push_back(light);
  }

  const int w = static_cast<int>(frame.width), h = static_cast<int>(frame.height);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      float color[4], albedo[3], emissive[3] = {0, 0, 0};
      for (int c = 0; c < 4; ++c) color[c] = finite_sample(images.color[i * 4 + c], settings.nonfinite);
      for (int c = 0; c < 3; ++c) {
        albedo[c] = finite_sample(images.albedo[i * 4 + c], settings.nonfinite);
        if (images.emissive) emissive[c] = finite_sample(images.emissive[i * 4 + c], settings.nonfinite);
      }
      float* out = output + i * 4;
      const double depth = pfx_view_depth(images.depth[i], frame.depth_encoding, frame.camera.near_plane,
                                          frame.camera.far_plane);
      if (!(depth > 0) || !std::isfinite(depth)) {
        for (int c = 0; c < 4; ++c) out[c] = color[c];
        continue;
      }
      const double pv[3] = {depth * ((2.0 * (x + 0.5) / w - 1 + perspective.offset_x) / perspective.scale_x),
                            depth * ((2.0 * (y + 0.5) / h - 1 + perspective.offset_y) / perspective.scale_y), -depth};
      double p[3];
      for (int k = 0; k < 3; ++k)
        p[k] = inverse_view[k] * pv[0] + inverse_view[4 + k] * pv[1] + inverse_view[8 + k] * pv[2] + inverse_view[12 + k];
      double n[3] = {images.normal[i * 4], images.normal[i * 4 + 1], images.normal[i * 4 + 2]};
      // A normal with a non-finite component lights nothing, as a zero normal.
      if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) n[0] = n[1] = n[2] = 0;
      const double n_length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (double& v : n) v = n_length > 0 ? v / n_length : 0.0;

      double sum[3] = {0, 0, 0};
      for (const Light& light : lights) {
        const double l[3] = {light.position[0] - p[0], light.position[1] - p[1], light.position[2] - p[2]};
        const double d2 = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
        const double d = std::sqrt(d2);
        const double theta = d2 > 0 ? std::max((n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) / d, 0.0) : 1.0;
        double factor = theta / (1 + d2);
        if (windowed) factor *= 1 - smoothstep(0.75 * light.range, light.range, d);
        for (int k = 0; k < 3; ++k) sum[k] += light.radiance[k] * factor;
      }
      const float* base = settings.base == BASE_EMISSIVE ? emissive : color;
      for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(base[k] + albedo[k] * sum[k]);
      out[3] = color[3];
    }
  return true;
}

}  // namespace pfx_tiledlights
