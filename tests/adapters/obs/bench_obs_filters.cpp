// Not a test: the time a frame takes at 1920x1080 through pfx's filters, against the same source
// with no filter and with stock OBS filters, and against a plain copy pass, all in one run (the
// table of docs/hosts.md). Hidden from ctest; run by hand:
//   xvfb-run -a build/bin/test_obs_filters '[.bench]'
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

#include <EGL/egl.h>

#include "obs_pictures.hpp"
#include "obs_session.hpp"
#include "png_io.hpp"
#include "render_process.hpp"

using namespace pfx::test;

namespace {

constexpr uint32_t kWidth = 1920, kHeight = 1080;

// The photograph mirrored into a 1920x1080 frame, so every pixel is a real picture's.
void write_full_hd(const std::string& path) {
  const auto photo = read_picture(PFX_TEST_PHOTOGRAPH);
  pfx::app::DisplayImage frame{int(kWidth), int(kHeight), 4, {}};
  frame.pixels.resize(size_t{kWidth} * kHeight * 4);
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      const int period_x = 2 * photo.width, period_y = 2 * photo.height;
      int px = int(x) % period_x, py = int(y) % period_y;
      if (px >= photo.width) px = period_x - 1 - px;
      if (py >= photo.height) py = period_y - 1 - py;
      std::copy_n(&photo.pixels[(size_t(py) * photo.width + px) * 4], 4, &frame.pixels[(size_t{y} * kWidth + x) * 4]);
    }
  std::string error;
  REQUIRE(pfx::app::write_png(path, frame, &error));
}

// Seconds for `frames` calls of draw into a 1080p target, waited for by reading one pixel back.
double timed(int frames, gs_texrender_t* target, gs_stagesurf_t* stage, const std::function<void()>& draw) {
  obs_enter_graphics();
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i) {
    gs_texrender_reset(target);
    if (gs_texrender_begin(target, kWidth, kHeight)) {
      gs_ortho(0.0f, float(kWidth), 0.0f, float(kHeight), -100.0f, 100.0f);
      draw();
      gs_texrender_end(target);
    }
  }
  gs_stage_texture(stage, gs_texrender_get_texture(target));
  uint8_t* data = nullptr;
  uint32_t line = 0;
  if (gs_stagesurface_map(stage, &data, &line)) gs_stagesurface_unmap(stage);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  obs_leave_graphics();
  return seconds;
}

// Milliseconds one more frame takes: (16 frames - 4 frames) / 12, median of 3 runs.
double ms_per_frame(gs_texrender_t* target, gs_stagesurf_t* stage, const std::function<void()>& draw) {
  timed(2, target, stage, draw);  // first-use work (programs, textures)
  std::vector<double> runs;
  for (int run = 0; run < 3; ++run)
    runs.push_back((timed(16, target, stage, draw) - timed(4, target, stage, draw)) / 12 * 1000);
  std::sort(runs.begin(), runs.end());
  return runs[1];
}

}  // namespace

