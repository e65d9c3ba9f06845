// pfx's filters in libobs itself (OBS Studio's library, its OpenGL renderer under Xvfb): the
// harness reads back the picture it was given; the filters give pfx-render's frame within one
// code, keep each instance's values, follow property and size changes, keep alpha, leave OBS's
// state for the stock filters after them, and pass the source through on bad settings.
#include <catch2/catch.hpp>

#include <cstdlib>

#include "obs_pictures.hpp"
#include "obs_session.hpp"
#include "png_io.hpp"
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

TEST_CASE("a libretro preset in the chain filter, its content size set, gives the frame of pfx-render within one code",
          "[obs]") {
  // Before the plugins load: the libretro plugin reads its folders once per process.
  setenv("PFX_LIBRETRO_PATH", PFX_SOURCE_DIR "/tests/libretro/conformance", 1);
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  const auto picture = write_photo_crop(scratch / "in.png", 200, 180, 96, 64);
  const auto reference = pfx_render_picture(scratch / "in.png", "libretro_passthrough",
                                            {"libretro_passthrough.content_height=16"}, scratch / "pfx-render.png");
  REQUIRE(worst_difference_pictures(reference, picture) > 8);  // 16 lines of content over 64 show

  obs_source_t* image = obs.image_source(scratch / "in.png");
  obs_data_t* values = settings_of([](obs_data_t* s) {
    obs_data_set_string(s, "chain", "libretro_passthrough");
    obs_data_set_string(s, "set", "libretro_passthrough.content_height=16");
  });
  obs_source_t* chain = obs.add_filter(image, "pfx_chain_filter", values);
  CHECK(worst_difference(obs.render(image), reference) <= 1);
  obs_data_release(values);
  release({chain, image});
}

// Not a test: a collection's presets in OBS against pfx-render, by hand, at a size and content
// height given. OBS counts frames its own way, so a preset that reads FrameCount (NTSC phases) is
// compared with pfx-render's frames 0 to 3 and the closest is taken. Hidden from ctest; run with
// the collection and a picture named:
//   export PFX_LIBRETRO_PATH=slang-shaders/crt PFX_OBS_PICTURE=photo.png PFX_OBS_CONTENT_HEIGHT=240
//   PFX_OBS_EFFECTS=libretro_crt_geom,libretro_crt_lottes xvfb-run -a build/bin/test_obs_filters '[.libretro]'
TEST_CASE("libretro presets of a collection in the chain filter against pfx-render, by hand", "[.libretro]") {
  const char* effects = std::getenv("PFX_OBS_EFFECTS");
  const char* picture = std::getenv("PFX_OBS_PICTURE");
  const char* lines = std::getenv("PFX_OBS_CONTENT_HEIGHT");
  REQUIRE(effects);
  REQUIRE(picture);
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  for (int k = 0; k < 4; ++k) std::filesystem::copy_file(picture, scratch / ("in." + std::to_string(k) + ".png"));
  const std::string list = effects;
  for (std::size_t start = 0; start < list.size();) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string effect = list.substr(start, end - start);
    start = end + 1;
    const std::string set = lines ? effect + ".content_height=" + lines : std::string();
    obs_source_t* image = obs.image_source(picture);
    obs_data_t* values = settings_of([&](obs_data_t* s) {
      obs_data_set_string(s, "chain", effect.c_str());
      obs_data_set_string(s, "set", set.c_str());
    });
    obs_source_t* chain = obs.add_filter(image, "pfx_chain_filter", values);
    const ObsFrame frame = obs.render(image);
    const Result made = pfx_render("--plugins " PFX_PLUGIN_OUTPUT_DIR " --input " + (scratch / "in.%d.png") +
                                   " --frames 0-3 --chain " + effect + (set.empty() ? "" : " --set " + set) +
                                   " --out " + (scratch / (effect + ".%d.png")));
    INFO(made.err);
    REQUIRE(made.exit_code == 0);
    int best = 256, best_frame = 0;
    for (int k = 0; k < 4; ++k) {
      const int worst = worst_difference(frame, read_picture(scratch / (effect + "." + std::to_string(k) + ".png")));
      if (worst < best) best = worst, best_frame = k;
    }
    std::printf("%s: %ux%u in OBS, at most %d codes from pfx-render's frame %d, which changed the picture by up to "
                "%d\n",
                effect.c_str(), frame.width, frame.height, best, best_frame,
                worst_difference_pictures(read_picture(scratch / (effect + ".0.png")), read_picture(picture)));
    std::fflush(stdout);  // each line as it comes: a collection's presets take long
    CHECK(best <= 1);
    obs_data_release(values);
    release({chain, image});
  }
}

TEST_CASE("the picture in docs/hosts.md is what the bloom filter gives in OBS", "[obs]") {
  // PFX_OBS_WRITE_DOCS_PICTURES=1 makes the pair first: the before picture cut from a photograph
  // Debian ships, the after picture what OBS gives now.
  ObsSession& obs = ObsSession::get();
  const std::string before = PFX_SOURCE_DIR "/docs/hosts/obs-before.png", after = PFX_SOURCE_DIR "/docs/hosts/obs-after.png";
  const bool write = std::getenv("PFX_OBS_WRITE_DOCS_PICTURES") != nullptr;
  if (write) write_photo_crop(before, 40, 100, 384, 288, false, "/usr/share/glmark2/textures/nasa2.png");
  obs_source_t* image = obs.image_source(before);
  obs_data_t* values = obs_data_create();
  obs_data_set_double(values, "threshold", 0.4);
  obs_data_set_double(values, "strength", 3);
  obs_source_t* bloom = obs.add_filter(image, "pfx_bloom_filter", values);
  const ObsFrame frame = obs.render(image);
  if (write) {
    pfx::app::DisplayImage picture{int(frame.width), int(frame.height), 4, frame.rgba};
    std::string error;
    REQUIRE(pfx::app::write_png(after, picture, &error));
  }
  CHECK(worst_difference(frame, read_picture(after)) <= 1);
  obs_data_release(values);
  obs_source_release(bloom);
  obs_source_release(image);
}
