// What the GL runtime tests share: one headless context per test process (created on first use),
// a registry loading through it, and images in and out of textures.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pfx/host/chain.hpp>

#include "headless_context.hpp"
#include "image.hpp"

namespace pfx::test {

// Fails the calling test (via REQUIRE in the .cpp) when no GL 4.5 context can be had.
pfx::app::HeadlessContext& gl_context();

struct CollectedLog {
  std::vector<std::string> lines;  // "level source: message"
};

std::unique_ptr<pfx::host::PluginRegistry> make_registry(CollectedLog* log = nullptr);

pfx_frame make_frame(int width, int height);

// A deterministic image with values across [-1, 8] so scaling and clamping show.
pfx::app::Image test_image(int width, int height);

// What a chain test starts from: a registry holding one plugin, a parameter store and a chain.
struct ChainRig {
  std::unique_ptr<pfx::host::PluginRegistry> registry = make_registry();
  pfx::host::ParamStore params;
  std::unique_ptr<pfx::host::Chain> chain;
  explicit ChainRig(const char* plugin_path);  // fails the test if the plugin does not load
  void add(const std::string& effect);          // fails the test on an error
  void set(const std::string& assignment);      // fails the test on an error
  // img through the chain, the output read back (row 0 = top); fails the test if it does not render.
  pfx::app::Image render(const pfx::app::Image& img);
};

}  // namespace pfx::test
