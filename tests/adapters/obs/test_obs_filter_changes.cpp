// pfx's OBS filters as a scene changes: two filters of one effect keep their own values, a
// property change shows in the next frame, the filter follows the source's size and keeps its
// alpha, and bad settings pass the source through with a line in OBS's log, once they have held
// (not one per keystroke while a user types into a text field).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include <catch2/catch.hpp>

#include "obs_pictures.hpp"
#include "obs_session.hpp"
#include "render_process.hpp"

using namespace pfx::test;

namespace {

obs_data_t* bloom_values(double threshold, double strength) {
  obs_data_t* settings = obs_data_create();
  obs_data_set_double(settings, "threshold", threshold);
  obs_data_set_double(settings, "strength", strength);
  return settings;
}

obs_data_t* chain_values(const char* chain, const char* set, const char* preset = "") {
  obs_data_t* settings = obs_data_create();
  obs_data_set_string(settings, "chain", chain);
  obs_data_set_string(settings, "set", set);
  obs_data_set_string(settings, "preset", preset);
  return settings;
}

}  // namespace

TEST_CASE("two bloom filters on one source keep their own values", "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  write_photo_crop(scratch / "in.png", 120, 300, 80, 56);
  const auto reference = pfx_render_picture(
      scratch / "in.png", "bloom,bloom",
      {"bloom.threshold=0.5", "bloom.strength=2", "bloom#2.threshold=0.2", "bloom#2.strength=1.5"},
      scratch / "pfx-render.png");
  obs_source_t* image = obs.image_source(scratch / "in.png");
  obs_data_t* first = bloom_values(0.5, 2), *second = bloom_values(0.2, 1.5);
  obs_source_t* filter1 = obs.add_filter(image, "pfx_bloom_filter", first);
  obs_source_t* filter2 = obs.add_filter(image, "pfx_bloom_filter", second);
  CHECK(worst_difference(obs.render(image), reference) <= 1);
  obs_data_release(first);
  obs_data_release(second);
  obs_source_release(filter1);
  obs_source_release(filter2);
  obs_source_release(image);
}

TEST_CASE("a property changed between frames changes the next frame", "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  write_photo_crop(scratch / "in.png", 200, 180, 64, 48);
  const auto strong = pfx_render_picture(scratch / "in.png", "bloom", {"bloom.threshold=0.5", "bloom.strength=2"},
                                         scratch / "strong.png");
  const auto weak = pfx_render_picture(scratch / "in.png", "bloom", {"bloom.threshold=0.5", "bloom.strength=0.25"},
                                       scratch / "weak.png");
  REQUIRE(worst_difference_pictures(strong, weak) > 8);
  obs_source_t* image = obs.image_source(scratch / "in.png");
  obs_data_t* values = bloom_values(0.5, 2);
  obs_source_t* bloom = obs.add_filter(image, "pfx_bloom_filter", values);
  CHECK(worst_difference(obs.render(image), strong) <= 1);
  obs_data_t* change = obs_data_create();
  obs_data_set_double(change, "strength", 0.25);
  obs_source_update(bloom, change);
  CHECK(worst_difference(obs.render(image), weak) <= 1);
  obs_data_release(change);
  obs_data_release(values);
  obs_source_release(bloom);
  obs_source_release(image);
}

