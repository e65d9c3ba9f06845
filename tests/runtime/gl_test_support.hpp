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

}  // namespace pfx::test
