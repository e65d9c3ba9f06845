// Two instances of one effect in a chain, each with its own values (the minimal fixture's "gain"):
// each renders what a chain holding only it renders with that value, values move with their
// instance and leave with it, the report names instances as the store does, and the store never
// has fewer instances than the chain holds, whatever is done to it.
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

TEST_CASE("a move or removal that gives a number other values changes its revision", "[chain][instances]") {
  Rig rig;
  for (int i = 0; i < 3; ++i) rig.add("gain");
  rig.set("gain.gain=2");
  rig.set("gain#2.gain=3");
  rig.set("gain#3.gain=5");
  const uint64_t first = rig.params.revision("gain"), second = rig.params.revision("gain#2"),
                 third = rig.params.revision("gain#3");
  rig.chain->move(2, 0);  // 5, 2, 3: every number holds other values
  CHECK(rig.params.get_text("gain.gain") == "5");
  CHECK(rig.params.get_text("gain#2.gain") == "2");
  CHECK(rig.params.get_text("gain#3.gain") == "3");
  CHECK(rig.params.revision("gain") != first);
  CHECK(rig.params.revision("gain#2") != second);
  CHECK(rig.params.revision("gain#3") != third);

  // Removing the second: the third's values become gain#2, and a viewer watching revisions sees it.
  const uint64_t kept = rig.params.revision("gain"), moved_down = rig.params.revision("gain#2");
  rig.chain->remove(1);  // 5, 3
  CHECK(rig.params.get_text("gain#2.gain") == "3");
  CHECK(rig.params.revision("gain") == kept);
  CHECK(rig.params.revision("gain#2") != moved_down);
}

TEST_CASE("the store keeps a block for every instance its chain holds", "[chain][instances]") {
  Rig rig;
  rig.add("gain");
  rig.add("gain");
  rig.set("gain.gain=2");
  rig.set("gain#2.gain=0.5");
  rig.chain->set_enabled(0, false);

  // Neither shrinking nor forgetting takes the chain's values away.
  CHECK_FALSE(rig.params.set_instance_count("gain", 1));
  CHECK_FALSE(rig.params.remove_effect("gain"));
  CHECK(rig.params.instance_count("gain") == 2);
  REQUIRE(rig.params.set_instance_count("gain", 3));  // more than the chain holds: a preset's
  REQUIRE(rig.params.set_instance_count("gain", 2));
  CHECK(rig.render(input()).rgba == single_gain("0.5").rgba);

  // A store assigned over the chain's keeps its instances: values from the assigned store where it
  // has them, the defaults where it has none.
  pfx::host::ParamStore one_gain;
  one_gain.add_effect(rig.registry->find_effect("gain")->desc);
  std::string error;
  REQUIRE(one_gain.set_assignment("gain.gain=3", &error));
  rig.params = one_gain;
  CHECK(rig.params.instance_count("gain") == 2);
  CHECK(rig.params.get_text("gain.gain") == "3");
  CHECK(rig.params.get_text("gain#2.gain") == "1");
  CHECK(rig.render(input()).rgba == single_gain("1").rgba);
  // Even one without the effect at all: the chain keeps the values it had.
  rig.set("gain#2.gain=0.5");
  rig.params = pfx::host::ParamStore();
  CHECK(rig.params.get_text("gain#2.gain") == "0.5");
  CHECK(rig.render(input()).rgba == single_gain("0.5").rgba);

  // A copy holds no instance of the chain's: it is shaped freely.
  pfx::host::ParamStore copy = rig.params;
  CHECK(copy.set_instance_count("gain", 1));
  CHECK(copy.remove_effect("gain"));

  // Once the chain is gone the store is shaped freely, and its values are still there.
  rig.chain.reset();
  CHECK(rig.params.get_text("gain#2.gain") == "0.5");
  CHECK(rig.params.set_instance_count("gain", 1));
  CHECK(rig.params.remove_effect("gain"));
}
