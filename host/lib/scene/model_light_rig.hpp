// A default light rig for a model of any size and place (pfx-render --scene, pfx-view --scene),
// as model viewers light what they open:
//   - a key light from above, to the right and in front (as the framing camera sees it), and a
//     sky over a darker ground as ambient, all in the G-buffer's colour;
//   - the point-light field (the demo grid's colours and intensities) spread over and around the
//     model's box rather than inside it, reaching a fraction of the model's size, for the lights
//     effect (tiledlights) to add;
//   - an exposure: all of it scaled by the model's mean albedo so that its mid-tones land in the
//     middle of the display range (mean near 0.2 linear) at exposure 0, whatever its textures.
#pragma once

#include <cstdint>

#include "scene.hpp"

namespace pfx::app {

struct ModelLightRigOptions {
  int point_lights = 400;  // --lights N; their total light stays the same for any count above 400
  uint64_t seed = 1;       // --seed S: the point lights' places and colours
};

// The model's mean albedo: per material, its colour times its albedo map's mean, weighted by the
// area of the triangles that use it; Rec. 709 luminance. 0.8 (the default material) for a scene
// without triangles.
double mean_albedo(const Scene& scene);

// Sets the scene's key light, sky and ground, background, and appends the point lights, from its
// bounds (update_bounds) and mean_albedo. Deterministic for a seed.
void add_model_light_rig(Scene* scene, const ModelLightRigOptions& options);

}  // namespace pfx::app
