#include "frame_files.hpp"

#include <cstdio>
#include <filesystem>
#include <vector>

#include <glad/gl.h>

#include "cli_text.hpp"
#include "exr_io.hpp"
#include "png_io.hpp"

namespace fs = std::filesystem;

namespace pfx::app {

std::string exr_beside(const std::string& png_path) {
  return (ends_with(png_path, ".png") ? png_path.substr(0, png_path.size() - 4) : png_path) + ".exr";
}

bool write_frame_pair(const Image& frame, const std::string& png_path, const ToneMapSettings& tone, std::string* error) {
  return write_png(png_path, tonemap_to_srgb8(frame, tone), error) &&
         write_exr(exr_beside(png_path), frame, ExrPixelType::Half, error);
}

std::string next_screenshot_base(const std::string& directory) {
  std::error_code ec;
  for (int n = 1;; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "pfx-view-%04d", n);
    const std::string base = (fs::path(directory) / name).string();
    if (!fs::exists(base + ".png", ec) && !fs::exists(base + ".exr", ec) && !fs::exists(base + ".json", ec)) return base;
  }
}

bool write_window_png(int width, int height, const std::string& path, std::string* error) {
  DisplayImage image;
  image.width = width;
  image.height = height;
  image.channels = 3;
  image.pixels.resize(size_t(width) * height * 3);
  std::vector<uint8_t> rows(image.pixels.size());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  // GL's first row is the bottom one; PNG's is the top.
  const size_t stride = size_t(width) * 3;
  for (int y = 0; y < height; ++y)
    std::copy(rows.begin() + long(y * stride), rows.begin() + long((y + 1) * stride),
              image.pixels.begin() + long((height - 1 - y) * stride));
  return write_png(path, image, error);
}

}  // namespace pfx::app
