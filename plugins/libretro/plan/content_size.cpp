#include "content_size.hpp"

#include <algorithm>
#include <cmath>

namespace pfx::libretro {
namespace {

int side(double value) { return static_cast<int>(std::clamp(std::round(value), 1.0, double{kMaxTextureSide})); }

}  // namespace

PixelSize content_size(PixelSize frame, int width_option, int height_option) {
  const double aspect = static_cast<double>(frame.width) / frame.height;
  if (width_option <= 0 && height_option <= 0) return frame;
  if (width_option <= 0) return {side(height_option * aspect), side(height_option)};
  if (height_option <= 0) return {side(width_option), side(width_option / aspect)};
  return {side(width_option), side(height_option)};
}

}  // namespace pfx::libretro
