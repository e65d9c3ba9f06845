// The built-in scenes' random numbers: SplitMix64, the same numbers on every platform (no std::
// distributions, whose output the standard leaves to the library), and the demo grid's point light.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include <pfx/effect.h>

namespace pfx::app {

class SceneRandom {
 public:
  explicit SceneRandom(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Uniform in [lo, hi): 53 random bits.
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1.0p-53; }
  // Uniform integer in [lo, hi].
  int integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<uint64_t>(hi - lo + 1)); }

 private:
  uint64_t state_;
};

// One of the demo grid's lights at position: intensity uniform in [0.25, 4), then a colour c in 1..7
// read as the bits (R, G, B); range 0 (derived by the effect).
pfx_light seed_light(const glm::vec3& position, SceneRandom& random);

}  // namespace pfx::app
