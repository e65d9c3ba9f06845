// The descriptor rules, each on a hand-made descriptor that breaks exactly it.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <pfx/cpp/descriptors.hpp>

#include "descriptor_checks.hpp"

using pfx::validate::effect_descriptor_problems;
using pfx::validate::param_descriptor_problems;

namespace {

pfx_param_desc good_float() {
  return pfx::desc::param("threshold")
      .label("Threshold")
      .group("Bloom")
      .tooltip("Brightness that blooms.")
      .float_range(0, 100)
      .display_range(0, 8)
      .step(0.1)
      .default_value(1.0);
}

const pfx_enum_item kItems[] = {{"chain", "Chain"}, {"dual", "Dual"}};

pfx_param_desc good_enum() {
  return pfx::desc::param("mode").label("Mode").tooltip("Which algorithm.").items(kItems, 2).default_value(1);
}

// The single problem of a descriptor that should have exactly one.
std::string only_problem(const pfx_param_desc& p) {
  const std::vector<std::string> problems = param_descriptor_problems(p);
  INFO("problems: " << problems.size());
  for (const auto& problem : problems) INFO(problem);
  REQUIRE(problems.size() == 1);
  return problems[0];
}

}  // namespace

TEST_CASE("well-formed parameters of every type have no problem", "[validate][descriptors]") {
  CHECK(param_descriptor_problems(good_float()).empty());
  CHECK(param_descriptor_problems(good_enum()).empty());
  CHECK(param_descriptor_problems(pfx::desc::param("on").label("On").tooltip("Turns it on.").boolean().default_value(1))
            .empty());
  CHECK(param_descriptor_problems(pfx::desc::param("tint")
                                      .label("Tint")
                                      .tooltip("Colour.")
                                      .color_range(0, 16)
                                      .display_range(0, 1)
                                      .step(0.01)
                                      .default_value(1, 0.5, 0.25))
            .empty());
}

TEST_CASE("a default outside the hard range is named with both numbers", "[validate][descriptors]") {
  pfx_param_desc p = good_float();
  p.default_value.v[0] = 101;
  CHECK(only_problem(p) == "parameter 'threshold': default 101 is above hard_max 100");
  p.default_value.v[0] = -0.5;
  CHECK(only_problem(p) == "parameter 'threshold': default -0.5 is below hard_min 0");
  p.default_value.v[0] = NAN;
  CHECK(only_problem(p) == "parameter 'threshold': default is NaN");
}

TEST_CASE("a vector default is checked per component and unused components must be 0", "[validate][descriptors]") {
  pfx_param_desc p = pfx::desc::param("tint")
                         .label("Tint")
                         .tooltip("Colour.")
                         .color_range(0, 16)
                         .display_range(0, 1)
                         .step(0.01)
                         .default_value(1, 17, 1);
  CHECK(only_problem(p) == "parameter 'tint': default component 1 17 is above hard_max 16");
  p.default_value = {{1, 1, 1, 3}};
  CHECK(only_problem(p) == "parameter 'tint': default component 3 is 3 but the type uses 3 (unused ones must be 0)");
}

TEST_CASE("the display range must lie inside the hard range and be finite", "[validate][descriptors]") {
  pfx_param_desc p = good_float();
  p.display_max = 200;
  CHECK(only_problem(p) == "parameter 'threshold': display range [0, 200] is not inside the hard range [0, 100]");
  p = good_float();
  p.hard_max = INFINITY;
  p.display_max = INFINITY;
  CHECK(only_problem(p) == "parameter 'threshold': display range is not finite (a slider needs finite ends)");
  p = good_float();
  p.display_min = 5;
  p.display_max = 4;
  CHECK(only_problem(p) == "parameter 'threshold': display range [5, 4] is empty");
}

TEST_CASE("labels and tooltips are required, unit and group may be empty but not NULL", "[validate][descriptors]") {
  pfx_param_desc p = good_float();
  p.label = "";
  CHECK(only_problem(p) == "parameter 'threshold': no label");
  p = good_float();
  p.tooltip = nullptr;
  CHECK(only_problem(p) == "parameter 'threshold': no tooltip");
  p = good_float();
  p.unit = nullptr;
  CHECK(only_problem(p) == "parameter 'threshold': unit is NULL (use \"\" for none)");
}

TEST_CASE("ids must be [a-z0-9_]+", "[validate][descriptors]") {
  pfx_param_desc p = good_float();
  p.id = "Threshold";
  CHECK(only_problem(p) == "parameter 'Threshold': the id is not [a-z0-9_]+");
  CHECK(pfx::validate::is_effect_or_param_id("auto_min_size2"));
  CHECK_FALSE(pfx::validate::is_effect_or_param_id("auto-min"));
  CHECK_FALSE(pfx::validate::is_effect_or_param_id(""));
  CHECK(pfx::validate::is_plugin_id("org.pfx.bloom"));
  CHECK(pfx::validate::is_plugin_id("com.example.my-effects"));
  CHECK_FALSE(pfx::validate::is_plugin_id("bloom"));
  CHECK_FALSE(pfx::validate::is_plugin_id("org..bloom"));
  CHECK_FALSE(pfx::validate::is_plugin_id("org.pfx."));
  CHECK_FALSE(pfx::validate::is_plugin_id("Org.pfx.bloom"));
}

TEST_CASE("enums need items with valid unique ids and the range [0, n-1]", "[validate][descriptors]") {
  pfx_param_desc p = good_enum();
  p.item_count = 0;
  CHECK(only_problem(p) == "parameter 'mode': an enum with no items");
  p = good_enum();
  p.hard_max = 2;
  p.display_max = 2;
  CHECK(only_problem(p) == "parameter 'mode': an enum's hard range must be [0, 1]");
  static const pfx_enum_item repeated[] = {{"chain", "Chain"}, {"chain", "Again"}};
  p = good_enum();
  p.items = repeated;
  CHECK(only_problem(p) == "parameter 'mode': item 1: id 'chain' repeats");
  p = good_enum();
  p.default_value.v[0] = 0.5;
  CHECK(only_problem(p) == "parameter 'mode': default 0.5 is not a whole number");
}

TEST_CASE("logarithmic parameters need a display range above 0", "[validate][descriptors]") {
  pfx_param_desc p = good_float();
  p.flags = PFX_PARAM_LOGARITHMIC;
  CHECK(only_problem(p) == "parameter 'threshold': logarithmic, but the display range does not start above 0");
}

TEST_CASE("an effect needs its callbacks, a label, a description and unique parameter ids", "[validate][descriptors]") {
  static const pfx_param_desc params[] = {good_float(), good_float()};
  pfx_effect_desc e{};
  e.struct_size = sizeof e;
  e.id = "bloom";
  e.label = "Bloom";
  e.description = "";
  e.params = params;
  e.param_count = 2;
  const std::vector<std::string> problems = effect_descriptor_problems(e);
  CHECK(problems == std::vector<std::string>{"no description", "create, destroy, declare and run_pass are all required",
                                             "parameter 'threshold': the id repeats"});
}
