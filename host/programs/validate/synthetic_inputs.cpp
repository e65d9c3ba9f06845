#include "synthetic_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pfx::validate {
namespace {

pfx::app::Image blank(int width, int height) {
  pfx::app::Image img;
  img.width = width;
  img.height = height;
  img.rgba.assign(img.pixel_count() * 4, 0.0f);
  img.depth.assign(img.pixel_count(), 1.0f);
  return img;
}

float ramp(int i, int n) { return n > 1 ? float(i) / float(n - 1) : 0.5f; }

}  // namespace

pfx::app::Image gradient_image(int width, int height) {
  pfx::app::Image img = blank(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      const float u = ramp(x, width), v = ramp(y, height);
      float* p = &img.rgba[i * 4];
      p[0] = -0.5f + 12.5f * u;
      p[1] = 6.0f * (1.0f - v);
      p[2] = 0.5f + 0.5f * std::sin(0.37f * float(x) + 0.23f * float(y));
      p[3] = 1.0f;
      img.depth[i] = 0.5f + 199.5f * u * v;
    }
  return img;
}

pfx::app::Image checkerboard_image(int width, int height) {
  pfx::app::Image img = blank(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      const float value = ((x / 8 + y / 8) % 2) ? 4.0f : 0.0f;
      for (int c = 0; c < 3; ++c) img.rgba[i * 4 + c] = value;
      img.rgba[i * 4 + 3] = 1.0f;
      img.depth[i] = ((x / 8 + y / 8) % 2) ? 2.0f : 50.0f;
    }
  return img;
}

pfx::app::Image hostile_image(int width, int height) {
  pfx::app::Image img = gradient_image(width, height);
  const float inf = std::numeric_limits<float>::infinity();
  const float values[] = {std::numeric_limits<float>::quiet_NaN(), inf, -inf, 70000.0f, -5.0f,
                          std::numeric_limits<float>::denorm_min()};
  const int n = static_cast<int>(sizeof values / sizeof values[0]);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      // Every 5th column and every 7th row carries one of the values, in all channels or one.
      if (x % 5 == 2) {
        const float v = values[(x / 5) % n];
        for (int c = 0; c < 4; ++c) img.rgba[i * 4 + c] = c == 3 ? 1.0f : v;
      } else if (y % 7 == 3) {
        img.rgba[i * 4 + (y / 7) % 3] = values[(y / 7 + x) % n];
      }
      if ((x + y) % 11 == 0) img.depth[i] = inf;
      if ((x + y) % 13 == 0) img.depth[i] = 0.0f;
    }
  return img;
}

std::vector<SyntheticInput> default_inputs() {
  return {{"gradient 64x48", gradient_image(64, 48)},
          {"checkerboard 64x48", checkerboard_image(64, 48)},
          {"NaN/Inf/70000 64x48", hostile_image(64, 48)},
          {"gradient 1x1", gradient_image(1, 1)},
          {"NaN/Inf/70000 1x1", hostile_image(1, 1)},
          {"gradient 1917x1079", gradient_image(1917, 1079)}};
}

pfx::app::Image aux_frame(AuxKind kind, int width, int height) {
  pfx::app::Image img = blank(width, height);
  img.depth.clear();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = &img.rgba[(static_cast<size_t>(y) * width + x) * 4];
      const float u = ramp(x, width) - 0.5f, v = ramp(y, height) - 0.5f;
      if (kind == AuxKind::Normal) {
        const float z = std::sqrt(std::max(0.0f, 1.0f - u * u - v * v));
        p[0] = u;
        p[1] = v;
        p[2] = z;
      } else if (kind == AuxKind::Albedo) {
        p[0] = 0.5f + 0.3f * u;
        p[1] = 0.5f;
        p[2] = 0.5f - 0.3f * v;
      } else if (u * u + v * v < 0.01f) {
        p[0] = p[1] = p[2] = 2.0f;
      }
      p[3] = 1.0f;
    }
  return img;
}

bool pixel_is_finite(const pfx::app::Image& image, size_t pixel) {
  const float* p = &image.rgba[pixel * 4];
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(p[3]);
}

}  // namespace pfx::validate
