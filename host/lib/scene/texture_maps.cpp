#include "texture_maps.hpp"

#include <array>
#include <cmath>

#include "texture_file.hpp"

namespace pfx::app {
namespace {

// The sRGB transfer function (IEC 61966-2-1) for every 8-bit code.
const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int code = 0; code < 256; ++code) {
      const double c = code / 255.0;
      t[static_cast<size_t>(code)] =
          static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table;
}

bool is_grey(const DisplayImage& image) {
  const size_t count = static_cast<size_t>(image.width) * image.height;
  for (size_t i = 0; i < count; ++i) {
    const uint8_t* p = &image.pixels[i * static_cast<size_t>(image.channels)];
    if (p[0] != p[1] || p[1] != p[2]) return false;
  }
  return true;
}

// How steep a height map's step of one full code range over one texel tilts the normal: heights
// are the codes / 255 in units of this many texels (the -bm option of a bump statement is not read).
constexpr float kBumpDepthTexels = 4.0f;

// A grey height map (rows bottom first, R) as a tangent-space normal map: the normal of the
// surface z = height, from central differences that wrap as the UVs repeat.
void heights_to_normals(Texture* texture) {
  const int w = texture->width, h = texture->height;
  std::vector<float> height(static_cast<size_t>(w) * h);
  for (size_t i = 0; i < height.size(); ++i) height[i] = texture->rgba[i * 4];
  auto at = [&](int x, int y) { return height[static_cast<size_t>((y + h) % h) * w + static_cast<size_t>((x + w) % w)]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float du = (at(x + 1, y) - at(x - 1, y)) * 0.5f * kBumpDepthTexels;
      const float dv = (at(x, y + 1) - at(x, y - 1)) * 0.5f * kBumpDepthTexels;
      const float length = std::sqrt(du * du + dv * dv + 1.0f);
      float* p = &texture->rgba[(static_cast<size_t>(y) * w + x) * 4];
      p[0] = -du / length * 0.5f + 0.5f;
      p[1] = -dv / length * 0.5f + 0.5f;
      p[2] = 1.0f / length * 0.5f + 0.5f;
      p[3] = 1.0f;
    }
}

}  // namespace

Texture make_map(const DisplayImage& image, MapKind kind) {
  const auto& decode = srgb_to_linear_table();
  Texture texture;
  texture.width = image.width;
  texture.height = image.height;
  texture.rgba.resize(static_cast<size_t>(image.width) * image.height * 4);
  const bool has_alpha = image.channels == 4;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* in = &image.pixels[(static_cast<size_t>(y) * image.width + x) * image.channels];
      float* out = &texture.rgba[(static_cast<size_t>(image.height - 1 - y) * image.width + x) * 4];
      for (int c = 0; c < 3; ++c) out[c] = kind == MapKind::color ? decode[in[c]] : in[c] / 255.0f;
      out[3] = has_alpha ? in[3] / 255.0f : kind == MapKind::alpha ? in[0] / 255.0f : 1.0f;
    }
  if (kind == MapKind::bump && is_grey(image)) heights_to_normals(&texture);
  return texture;
}

bool load_map(const std::string& path, MapKind kind, Texture* out, std::string* problem) {
  DisplayImage image;
  if (!read_texture_file(path, &image, problem)) return false;
  *out = make_map(image, kind);
  return true;
}

}  // namespace pfx::app
