// The frames pfx-validate renders every effect over. Made in code, the same every run. Colour
// has depth beside it (linear metres), so effects that read depth get it; normal, albedo and
// emissive frames come from aux_frame().
#pragma once

#include <string>
#include <vector>

#include "image.hpp"

namespace pfx::validate {

struct SyntheticInput {
  std::string name;  // "gradient 64x48"
  pfx::app::Image image;
};

// A smooth HDR ramp from -0.5 to 12 across, and a second ramp down; depth from 0.5 m to 200 m.
pfx::app::Image gradient_image(int width, int height);
// 8x8 cells of 0 and 4: hard edges, the worst case for filters that ring.
pfx::app::Image checkerboard_image(int width, int height);
// A gradient with rows and columns of NaN, +Inf, -Inf, 70000 (above the half-float maximum),
// -5 and denormals, and depth with +inf ("nothing there", as pfx-render gives it) and 0.
pfx::app::Image hostile_image(int width, int height);

// What the "defaults" check renders: gradient, checkerboard and hostile at 64x48, 1x1, 1917x1079.
std::vector<SyntheticInput> default_inputs();

enum class AuxKind { Normal, Albedo, Emissive };
// A G-buffer companion of the given size: unit normals facing the camera with a tilt, a grey
// albedo, a dim emissive patch.
pfx::app::Image aux_frame(AuxKind kind, int width, int height);

// True when all four channels of pixel i are finite.
bool pixel_is_finite(const pfx::app::Image& image, size_t pixel);

}  // namespace pfx::validate