TEST_CASE("the filter follows the size of its source and keeps its alpha", "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  write_photo_crop(scratch / "big.png", 200, 180, 72, 40);
  write_photo_crop(scratch / "small.png", 260, 100, 37, 23, true);  // odd sizes, alpha falling to 0
  const auto big = pfx_render_picture(scratch / "big.png", "bloom", {"bloom.threshold=0.5"}, scratch / "big-pfx.png");
  obs_source_t* image = obs.image_source(scratch / "small.png");
  const ObsFrame plain = obs.render(image);
  obs_data_t* file = obs_data_create();
  obs_data_set_string(file, "file", (scratch / "big.png").c_str());
  obs_source_update(image, file);
  obs_data_t* values = bloom_values(0.5, 1);
  obs_source_t* bloom = obs.add_filter(image, "pfx_bloom_filter", values);
  CHECK(worst_difference(obs.render(image), big) <= 1);

  obs_data_set_string(file, "file", (scratch / "small.png").c_str());
  obs_source_update(image, file);
  const ObsFrame small = obs.render(image);
  REQUIRE(small.width == 37);
  REQUIRE(small.height == 23);
  int alpha_worst = 0, colour_changed = 0;
  for (size_t i = 0; i < small.rgba.size(); ++i) {
    if (i % 4 == 3) alpha_worst = std::max(alpha_worst, std::abs(small.rgba[i] - plain.rgba[i]));
    else colour_changed += small.rgba[i] != plain.rgba[i];
  }
  CHECK(plain.rgba[3] == 255);
  CHECK(plain.rgba[small.width * 4 - 1] == 0);
  CHECK(alpha_worst == 0);
  CHECK(colour_changed > 100);
  obs_data_release(values);
  obs_data_release(file);
  obs_source_release(bloom);
  obs_source_release(image);
}

TEST_CASE("bad settings pass the source through with a line in the log and good ones apply again", "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  const auto picture = write_photo_crop(scratch / "in.png", 200, 180, 48, 32);
  const auto reference = pfx_render_picture(scratch / "in.png", "bloom", {"bloom.threshold=0.5"}, scratch / "pfx.png");
  REQUIRE(worst_difference_pictures(reference, picture) > 8);
  {
    std::FILE* bad = std::fopen((scratch / "bad-preset.json").c_str(), "w");
    std::fputs("{ this is not a preset", bad);
    std::fclose(bad);
  }
  obs_source_t* image = obs.image_source(scratch / "in.png");
  obs_data_t* good = chain_values("bloom", "bloom.threshold=0.5");
  obs_source_t* chain = obs.add_filter(image, "pfx_chain_filter", good);
  CHECK(worst_difference(obs.render(image), reference) <= 1);
  struct Bad {
    const char *chain, *set;
    std::string preset, named;
  };
  const Bad bad[] = {{"bloom,nosuch", "", "", "nosuch"},
                     {"bloom", "bloom.nosuch=1", "", "nosuch"},
                     {"bloom", "bloom.threshold=banana", "", "banana"},
                     {"", "", scratch / "missing.json", "missing.json"},
                     {"", "", scratch / "bad-preset.json", "bad-preset.json"}};
  for (const Bad& setting : bad) {
    INFO(setting.chain << " | " << setting.set << " | " << setting.preset);
    obs.clear_log();
    obs_data_t* values = chain_values(setting.chain, setting.set, setting.preset.c_str());
    obs_source_update(chain, values);
    obs_data_release(values);
    CHECK(worst_difference(obs.render(image), picture) == 0);
    // Said once the settings have held a second (a user may still be typing before that).
    CHECK(obs.log().find(setting.named) == std::string::npos);
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    CHECK(worst_difference(obs.render(image), picture) == 0);
    const std::string log = obs.log();
    INFO(log);
    CHECK(log.find("[pfx-obs]") != std::string::npos);
    CHECK(log.find(setting.named) != std::string::npos);
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    CHECK(worst_difference(obs.render(image), picture) == 0);  // said once, still passing through
    CHECK(obs.log() == log);
  }
  // The filter's settings are the object it was made with (OBS keeps a reference): a new one.
  obs_data_t* good_again = chain_values("bloom", "bloom.threshold=0.5");
  obs_source_update(chain, good_again);
  CHECK(worst_difference(obs.render(image), reference) <= 1);
  obs_data_release(good_again);
  obs_data_release(good);
  obs_source_release(chain);
  obs_source_release(image);
}