TEST_CASE("bench: a 1920x1080 frame through pfx's filters and OBS's own", "[.bench]") {
  ObsSession& obs = ObsSession::get();
  Scratch scratch;
  write_full_hd(scratch / "frame.png");
  obs_source_t* image = obs.image_source(scratch / "frame.png");
  REQUIRE(obs_source_get_width(image) == kWidth);
  obs_enter_graphics();
  gs_texrender_t* target = gs_texrender_create(GS_RGBA, GS_ZS_NONE);
  gs_texrender_t* copy_target = gs_texrender_create(GS_RGBA16F, GS_ZS_NONE);
  gs_stagesurf_t* stage = gs_stagesurface_create(kWidth, kHeight, GS_RGBA);
  gs_stagesurf_t* copy_stage = gs_stagesurface_create(kWidth, kHeight, GS_RGBA16F);
  gs_texture_t* half = gs_texture_create(kWidth, kHeight, GS_RGBA16F, 1, nullptr, GS_RENDER_TARGET);
  obs_leave_graphics();

  // A plain copy pass: a 1080p RGBA16F texture drawn into another by OBS's default effect.
  const double copy = ms_per_frame(copy_target, copy_stage, [&] {
    gs_effect_t* effect = obs_get_base_effect(OBS_EFFECT_DEFAULT);
    gs_effect_set_texture(gs_effect_get_param_by_name(effect, "image"), half);
    while (gs_effect_loop(effect, "Draw")) gs_draw_sprite(half, 0, kWidth, kHeight);
  });
  const double plain = ms_per_frame(target, stage, [&] { obs_source_video_render(image); });
  obs_enter_graphics();
  using GetString = const unsigned char* (*)(unsigned int);
  const auto get_string = reinterpret_cast<GetString>(eglGetProcAddress("glGetString"));
  std::printf("renderer: %s\n", reinterpret_cast<const char*>(get_string(0x1F01)));  // GL_RENDERER
  obs_leave_graphics();
  std::printf("copy pass (RGBA16F 1920x1080): %.2f ms\n", copy);
  std::printf("| filter | ms a frame | added ms | added, in copy passes |\n|---|---|---|---|\n");
  std::printf("| no filter (the image source drawn) | %.1f |  |  |\n", plain);

  struct Config {
    const char* label;
    const char* type;
    std::function<void(obs_data_t*)> settings;
  };
  static constexpr const char* kChainBloom = "pfx chain, `chain=bloom`";
  static constexpr const char* kChainBloomTwice = "pfx chain, `chain=bloom,bloom`";
  const Config configs[] = {
      {"OBS Sharpen (`sharpness_filter_v2`, stock)", "sharpness_filter_v2", [](obs_data_t*) {}},
      {"OBS Color Correction (`color_filter_v2`, stock)", "color_filter_v2", [](obs_data_t* s) { obs_data_set_double(s, "gamma", 0.3); }},
      {"pfx chain, `chain=none`", "pfx_chain_filter", [](obs_data_t* s) { obs_data_set_string(s, "chain", "none"); }},
      {"pfx chain, bloom at strength 0 (a no-op)", "pfx_chain_filter",
       [](obs_data_t* s) {
         obs_data_set_string(s, "chain", "bloom");
         obs_data_set_string(s, "set", "bloom.strength=0");
       }},
      {"pfx Bloom (defaults)", "pfx_bloom_filter", [](obs_data_t*) {}},
      {kChainBloom, "pfx_chain_filter", [](obs_data_t* s) { obs_data_set_string(s, "chain", "bloom"); }},
      {kChainBloomTwice, "pfx_chain_filter", [](obs_data_t* s) { obs_data_set_string(s, "chain", "bloom,bloom"); }},
      {"pfx Glare (defaults)", "pfx_glare_filter", [](obs_data_t*) {}},
  };
  double chain_bloom = 0, chain_bloom_twice = 0;
  for (const Config& config : configs) {
    obs_data_t* settings = obs_data_create();
    config.settings(settings);
    obs_source_t* filter = obs.add_filter(image, config.type, settings);
    obs.wait_for_ticks();
    const double ms = ms_per_frame(target, stage, [&] { obs_source_video_render(image); });
    std::printf("| %s | %.1f | %.1f | %.2f |\n", config.label, ms, ms - plain, (ms - plain) / copy);
    if (config.label == kChainBloom) chain_bloom = ms;
    if (config.label == kChainBloomTwice) chain_bloom_twice = ms;
    obs_source_filter_remove(image, filter);
    obs_source_release(filter);
    obs_data_release(settings);
  }
  // What the filter adds around bloom's passes: bloom's time less what a second bloom adds, so that
  // no pass timer is trusted.
  const double around = chain_bloom - (chain_bloom_twice - chain_bloom) - plain;
  std::printf("pfx chain around bloom's passes: %.1f ms, %.2f copy passes\n", around, around / copy);
  obs_enter_graphics();
  gs_texture_destroy(half);
  gs_stagesurface_destroy(copy_stage);
  gs_stagesurface_destroy(stage);
  gs_texrender_destroy(copy_target);
  gs_texrender_destroy(target);
  obs_leave_graphics();
  obs_source_release(image);
}
