#include "bench_frames.hpp"

#include <algorithm>
#include <cctype>

#include "demo_image.hpp"
#include "display_transfer.hpp"
#include "exr_io.hpp"
#include "png_io.hpp"

namespace pfx::bench {
namespace {

bool read_same_size(const std::string& path, const pfx::app::Image& input, pfx::app::Image* out, std::string* error) {
  if (!pfx::app::read_exr(path, out, error)) return false;
  if (out->width != input.width || out->height != input.height) {
    *error = path + ": " + std::to_string(out->width) + "x" + std::to_string(out->height) + ", but its input is " +
             std::to_string(input.width) + "x" + std::to_string(input.height);
    return false;
  }
  return true;
}

bool ends_with_png(const std::string& path) {
  std::string end = path.size() >= 4 ? path.substr(path.size() - 4) : path;
  std::transform(end.begin(), end.end(), end.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return end == ".png";
}

// The PNG as RGBA codes (an RGB file opaque), and those codes in linear light.
bool read_display_frame(const std::string& path, BenchFrame* frame, std::string* error) {
  pfx::app::DisplayImage image;
  if (!pfx::app::read_png(path, &image, error)) return false;
  if (image.channels == 3) {
    std::vector<uint8_t> rgba(image.pixels.size() / 3 * 4, 255);
    for (size_t i = 0; i < image.pixels.size() / 3; ++i) std::copy_n(&image.pixels[i * 3], 3, &rgba[i * 4]);
    image.pixels = std::move(rgba);
    image.channels = 4;
  }
  frame->image = pfx::app::decode_display_image(image, pfx::app::Transfer::SRGB);
  frame->display = std::move(image);
  return true;
}

}  // namespace

bool make_bench_frames(const BenchOptions& options, std::vector<BenchFrame>* frames, std::string* error) {
  frames->clear();
  if (options.inputs.empty()) {
    for (const auto& [width, height] : options.sizes)
      frames->push_back({"demo image", pfx::app::make_demo_image(width, height), {}, {}, {}});
    return true;
  }
  for (size_t i = 0; i < options.inputs.size(); ++i) {
    BenchFrame frame;
    frame.source = options.inputs[i];
    if (ends_with_png(options.inputs[i])) {
      if (!read_display_frame(options.inputs[i], &frame, error)) return false;
      frame.source += " (8-bit, as hosts hand it over)";
    } else {
      pfx::app::ExrRequest request;
      request.layer = options.layer;
      if (!pfx::app::read_exr(options.inputs[i], &frame.image, error, request, nullptr)) return false;
    }
    if (i < options.truths.size()) {
      pfx::app::Image truth;
      if (!read_same_size(options.truths[i], frame.image, &truth, error)) return false;
      frame.truth = std::move(truth.rgba);
    }
    if (i < options.halo_masks.size()) {
      pfx::app::Image mask;
      if (!read_same_size(options.halo_masks[i], frame.image, &mask, error)) return false;
      for (size_t p = 0; p < mask.pixel_count(); ++p) frame.halo_mask.push_back(mask.rgba[p * 4] > 0.5f);
    }
    frames->push_back(std::move(frame));
  }
  return true;
}

}  // namespace pfx::bench
