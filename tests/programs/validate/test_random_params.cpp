// Random parameter sets: inside the hard ranges, whole where they must be, the same for a seed.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>

#include <pfx/cpp/descriptors.hpp>

#include "random_params.hpp"

using pfx::validate::random_parameter_set;
using pfx::validate::SplitMix64;

namespace {

const pfx_enum_item kItems[] = {{"a", "A"}, {"b", "B"}, {"c", "C"}};

const pfx_param_desc kParams[] = {
    pfx::desc::param("f")
        .label("F")
        .tooltip("A float.")
        .float_range(-2, 65504)
        .display_range(0, 8)
        .step(0.1)
        .default_value(1),
    pfx::desc::param("i").label("I").tooltip("An int.").int_range(1, 12).display_range(1, 6).default_value(3),
    pfx::desc::param("b").label("B").tooltip("A bool.").boolean().default_value(0),
    pfx::desc::param("e").label("E").tooltip("An enum.").items(kItems, 3).default_value(0),
    pfx::desc::param("c")
        .label("C")
        .tooltip("A colour.")
        .color_range(0, 16)
        .display_range(0, 1)
        .step(0.01)
        .default_value(1, 1, 1),
    pfx::desc::param("v")
        .label("V")
        .tooltip("A vector with an infinite hard range.")
        .vec2_range(-INFINITY, INFINITY)
        .display_range(-5, 5)
        .step(0.1)
        .default_value(0, 0),
};

pfx_effect_desc effect() {
  pfx_effect_desc e{};
  e.struct_size = sizeof e;
  e.id = "test";
  e.params = kParams;
  e.param_count = sizeof kParams / sizeof kParams[0];
  return e;
}

}  // namespace

TEST_CASE("SplitMix64 gives the published sequence for seed 0", "[validate][random]") {
  // First outputs of SplitMix64 from state 0, as in the reference implementation (Vigna's splitmix64.c).
  SplitMix64 rng(0);
  CHECK(rng.next() == 0xe220a8397b1dcdafull);
  CHECK(rng.next() == 0x6e789e6aa1b965f4ull);
  CHECK(rng.next() == 0x06c45d188009454full);
}

TEST_CASE("random values stay inside the hard ranges, whole where the type is", "[validate][random]") {
  const pfx_effect_desc e = effect();
  SplitMix64 rng(7);
  std::set<double> float_values, enum_values;
  bool saw_min = false, saw_max = false;
  for (int run = 0; run < 2000; ++run) {
    const std::vector<pfx_value> values = random_parameter_set(e, rng);
    REQUIRE(values.size() == e.param_count);
    for (uint32_t p = 0; p < e.param_count; ++p) {
      const pfx_param_desc& d = kParams[p];
      const int used = d.type == PFX_PARAM_COLOR ? 3 : d.type == PFX_PARAM_VEC2 ? 2 : 1;
      for (int c = 0; c < 4; ++c) {
        const double v = values[p].v[c];
        INFO("parameter " << d.id << " component " << c << " = " << v);
        if (c >= used) {
          CHECK(v == 0);
          continue;
        }
        REQUIRE(std::isfinite(v));
        CHECK(v >= (std::isfinite(d.hard_min) ? d.hard_min : d.display_min));
        CHECK(v <= (std::isfinite(d.hard_max) ? d.hard_max : d.display_max));
        if (d.type == PFX_PARAM_INT || d.type == PFX_PARAM_BOOL || d.type == PFX_PARAM_ENUM) CHECK(v == std::floor(v));
      }
    }
    float_values.insert(values[0].v[0]);
    enum_values.insert(values[3].v[0]);
    saw_min |= values[0].v[0] == -2;
    saw_max |= values[0].v[0] == 65504;
  }
  CHECK(saw_min);  // the ends of the hard range are tried on purpose
  CHECK(saw_max);
  CHECK(float_values.size() > 1000);
  CHECK(enum_values == std::set<double>{0, 1, 2});
}

TEST_CASE("a seed names the same sets, another seed other sets", "[validate][random]") {
  const pfx_effect_desc e = effect();
  SplitMix64 a(42), b(42), c(43);
  for (int run = 0; run < 20; ++run) {
    const auto first = random_parameter_set(e, a);
    const auto second = random_parameter_set(e, b);
    const auto other = random_parameter_set(e, c);
    for (uint32_t p = 0; p < e.param_count; ++p)
      for (int k = 0; k < 4; ++k) CHECK(first[p].v[k] == second[p].v[k]);
    if (run == 0) CHECK(first[0].v[0] != other[0].v[0]);
  }
}
