#include "input_image.hpp"

namespace pfx::app {

bool read_input_image(const InputFiles& files, Image* image, InputReport* report, std::string* error) {
  ExrRequest color;
  color.layer = files.layer;
  color.limits = files.limits;
  InputReport read;
  Image result;
  if (!read_exr(files.input, &result, error, color, &read.color)) return false;
  if (!files.depth.empty()) {
    ExrRequest depth_request;
    depth_request.role = ExrRequest::Role::Depth;
    depth_request.limits = files.limits;
    Image depth;
    if (!read_exr(files.depth, &depth, error, depth_request, &read.depth)) return false;
    if (depth.width != result.width || depth.height != result.height) {
      *error = files.depth + ": depth is " + std::to_string(depth.width) + "x" + std::to_string(depth.height) +
               " but the image is " + std::to_string(result.width) + "x" + std::to_string(result.height);
      return false;
    }
    result.depth = std::move(depth.depth);
  }
  *image = std::move(result);
  if (report) *report = std::move(read);
  return true;
}

}  // namespace pfx::app
