// Two instances of one effect in a chain, each with its own values (the minimal fixture's "gain"):
// each renders what a chain holding only it renders with that value, values move with their
// instance and leave with it, and the report names instances as the store does.
#include <catch2/catch.hpp>

#include "gl_test_support.hpp"
#include "image_texture.hpp"

using pfx::app::Image;

namespace {

struct Rig {
  std::unique_ptr<pfx::host::PluginRegistry> registry = pfx::test::make_registry();
  pfx::host::ParamStore params;
  std::unique_ptr<pfx::host::Chain> chain;
  Rig() {
    std::string error;
    REQUIRE(registry->load(PFX_TEST_MINIMAL_PLUGIN, &error));
    chain = std::make_unique<pfx::host::Chain>(*registry, params);
  }
  void add(const std::string& effect) {
    std::string error;
    INFO(error);
    REQUIRE(chain->add(effect, &error));
  }
  void set(const std::string& assignment) {
    std::string error;
    INFO(error);
    REQUIRE(params.set_assignment(assignment, &error));
  }
  Image render(const Image& img) {
    pfx::host::FrameTextures textures;
    textures.color = pfx::app::upload_color_texture(img);
    uint32_t output = pfx::app::create_color_texture(img.width, img.height);
    std::string error;
    const bool ok = chain->render(pfx::test::make_frame(img.width, img.height), textures, output, &error);
    Image result = pfx::app::download_color_texture(output, img.width, img.height);
    pfx::app::delete_texture(textures.color);
    pfx::app::delete_texture(output);
    INFO(error);
    REQUIRE(ok);
    return result;
  }
};

const Image& input() {
  static const Image image = pfx::test::test_image(21, 13);
  return image;
}

// What a chain holding one gain renders with this value: the reference for each instance.
Image single_gain(const std::string& value) {
  Rig rig;
  rig.add("gain");
  rig.set("gain.gain=" + value);
  return rig.render(input());
}

}  // namespace

TEST_CASE("two instances of one effect keep their own values and each renders as it would alone",
          "[chain][instances]") {
  Rig rig;
  rig.add("gain");
  rig.add("boxblur");
  rig.add("gain");
  rig.chain->set_enabled(1, false);
  rig.set("gain.gain=2");
  rig.set("gain#2.gain=0.5");
  CHECK(rig.chain->instance_name(0) == "gain");
  CHECK(rig.chain->instance_name(2) == "gain#2");
  CHECK(rig.chain->instance_number(2) == 2);

  const Image two = single_gain("2"), half = single_gain("0.5");
  REQUIRE(two.rgba != half.rgba);  // the values make different pictures
  rig.chain->set_enabled(2, false);
  CHECK(rig.render(input()).rgba == two.rgba);
  rig.chain->set_enabled(0, false);
  rig.chain->set_enabled(2, true);
  CHECK(rig.render(input()).rgba == half.rgba);
  CHECK(rig.chain->report().effects_run == std::vector<std::string>{"gain#2"});
  CHECK(rig.chain->report().effects_skipped == std::vector<std::string>{"gain", "boxblur"});
  REQUIRE(rig.chain->report().passes.size() == 1);
  CHECK(rig.chain->report().passes[0].effect == "gain#2");

  // "gain#1" is "gain".
  rig.set("gain#1.gain=3");
  CHECK(rig.params.get_text("gain.gain") == "3");
  rig.chain->set_enabled(0, true);
  rig.chain->set_enabled(2, false);
  CHECK(rig.render(input()).rgba == single_gain("3").rgba);

  // Both on: 3 then 0.5, within the half-float rounding of the intermediate.
  rig.chain->set_enabled(2, true);
  const Image both = rig.render(input());
  for (size_t i = 0; i < both.rgba.size(); ++i) {
    const float expected = (i % 4 == 3) ? input().rgba[i] : input().rgba[i] * 1.5f;
    REQUIRE(both.rgba[i] == Approx(expected).epsilon(3.0 / 1024).margin(1e-6));
  }
  REQUIRE(rig.chain->report().passes.size() == 2);
  CHECK(rig.chain->report().passes[0].effect == "gain");
  CHECK(rig.chain->report().passes[1].effect == "gain#2");
}

TEST_CASE("an instance moved past another of its effect takes its values along", "[chain][instances]") {
  Rig rig;
  rig.add("gain");
  rig.add("gain");
  rig.set("gain.gain=2");
  rig.set("gain#2.gain=0.5");
  rig.chain->set_enabled(1, false);
  rig.chain->move(1, 0);  // the disabled 0.5 goes first and becomes gain#1
  CHECK(rig.chain->enabled(0) == false);
  CHECK(rig.chain->instance_name(1) == "gain#2");
  CHECK(rig.params.get_text("gain.gain") == "0.5");
  CHECK(rig.params.get_text("gain#2.gain") == "2");
  CHECK(rig.render(input()).rgba == single_gain("2").rgba);

  // Past another effect only: the numbers and values stay.
  rig.add("boxblur");
  rig.chain->move(2, 0);
  CHECK(rig.chain->effect_id(0) == "boxblur");
  CHECK(rig.params.get_text("gain.gain") == "0.5");
  CHECK(rig.params.get_text("gain#2.gain") == "2");
}

TEST_CASE("removing an instance drops its values and the others renumber", "[chain][instances]") {
  Rig rig;
  for (int i = 0; i < 3; ++i) rig.add("gain");
  rig.set("gain.gain=2");
  rig.set("gain#2.gain=3");
  rig.set("gain#3.gain=5");
  rig.chain->remove(0);
  CHECK(rig.params.instance_count("gain") == 2);
  CHECK(rig.params.get_text("gain.gain") == "3");
  CHECK(rig.params.get_text("gain#2.gain") == "5");
  std::string error;
  CHECK_FALSE(rig.params.set_assignment("gain#3.gain=1", &error));
  CHECK(error == "'gain#3.gain': there is no gain#3, effect 'gain' has 2 instances");
  rig.chain->set_enabled(1, false);
  CHECK(rig.render(input()).rgba == single_gain("3").rgba);

  // The last instance to leave keeps its values in the store: a chain rebuilt from scratch (as a
  // host with one instance per effect does) finds them again.
  rig.chain->remove(0);
  CHECK(rig.params.get_text("gain.gain") == "5");
  rig.chain->remove(0);
  CHECK(rig.params.instance_count("gain") == 1);
  CHECK(rig.params.get_text("gain.gain") == "5");
  rig.add("gain");
  CHECK(rig.render(input()).rgba == single_gain("5").rgba);
  // A new second instance starts at the defaults.
  rig.add("gain");
  CHECK(rig.params.get_text("gain#2.gain") == "1");
}
