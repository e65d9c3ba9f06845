#include "frame_capture.hpp"

#include "exr_io.hpp"
#include "image_texture.hpp"
#include "png_io.hpp"

namespace pfx::inject {

bool write_texture_exr(GLuint texture, int width, int height, const std::string& path, std::string* error) {
  const app::Image image = app::download_color_texture(texture, width, height);
  return app::write_exr(path, image, app::ExrPixelType::Half, error);
}

bool write_presented_png(const app::DisplayImage& image, const std::string& path, std::string* error) {
  return app::write_png(path, image, error);
}

}  // namespace pfx::inject
