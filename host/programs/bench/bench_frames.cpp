#include "bench_frames.hpp"

#include "demo_image.hpp"
#include "exr_io.hpp"

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

}  // namespace

bool make_bench_frames(const BenchOptions& options, std::vector<BenchFrame>* frames, std::string* error) {
  frames->clear();
  if (options.inputs.empty()) {
    for (const auto& [width, height] : options.sizes)
      frames->push_back({"demo image", pfx::app::make_demo_image(width, height), {}, {}});
    return true;
  }
  for (size_t i = 0; i < options.inputs.size(); ++i) {
    BenchFrame frame;
    frame.source = options.inputs[i];
    pfx::app::ExrRequest request;
    request.layer = options.layer;
    if (!pfx::app::read_exr(options.inputs[i], &frame.image, error, request, nullptr)) return false;
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