TEST_CASE("typing an effect name into the chain field logs nothing on the way and one line for a name that stays bad",
          "[obs]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  const auto picture = write_photo_crop(scratch / "in.png", 200, 180, 48, 32);
  obs_source_t* image = obs.image_source(scratch / "in.png");
  obs_data_t* empty = chain_values("", "");
  obs_source_t* chain = obs.add_filter(image, "pfx_chain_filter", empty);
  obs.render(image);
  obs.clear_log();
  // OBS applies the field at each keystroke; a frame is drawn between keystrokes (a 60 Hz preview
  // draws several), each keystroke well inside the time a warning waits.
  for (const char* typed : {"b", "bl", "blo", "bloo", "bloom", "bloom,", "bloom,g", "bloom,gl", "bloom,gla"}) {
    obs_data_t* values = chain_values(typed, "");
    obs_source_update(chain, values);
    obs_data_release(values);
    obs.render(image);
    obs.render(image);
  }
  INFO(obs.log());
  CHECK(obs.log().find("[pfx-obs]") == std::string::npos);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  obs.render(image);
  const std::string log = obs.log();
  INFO(log);
  // The name the user stopped at, in exactly one line.
  CHECK(log.find("gla") != std::string::npos);
  size_t lines = 0;
  for (size_t at = log.find("[pfx-obs]"); at != std::string::npos; at = log.find("[pfx-obs]", at + 1)) ++lines;
  CHECK(lines == 1);
  obs_data_release(empty);
  obs_source_release(chain);
  obs_source_release(image);
}

TEST_CASE("a ReShade preset as users share it gives pfx-render's frame of what applies, and one line names what it left out",
          "[obs][fx]") {
  ::setenv("PFX_FX_PATH", PFX_SOURCE_DIR "/tests/fx/presets/Shaders", 1);  // before the module lists its effects
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  const auto picture = write_photo_crop(scratch / "in.png", 200, 180, 96, 64);
  // From a Windows editor (a byte-order mark, CRLF), naming a technique whose file is not here and
  // values that do not fit; the chain is the preset's (the filter's chain field left empty).
  const std::string preset = scratch / "shared.ini";
  {
    std::FILE* file = std::fopen(preset.c_str(), "wb");
    std::fputs("\xEF\xBB\xBF; shared\r\nTechniques=Grade@Grade.fx,Bogus@Bogus.fx,Edge@Edge.fx\r\n"
               "TechniqueSorting=Edge@Edge.fx,Bogus@Bogus.fx,Grade@Grade.fx\r\n\r\n"
               "[Grade.fx]\r\nLift=0.1\r\nGain=0.800000\r\nGain=1.500000\r\nInvert=1\r\n\r\n[Edge.fx]\r\nStrength=0.5\r\n",
               file);
    std::fclose(file);
  }
  const auto reference = pfx_render_picture(scratch / "in.png", "fx_edge,fx_grade",
                                            {"fx_edge.strength=0.5", "fx_grade.gain=0.8", "fx_grade.invert=1"},
                                            scratch / "pfx.png");
  REQUIRE(worst_difference_pictures(reference, picture) > 8);

  obs.clear_log();
  obs_source_t* image = obs.image_source(scratch / "in.png");
  obs_data_t* values = chain_values("", "", preset.c_str());
  obs_source_t* chain = obs.add_filter(image, "pfx_chain_filter", values);
  CHECK(worst_difference(obs.render(image), reference) <= 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // the log line waits for settings that hold
  CHECK(worst_difference(obs.render(image), reference) <= 1);
  const std::string log = obs.log();
  INFO(log);
  const size_t line = log.find("left out: fx_bogus (not loaded), fx_grade.lift (expects 3 numbers, got 1)");
  CHECK(line != std::string::npos);
  CHECK(log.find("left out:", line + 1) == std::string::npos);
  obs_data_release(values);
  obs_source_release(chain);
  obs_source_release(image);
}
