#include "random_params.hpp"

#include <algorithm>
#include <cmath>

namespace pfx::validate {
namespace {

int component_count(pfx_param_type type) {
  return type == PFX_PARAM_VEC2 ? 2 : (type == PFX_PARAM_VEC3 || type == PFX_PARAM_COLOR) ? 3 : 1;
}

double uniform(SplitMix64& rng, double lo, double hi) { return lo + (hi - lo) * rng.unit(); }

double random_component(const pfx_param_desc& p, SplitMix64& rng) {
  const double lo = std::isfinite(p.hard_min) ? p.hard_min : p.display_min;
  const double hi = std::isfinite(p.hard_max) ? p.hard_max : p.display_max;
  const bool whole = p.type == PFX_PARAM_INT || p.type == PFX_PARAM_BOOL || p.type == PFX_PARAM_ENUM;
  if (p.type == PFX_PARAM_ENUM) return p.item_count ? std::floor(rng.unit() * p.item_count) : 0.0;
  if (p.type == PFX_PARAM_BOOL) return rng.unit() < 0.5 ? 0.0 : 1.0;
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) return p.default_value.v[0];  // the descriptor check says why
  double v;
  const double pick = rng.unit();
  if (pick < 0.15) {
    v = lo;
  } else if (pick < 0.3) {
    v = hi;
  } else if (pick < 0.65) {
    v = uniform(rng, std::max(lo, p.display_min), std::min(hi, p.display_max));
  } else if ((p.flags & PFX_PARAM_LOGARITHMIC) && lo > 0) {
    v = std::exp(uniform(rng, std::log(lo), std::log(hi)));
  } else {
    v = uniform(rng, lo, hi);
  }
  if (whole) v = std::round(v);
  return std::clamp(v, lo, hi);
}

}  // namespace

uint64_t SplitMix64::next() {
  uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

double SplitMix64::unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

std::vector<pfx_value> random_parameter_set(const pfx_effect_desc& effect, SplitMix64& rng) {
  std::vector<pfx_value> values(effect.param_count, pfx_value{{0, 0, 0, 0}});
  for (uint32_t i = 0; i < effect.param_count; ++i) {
    const pfx_param_desc& p = effect.params[i];
    for (int c = 0; c < component_count(p.type); ++c) values[i].v[c] = random_component(p, rng);
  }
  return values;
}

}  // namespace pfx::validate
