// The CPU references' picture of a texture: width x height texels of 4 doubles, rows bottom first,
// read the way the GPU passes read them (texelFetch clamped to the edge, or GL_LINEAR bilinear with
// clamp-to-edge).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pfx_dof {

using Texel = std::array<double, 4>;

struct Texture {
  int width = 0, height = 0;
  std::vector<Texel> texels;

  Texture() = default;
  Texture(int w, int h) : width(w), height(h), texels(static_cast<size_t>(w) * h, Texel{0, 0, 0, 0}) {}
  Texel& at(int x, int y) { return texels[static_cast<size_t>(y) * width + x]; }
  // texelFetch with the coordinates clamped to the edge.
  const Texel& fetch(int x, int y) const {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return texels[static_cast<size_t>(y) * width + x];
  }
  // GL_LINEAR at texture coordinates (u, v) in 0..1, clamp-to-edge.
  Texel bilinear(double u, double v) const {
    const double s = u * width - 0.5, t = v * height - 0.5;
    const double x0 = std::floor(s), y0 = std::floor(t);
    const double fx = s - x0, fy = t - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    Texel r{};
    const Texel &a = fetch(ix, iy), &b = fetch(ix + 1, iy), &c = fetch(ix, iy + 1), &d = fetch(ix + 1, iy + 1);
    for (int k = 0; k < 4; ++k)
      r[k] = (a[k] * (1 - fx) + b[k] * fx) * (1 - fy) + (c[k] * (1 - fx) + d[k] * fx) * fy;
    return r;
  }
};

// Half-float storage of every channel (what an RGBA16F target keeps).
void store_half(Texture* t);

}  // namespace pfx_dof
