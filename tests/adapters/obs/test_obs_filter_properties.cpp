// What OBS offers: a filter per effect that needs colour alone and the chain filter, and each
// per-effect filter's properties and defaults as `pfx-render --list --json` describes the effect's
// parameters (the display-referred default where the effect has one).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <set>

#include <nlohmann/json.hpp>

#include "obs_session.hpp"
#include "render_process.hpp"

using namespace pfx::test;

namespace {

nlohmann::json effect_listing(const std::string& id) {
  const Result listed = pfx_render("--plugins " PFX_PLUGIN_OUTPUT_DIR " --list --json", false);
  INFO(listed.out << listed.err);
  REQUIRE(listed.exit_code == 0);
  const nlohmann::json listing = nlohmann::json::parse(listed.out);
  for (const auto& plugin : listing["plugins"])
    for (const auto& effect : plugin["effects"])
      if (effect["id"] == id) return effect;
  FAIL("pfx-render --list --json has no effect " << id);
  return {};
}

}  // namespace

TEST_CASE("OBS offers the chain filter and one filter per colour-only effect", "[obs]") {
  ObsSession::get();
  std::set<std::string> types;
  const char* type = nullptr;
  for (size_t i = 0; obs_enum_filter_types(i, &type); ++i) types.insert(type);
  CHECK(types.count("pfx_chain_filter") == 1);
  CHECK(types.count("pfx_bloom_filter") == 1);
  CHECK(types.count("pfx_glare_filter") == 1);
  CHECK(types.count("pfx_dof_filter") == 0);  // depth of field needs depth
  CHECK(types.count("pfx_tiledlights_filter") == 0);  // lights
  CHECK(std::string(obs_source_get_display_name("pfx_bloom_filter")) == "pfx Bloom");
}

TEST_CASE("the bloom and glare filters have a property per parameter with its range and items and explanation and display-referred default", "[obs]") {
  ObsSession::get();
  for (const std::string id : {"bloom", "glare"}) {
    const nlohmann::json effect = effect_listing(id);
    const std::string type = "pfx_" + id + "_filter";
    obs_properties_t* props = obs_get_source_properties(type.c_str());
    obs_data_t* defaults = obs_get_source_defaults(type.c_str());
    REQUIRE(props);
    REQUIRE(defaults);
    for (const auto& param : effect["parameters"]) {
      const std::string name = param["id"], kind = param["type"];
      const nlohmann::json value = param.contains("display_default") ? param["display_default"] : param["default"];
      const int components = kind == "color" || kind == "vec3" ? 3 : kind == "vec2" ? 2 : 1;
      for (int c = 0; c < components; ++c) {
        const std::string key = components == 1 ? name : name + "." + std::to_string(c);
        INFO(type << " " << key);
        obs_property_t* property = obs_properties_get(props, key.c_str());
        REQUIRE(property);
        CHECK(std::string(obs_property_long_description(property)) == param["tooltip"].get<std::string>());
        CHECK(std::string(obs_property_description(property)).rfind(param["label"].get<std::string>(), 0) == 0);
        if (kind == "float" || components > 1) {
          CHECK(obs_property_float_min(property) == param["display_min"].get<double>());
          CHECK(obs_property_float_max(property) == param["display_max"].get<double>());
          CHECK(obs_data_get_default_double(defaults, key.c_str()) ==
                Approx(components > 1 ? value[c].get<double>() : value.get<double>()));
        } else if (kind == "int") {
          CHECK(obs_property_int_min(property) == param["display_min"].get<int>());
          CHECK(obs_property_int_max(property) == param["display_max"].get<int>());
          CHECK(obs_data_get_default_int(defaults, key.c_str()) == value.get<int>());
        } else if (kind == "bool") {
          CHECK(obs_data_get_default_bool(defaults, key.c_str()) == value.get<bool>());
        } else {
          REQUIRE(kind == "enum");
          const auto& items = param["items"];
          REQUIRE(obs_property_list_item_count(property) == items.size());
          for (size_t i = 0; i < items.size(); ++i)
            CHECK(std::string(obs_property_list_item_string(property, i)) == items[i]["id"].get<std::string>());
          CHECK(std::string(obs_data_get_default_string(defaults, key.c_str())) == value.get<std::string>());
        }
      }
    }
    obs_data_release(defaults);
    obs_properties_destroy(props);
  }
}

// tests/fx/frame_size/Scanlines.fx: iHeight's default and slider maximum are BUFFER_HEIGHT, one
// dark line per 4 rows of it. A filter on a 320x240 source offers iHeight up to 240 and draws 60
// lines (240 / 4, the file's arithmetic) without anyone setting it; OBS asking for the filter
// type's properties alone gets the listed 1920x1080 range and the explanation.
TEST_CASE("an FX filter's parameter that follows the frame size has the source's range and runs at its default", "[obs][fx]") {
  ::setenv("PFX_FX_PATH", PFX_SOURCE_DIR "/tests/fx/frame_size", 1);  // before the module lists its effects
  ObsSession& obs = ObsSession::get();
  const char* type = "pfx_fx_scanlines_filter";
  obs_properties_t* listed = obs_get_source_properties(type);
  REQUIRE(listed);
  obs_property_t* height = obs_properties_get(listed, "iheight");
  REQUIRE(height);
  CHECK(obs_property_int_max(height) == 1080);
  CHECK(std::string(obs_property_long_description(height)).find("follow the frame size") != std::string::npos);
  obs_properties_destroy(listed);

  obs_source_t* source = obs.color_source(320, 240, 0xff808080);
  obs_source_t* filter = obs.add_filter(source, type);
  REQUIRE(filter);
  obs_properties_t* props = obs_source_properties(filter);
  REQUIRE(props);
  height = obs_properties_get(props, "iheight");
  REQUIRE(height);
  CHECK(obs_property_int_min(height) == 1);
  CHECK(obs_property_int_max(height) == 240);
  CHECK(std::string(obs_property_long_description(height)).find("240 at 320x240") != std::string::npos);
  obs_properties_destroy(props);

  obs.wait_for_ticks();
  const ObsFrame frame = obs.render(source);
  REQUIRE(frame.height == 240);
  int lines = 0;
  bool was_dark = false;
  for (uint32_t y = 0; y < frame.height; ++y) {
    const bool dark = frame.rgba[(y * frame.width + 5) * 4] < 128;
    lines += dark && !was_dark;
    was_dark = dark;
  }
  CHECK(lines == 240 / 4);
  // Released before libobs shuts down: it logs what is still alive with names it has freed.
  obs_source_release(filter);
  obs_source_release(source);
}
