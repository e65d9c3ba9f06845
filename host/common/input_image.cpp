#include "input_image.hpp"

#include "exr_io.hpp"

namespace pfx::app {

bool read_input_image(const std::string& input, const std::string& depth_path, Image* image, std::string* error,
                      const ExrLimits& limits) {
  if (!read_exr(input, image, error, limits)) return false;
  if (depth_path.empty()) return true;
  Image depth;
  if (!read_exr(depth_path, &depth, error, limits)) return false;
  if (depth.width != image->width || depth.height != image->height) {
    *error = depth_path + ": depth is " + std::to_string(depth.width) + "x" + std::to_string(depth.height) +
             " but the image is " + std::to_string(image->width) + "x" + std::to_string(image->height);
    return false;
  }
  if (depth.has_depth()) {
    image->depth = depth.depth;
  } else {
    image->depth.resize(image->pixel_count());
    for (size_t i = 0; i < image->depth.size(); ++i) image->depth[i] = depth.rgba[i * 4];
  }
  return true;
}

}  // namespace pfx::app
