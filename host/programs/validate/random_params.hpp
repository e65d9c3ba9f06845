// Seeded random parameter sets inside each parameter's hard range. The generator and the mapping
// to values are written out here (no std:: distributions, whose results differ between standard
// libraries), so a seed names the same sets on every machine.
#pragma once

#include <cstdint>
#include <vector>

#include <pfx/effect.h>

namespace pfx::validate {

// SplitMix64 (Steele, Lea, Flood 2014): tiny, and every seed, 0 included, gives a good stream.
class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}
  uint64_t next();
  double unit();  // [0, 1) with 53 random bits

 private:
  uint64_t state_;
};

// One value per parameter. Each component is, with about equal odds, the hard minimum or maximum
// (where bugs live), uniform over the display range (where users are), or uniform over the hard
// range (log-uniform for PFX_PARAM_LOGARITHMIC); an infinite hard end is replaced by the display
// end. Whole-number types get whole numbers; enums a valid index; unused components are 0.
std::vector<pfx_value> random_parameter_set(const pfx_effect_desc& effect, SplitMix64& rng);

}  // namespace pfx::validate
