// pfx's filters in libobs itself (OBS Studio's library, its OpenGL renderer under Xvfb): the
// harness reads back the picture it was given; the filters give pfx-render's frame within one
// code, keep each instance's values, follow property and size changes, keep alpha, leave OBS's
// state for the stock filters after them, and pass the source through on bad settings.
#include <catch2/catch.hpp>

#include "obs_pictures.hpp"
#include "obs_session.hpp"
#include "render_process.hpp"

using namespace pfx::test;

namespace {

// Settings for a filter: `build` fills them.
template <typename Build>
obs_data_t* settings_of(Build build) {
  obs_data_t* settings = obs_data_create();
  build(settings);
  return settings;
}

void release(std::initializer_list<obs_source_t*> sources) {
  for (obs_source_t* source : sources) obs_source_release(source);
}

}  // namespace

TEST_CASE("the unfiltered frame is the picture of an image source and a colour source", "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  const auto picture = write_photo_crop(scratch / "in.png", 200, 180, 96, 64);
  obs_source_t* image = obs.image_source(scratch / "in.png");
  CHECK(worst_difference(obs.render(image), picture) == 0);
  obs_source_t* colour = obs.color_source(20, 10, 0xff2040c0);
  const ObsFrame flat = obs.render(colour);
  REQUIRE(flat.rgba.size() == 20 * 10 * 4);
  for (size_t i = 0; i < flat.rgba.size(); i += 4) {
    CHECK(flat.rgba[i] == 0xc0);
    CHECK(flat.rgba[i + 1] == 0x40);
    CHECK(flat.rgba[i + 2] == 0x20);
    CHECK(flat.rgba[i + 3] == 0xff);
  }
  release({image, colour});
}

TEST_CASE("the bloom filter and the chain filter give the frame of pfx-render within one code", "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  const auto picture = write_photo_crop(scratch / "in.png", 200, 180, 96, 64);
  const auto reference = pfx_render_picture(scratch / "in.png", "bloom", {"bloom.threshold=0.5", "bloom.strength=2"},
                                            scratch / "pfx-render.png");
  REQUIRE(worst_difference_pictures(reference, picture) > 8);  // bloom shows on this picture

  obs_source_t* image = obs.image_source(scratch / "in.png");
  obs_data_t* values = settings_of([](obs_data_t* s) {
    obs_data_set_double(s, "threshold", 0.5);
    obs_data_set_double(s, "strength", 2);
  });
  obs_source_t* bloom = obs.add_filter(image, "pfx_bloom_filter", values);
  CHECK(worst_difference(obs.render(image), reference) <= 1);
  obs_source_filter_remove(image, bloom);

  obs_data_t* chain_values = settings_of([](obs_data_t* s) {
    obs_data_set_string(s, "chain", "bloom");
    obs_data_set_string(s, "set", "bloom.threshold=0.5; bloom.strength=2");
  });
  obs_source_t* chain = obs.add_filter(image, "pfx_chain_filter", chain_values);
  CHECK(worst_difference(obs.render(image), reference) <= 1);
  obs_data_release(values);
  obs_data_release(chain_values);
  release({bloom, chain, image});
}
