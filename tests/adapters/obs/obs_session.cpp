#include "obs_session.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <chrono>
#include <mutex>
#include <thread>

#include <catch2/catch.hpp>
#include <obs-nix-platform.h>

#include "obs_test_video.hpp"
// Last: Xlib's macros (None, Always) clash with names in the headers above.
#include <X11/Xlib.h>

namespace pfx::test {
namespace {

std::mutex g_log_mutex;
std::string g_log;
Display* g_display = nullptr;

void capture_log(int level, const char* format, va_list args, void*) {
  char line[4096];
  std::vsnprintf(line, sizeof line, format, args);
  std::lock_guard<std::mutex> lock(g_log_mutex);
  // Warnings and errors go to the test's output; PFX_OBS_TEST_LOG=1 shows every line libobs logs.
  if (level <= LOG_WARNING || std::getenv("PFX_OBS_TEST_LOG")) std::fprintf(stderr, "libobs: %s\n", line);
  g_log += line;
  g_log += '\n';
}

void load_module(const std::string& file, const std::string& data) {
  obs_module_t* module = nullptr;
  const int opened = obs_open_module(&module, file.c_str(), data.c_str());
  INFO(file);
  REQUIRE(opened == MODULE_SUCCESS);
  REQUIRE(obs_init_module(module));
}

}  // namespace

ObsSession& ObsSession::get() {
  static ObsSession session;
  return session;
}

ObsSession::ObsSession() {
  base_set_log_handler(capture_log, nullptr);
  g_display = XOpenDisplay(nullptr);
  REQUIRE(g_display);  // run under xvfb-run
  obs_set_nix_platform(OBS_NIX_PLATFORM_X11_EGL);
  obs_set_nix_platform_display(g_display);
  REQUIRE(obs_startup("en-US", nullptr, nullptr));
  obs_video_info video = obs_test_video();
  INFO(log());
  REQUIRE(obs_reset_video(&video) == OBS_VIDEO_SUCCESS);
  const std::string stock = OBS_STOCK_MODULE_DIR, stock_data = OBS_STOCK_DATA_DIR;
  load_module(stock + "/image-source.so", stock_data + "/image-source");
  load_module(stock + "/obs-filters.so", stock_data + "/obs-filters");
  load_module(PFX_OBS_MODULE, PFX_OBS_DATA_DIR);
}

ObsSession::~ObsSession() {
  obs_shutdown();
  XCloseDisplay(g_display);
}

obs_source_t* ObsSession::image_source(const std::string& png) {
  obs_data_t* settings = obs_data_create();
  obs_data_set_string(settings, "file", png.c_str());
  obs_source_t* source = obs_source_create("image_source", png.c_str(), settings, nullptr);
  obs_data_release(settings);
  REQUIRE(source);
  return source;
}

obs_source_t* ObsSession::color_source(uint32_t width, uint32_t height, uint32_t abgr) {
  obs_data_t* settings = obs_data_create();
  obs_data_set_int(settings, "color", abgr);
  obs_data_set_int(settings, "width", width);
  obs_data_set_int(settings, "height", height);
  obs_source_t* source = obs_source_create("color_source", "colour", settings, nullptr);
  obs_data_release(settings);
  REQUIRE(source);
  return source;
}

obs_source_t* ObsSession::add_filter(obs_source_t* source, const char* type, obs_data_t* settings) {
  static int count = 0;
  const std::string name = std::string(type) + " " + std::to_string(++count);
  obs_source_t* filter = obs_source_create(type, name.c_str(), settings, nullptr);
  INFO(type);
  REQUIRE(filter);
  obs_source_filter_add(source, filter);
  return filter;
}

void ObsSession::wait_for_ticks() {
  // OBS applies a video source's new settings (obs_source_update) at its next tick, on the
  // graphics thread, at the frame rate: two frames later, one whole tick has run since.
  const auto start = std::chrono::steady_clock::now();
  uint64_t seen = obs_get_video_frame_time();
  for (int changes = 0; changes < 2;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const uint64_t now = obs_get_video_frame_time();
    if (now != seen) {
      seen = now;
      ++changes;
    }
    REQUIRE(std::chrono::steady_clock::now() - start < std::chrono::seconds(20));
  }
}

ObsFrame ObsSession::render(obs_source_t* source) {
  wait_for_ticks();
  ObsFrame frame;
  frame.width = obs_source_get_width(source);
  frame.height = obs_source_get_height(source);
  REQUIRE(frame.width > 0);
  REQUIRE(frame.height > 0);
  obs_enter_graphics();
  gs_texrender_t* target = gs_texrender_create(GS_RGBA, GS_ZS_NONE);
  gs_stagesurf_t* stage = gs_stagesurface_create(frame.width, frame.height, GS_RGBA);
  gs_blend_state_push();
  gs_blend_function(GS_BLEND_ONE, GS_BLEND_ZERO);
  bool drawn = gs_texrender_begin(target, frame.width, frame.height);
  if (drawn) {
    vec4 clear;
    vec4_zero(&clear);
    gs_clear(GS_CLEAR_COLOR, &clear, 0.0f, 0);
    gs_ortho(0.0f, static_cast<float>(frame.width), 0.0f, static_cast<float>(frame.height), -100.0f, 100.0f);
    obs_source_video_render(source);
    gs_texrender_end(target);
    gs_stage_texture(stage, gs_texrender_get_texture(target));
    uint8_t* data = nullptr;
    uint32_t line_size = 0;
    drawn = gs_stagesurface_map(stage, &data, &line_size);
    if (drawn) {
      frame.rgba.resize(size_t{frame.width} * frame.height * 4);
      for (uint32_t y = 0; y < frame.height; ++y)
        std::copy(data + size_t{y} * line_size, data + size_t{y} * line_size + size_t{frame.width} * 4,
                  frame.rgba.begin() + size_t{y} * frame.width * 4);
      gs_stagesurface_unmap(stage);
    }
  }
  gs_blend_state_pop();
  gs_stagesurface_destroy(stage);
  gs_texrender_destroy(target);
  obs_leave_graphics();
  REQUIRE(drawn);
  return frame;
}

std::string ObsSession::log() const {
  std::lock_guard<std::mutex> lock(g_log_mutex);
  return g_log;
}

void ObsSession::clear_log() {
  std::lock_guard<std::mutex> lock(g_log_mutex);
  g_log.clear();
}

}  // namespace pfx::test
