// The lights of a frame, checked and prepared once per frame for every mode and for the CPU
// references: each light's range from its explicit range or the range rule, its radiance
// (colour x intensity) and its centre in view space. GL-free.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pfx/effect.h>

#include "tiledlights_params.hpp"

namespace pfx_tiledlights {

// std430 layout of one light in the lights buffer: three vec4.
struct GpuLight {
  float world[3];
  float range;        // where the window reaches zero; > 0
  float radiance[3];  // colour x intensity
  float unused;
  float view[3];      // centre in view space (double-precision transform, then rounded)
  float cull_radius;  // range widened so rounding can never cull a light that still reaches a pixel
};
static_assert(sizeof(GpuLight) == 48, "std430 layout of three vec4");

// The range a light reaches, in metres (0: it reaches nothing and is left out). An explicit range
// (> 0) wins; otherwise the rule: cutoff: the distance at which intensity x max(colour) / (1 + d^2)
// falls to the cutoff; seed: 3 sqrt(intensity x max(colour)).
double light_range(const pfx_light& light, int range_rule, double cutoff);

// Widening of the culling sphere: cull radius = range (1 + relative) + absolute (1 + |centre|), in
// metres. It covers float rounding of the planes, the stored centre and the reconstructed pixel
// positions (a few 1e-7 of the distances involved). The window is exactly 0 at and past the range,
// so culling with a wider sphere changes no pixel: it only keeps rounding from culling a light that
// still reaches one.
constexpr double kCullRelativeMargin = 1e-4;
constexpr double kCullAbsoluteMargin = 1e-5;

struct LightSet {
  std::vector<GpuLight> lights;   // in frame order, only lights with a range > 0
  std::vector<uint32_t> source;   // the frame index of each
  uint32_t frame_lights = 0;      // as given
  uint32_t unreachable = 0;       // left out: zero intensity, black, or under the cutoff everywhere
};

// The view matrix of the frame in double precision (column-major, as pfx_camera stores it).
void view_matrix(const pfx_camera& camera, double out[16]);

// Checks every light and prepares those that reach anything. False with *error naming the first
// bad light and what is wrong ("light 17: position is not finite (nan, 0, 1)"): non-finite
// position, colour, intensity or range; negative colour or intensity; or a light array the frame
// describes inconsistently.
bool prepare_lights(const pfx_frame& frame, const Settings& settings, LightSet* out, std::string* error);

}  // namespace pfx_tiledlights
