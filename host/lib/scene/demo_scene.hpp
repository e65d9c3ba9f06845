// The built-in demo scene (pfx-render --demo, pfx-view), made in code: a textured floor, boxes and
// spheres, a few emissive objects bright enough to bloom, and 400 point lights (a 20x20
// grid 2 m apart, 1 m above the floor, colours from the 7 non-black RGB corners, intensity 0.25..4),
// seen by a camera that frames the grid. Everything depends only on the options.
#pragma once

#include <cstdint>

#include "scene.hpp"

namespace pfx::app {

struct DemoSceneOptions {
  int extra_lights = 0;  // --lights N: N more lights at random inside the scene's bounds
  uint64_t seed = 1;     // --seed S: drives every random choice (grid colours and extra lights)
};

Scene make_demo_scene(const DemoSceneOptions& options = {});

// Appends count lights uniformly inside [lo, hi], each with a random corner colour and intensity
// in [0.25, 4] as the grid's lights have, derived range (range = 0). Deterministic for a seed, on
// every platform (no std:: distributions, whose output the standard leaves to the library).
void add_random_lights(Scene* scene, int count, const glm::vec3& lo, const glm::vec3& hi, uint64_t seed);

// The demo's light grid: 20x20 lights, 2 m apart, centred on the origin, 1 m above y = 0.
void add_seed_light_grid(Scene* scene, uint64_t seed);

}  // namespace pfx::app
