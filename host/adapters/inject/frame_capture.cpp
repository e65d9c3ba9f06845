#include "frame_capture.hpp"

#include "exr_io.hpp"
#include "png_io.hpp"

namespace pfx::inject {

bool write_image_exr(const app::Image& image, const std::string& path, std::string* error) {
  return app::write_exr(path, image, app::ExrPixelType::Half, error);
}

bool write_presented_png(const app::DisplayImage& image, const std::string& path, std::string* error) {
  return app::write_png(path, image, error);
}

}  // namespace pfx::inject
