// pfx-bench --lights: the tiledlights effect against its light count. For every size,
// light count and mode: culling and shading time, total, ratio to the copy pass, speed-up over
// brute force, list lengths, shader storage bytes; and the error against the un-windowed light sum
// as the cutoff varies. Runs the light-field scene (host/lib/scene/light_field_scene.hpp).
#pragma once

#include <string>
#include <vector>

namespace pfx::bench {

// argv after "--lights". Exit codes as pfx-bench's: 0 ok, 1 internal, 2 usage, 4 plugin missing.
int lights_bench_main(const std::vector<std::string>& args);

}  // namespace pfx::bench
