// A scene for measuring lights against their count (pfx-bench --lights): the demo's objects on a
// floor that grows with the light count so the lights' density stays the same (the demo grid's
// density, one light per 4 m^2), seen from 20 m up and back by a camera whose view (with the
// lights' ranges) takes in about 560 lights from 1,000 lights on: the floor then fills the view,
// so more lights means more lights outside it, not more per pixel. Below 1,000 lights the floor
// stays 44 m wide (fewer lights per square metre).
#pragma once

#include <cstdint>

#include "scene.hpp"

namespace pfx::app {

constexpr double kLightFieldDensity = 0.25;  // lights per square metre

Scene make_light_field_scene(int light_count, uint64_t seed);

}  // namespace pfx::app
