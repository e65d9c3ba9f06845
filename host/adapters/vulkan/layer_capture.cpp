#include "layer_capture.hpp"

#include "image.hpp"
#include "inject_settings.hpp"
#include "layer_calls.hpp"
#include "png_io.hpp"

namespace pfx::vulkan_layer {
namespace {

app::DisplayImage rgb_of(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba) {
  app::DisplayImage image;
  image.width = int(width);
  image.height = int(height);
  image.channels = 3;  // a swapchain's alpha is not part of what is seen
  image.pixels.resize(size_t(width) * height * 3);
  for (size_t i = 0; i < size_t(width) * height; ++i)
    for (size_t c = 0; c < 3; ++c) image.pixels[i * 3 + c] = rgba[i * 4 + c];
  return image;
}

}  // namespace

std::vector<std::string> capture_prefixes_for(uint64_t frame) {
  return inject::capture_prefixes(layer_inject_settings().captures, frame);
}

std::string swapchain_suffix(uint32_t swapchain_index) {
  return swapchain_index > 0 ? "-" + std::to_string(swapchain_index + 1) : "";
}

void say_captures_skipped(uint64_t frame, uint32_t swapchain_index, const std::string& why) {
  for (const auto& skipped : inject::skipped_captures(layer_inject_settings().captures, frame, why,
                                                      swapchain_suffix(swapchain_index))) {
    if (skipped.once_key.empty()) log_line(skipped.line);
    else log_once(skipped.once_key, skipped.line);
  }
}

void write_capture(const std::string& prefix, uint32_t width, uint32_t height, const std::vector<uint8_t>& app,
                   const std::vector<uint8_t>& result) {
  std::string error;
  if (!app::write_png(prefix + ".app.png", rgb_of(width, height, app), &error))
    log_line("capture not written: " + error);
  if (!app::write_png(prefix + ".png", rgb_of(width, height, result), &error))
    log_line("capture not written: " + error);
}

uint64_t quit_after() { return layer_inject_settings().quit_after; }

}  // namespace pfx::vulkan_layer
