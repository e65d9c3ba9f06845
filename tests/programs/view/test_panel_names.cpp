// The names the viewer's panels give a chain's instances.
#include <catch2/catch.hpp>

#include "panel_names.hpp"

using pfx::app::panel_names;
using Names = std::vector<std::string>;

TEST_CASE("panels number the instances of an effect that appears more than once", "[view][instances]") {
  CHECK(panel_names({"bloom", "glare", "bloom"}) == Names{"bloom#1", "glare", "bloom#2"});
  CHECK(panel_names({"dof", "bloom", "bloom", "glare", "bloom"}) ==
        Names{"dof", "bloom#1", "bloom#2", "glare", "bloom#3"});
  // One instance per effect: the names of today, which --set and presets use.
  CHECK(panel_names({"dof", "bloom", "glare"}) == Names{"dof", "bloom", "glare"});
  CHECK(panel_names({}).empty());
}
