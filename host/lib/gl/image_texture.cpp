#include "image_texture.hpp"

#include <vector>

#include <glad/gl.h>

namespace pfx::app {
std::vector<float> flip_rows(const std::vector<float>& data, int width, int height, int channels) {
  std::vector<float> flipped(data.size());
  const size_t row = static_cast<size_t>(width) * channels;
  for (int y = 0; y < height; ++y)
    std::copy(data.begin() + static_cast<long>(y * row), data.begin() + static_cast<long>((y + 1) * row),
              flipped.begin() + static_cast<long>((height - 1 - y) * row));
  return flipped;
}

uint32_t create_texture(uint32_t internal_format, int width, int height) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, internal_format, width, height);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return texture;
}

void fill_color_texture(uint32_t texture, const Image& img) {
  std::vector<float> flipped = flip_rows(img.rgba, img.width, img.height, 4);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture, 0, 0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, flipped.data());
}

void fill_depth_texture(uint32_t texture, const Image& img) {
  std::vector<float> flipped = flip_rows(img.depth, img.width, img.height, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture, 0, 0, 0, img.width, img.height, GL_RED, GL_FLOAT, flipped.data());
}

uint32_t upload_color_texture(const Image& img) {
  GLuint texture = create_texture(GL_RGBA16F, img.width, img.height);
  fill_color_texture(texture, img);
  return texture;
}

uint32_t upload_depth_texture(const Image& img) {
  if (!img.has_depth()) return 0;
  GLuint texture = create_texture(GL_R32F, img.width, img.height);
  fill_depth_texture(texture, img);
  return texture;
}

uint32_t create_color_texture(int width, int height) { return create_texture(GL_RGBA16F, width, height); }

Image download_color_texture(uint32_t texture, int width, int height) {
  std::vector<float> data(static_cast<size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(data.size() * sizeof(float)), data.data());
  Image img;
  img.width = width;
  img.height = height;
  img.rgba = flip_rows(data, width, height, 4);
  return img;
}

void delete_texture(uint32_t texture) {
  GLuint name = texture;
  if (name) glDeleteTextures(1, &name);
}

}  // namespace pfx::app
