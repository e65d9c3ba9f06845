#include "frame_capture.hpp"

#include "exr_io.hpp"
#include "image_texture.hpp"
#include "png_io.hpp"

namespace pfx::inject {

std::vector<std::string> capture_prefixes(const std::vector<Capture>& captures, uint64_t frame) {
  std::vector<std::string> prefixes;
  for (const auto& capture : captures) {
    if (capture.every_frame) {
      std::string prefix = capture.prefix;
      prefix.replace(prefix.find("%d"), 2, std::to_string(frame));
      prefixes.push_back(prefix);
    } else if (capture.frame == frame) {
      prefixes.push_back(capture.prefix);
    }
  }
  return prefixes;
}

bool write_texture_exr(GLuint texture, int width, int height, const std::string& path, std::string* error) {
  const app::Image image = app::download_color_texture(texture, width, height);
  return app::write_exr(path, image, app::ExrPixelType::Half, error);
}

bool write_presented_png(const app::DisplayImage& image, const std::string& path, std::string* error) {
  return app::write_png(path, image, error);
}

}  // namespace pfx::inject
