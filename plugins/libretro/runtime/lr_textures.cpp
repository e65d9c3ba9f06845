#include "lr_textures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "lr_images.hpp"

namespace pfx_libretro {

using pfx::libretro::ChainPlan;
using pfx::libretro::PixelSize;
using pfx::libretro::WrapMode;

GLenum gl_format(const std::string& format) {
  static const std::map<std::string, GLenum> kFormats = {
      {"R8_UNORM", GL_R8},
      {"R8_UINT", GL_R8UI},
      {"R8_SINT", GL_R8I},
      {"R8G8_UNORM", GL_RG8},
      {"R8G8_UINT", GL_RG8UI},
      {"R8G8_SINT", GL_RG8I},
      {"R8G8B8A8_UNORM", GL_RGBA8},
      {"R8G8B8A8_UINT", GL_RGBA8UI},
      {"R8G8B8A8_SINT", GL_RGBA8I},
      {"R8G8B8A8_SRGB", GL_SRGB8_ALPHA8},
      {"A2B10G10R10_UNORM_PACK32", GL_RGB10_A2},
      {"A2B10G10R10_UINT_PACK32", GL_RGB10_A2UI},
      {"R16_UINT", GL_R16UI},
      {"R16_SINT", GL_R16I},
      {"R16_SFLOAT", GL_R16F},
      {"R16G16_UINT", GL_RG16UI},
      {"R16G16_SINT", GL_RG16I},
      {"R16G16_SFLOAT", GL_RG16F},
      {"R16G16B16A16_UINT", GL_RGBA16UI},
      {"R16G16B16A16_SINT", GL_RGBA16I},
      {"R16G16B16A16_SFLOAT", GL_RGBA16F},
      {"R32_UINT", GL_R32UI},
      {"R32_SINT", GL_R32I},
      {"R32_SFLOAT", GL_R32F},
      {"R32G32_UINT", GL_RG32UI},
      {"R32G32_SINT", GL_RG32I},
      {"R32G32_SFLOAT", GL_RG32F},
      {"R32G32B32A32_UINT", GL_RGBA32UI},
      {"R32G32B32A32_SINT", GL_RGBA32I},
      {"R32G32B32A32_SFLOAT", GL_RGBA32F},
  };
  auto found = kFormats.find(format);
  return found == kFormats.end() ? GLenum{GL_RGBA8} : found->second;
}

int full_mip_levels(PixelSize size) {
  return 1 + static_cast<int>(std::floor(std::log2(static_cast<double>(std::max(size.width, size.height)))));
}

std::size_t texture_bytes(const std::string& format, PixelSize size, int levels) {
  // Components times their bits, from the name: R16G16_SFLOAT is 2 x 16 bits.
  std::size_t bits = 0;
  for (std::size_t at = 0; at < format.size() && format[at] != '_'; ++at)
    if (format[at] >= 'A' && format[at] <= 'Z') bits += static_cast<std::size_t>(std::atoi(format.c_str() + at + 1));
  std::size_t bytes = 0;
  for (int level = 0; level < levels; ++level)
    bytes += static_cast<std::size_t>(std::max(1, size.width >> level)) *
             static_cast<std::size_t>(std::max(1, size.height >> level));
  return bytes * (bits / 8);
}

namespace {

// A texture of `levels` mips, every texel zero: history and feedback start black.
GLuint cleared_texture(GLenum format, PixelSize size, int levels, bool integer) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, levels, format, size.width, size.height);
  const unsigned zeros[4] = {0, 0, 0, 0};
  for (int level = 0; level < levels; ++level)
    glClearTexImage(texture, level, integer ? GL_RGBA_INTEGER : GL_RGBA, integer ? GL_UNSIGNED_INT : GL_FLOAT, zeros);
  return texture;
}

GLenum gl_wrap(WrapMode wrap) {
  switch (wrap) {
    case WrapMode::kClampToBorder:
      return GL_CLAMP_TO_BORDER;
    case WrapMode::kClampToEdge:
      return GL_CLAMP_TO_EDGE;
    case WrapMode::kRepeat:
      return GL_REPEAT;
    case WrapMode::kMirroredRepeat:
      return GL_MIRRORED_REPEAT;
  }
  return GL_CLAMP_TO_BORDER;
}

}  // namespace

bool LrTextures::load_lookups(const pfx::libretro::Preset& preset, std::string* error) {
  for (const pfx::libretro::LookupTexture& texture : preset.textures) {
    DecodedImage image;
    if (!decode_image(texture.path, &image, error)) {
      *error = "lookup texture '" + texture.id + "': " + *error;
      return false;
    }
    Lookup lookup;
    lookup.size = {image.width, image.height};
    lookup.mipmap = texture.mipmap;
    lookup.rgba = std::move(image.rgba);
    lookup_bytes_ += texture_bytes("R8G8B8A8_UNORM", lookup.size, texture.mipmap ? full_mip_levels(lookup.size) : 1);
    lookups_.push_back(std::move(lookup));
  }
  return true;
}

void LrTextures::upload_lookups() {
  for (Lookup& lookup : lookups_) {
    if (lookup.texture) continue;
    const int levels = lookup.mipmap ? full_mip_levels(lookup.size) : 1;
    glCreateTextures(GL_TEXTURE_2D, 1, &lookup.texture);
    glTextureStorage2D(lookup.texture, levels, GL_RGBA8, lookup.size.width, lookup.size.height);
    // Rows of RGBA8 meet the contract's alignment of 4; nothing is bound to the unpack buffer.
    glTextureSubImage2D(lookup.texture, 0, 0, 0, lookup.size.width, lookup.size.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        lookup.rgba.data());
    if (levels > 1) glGenerateTextureMipmap(lookup.texture);
    lookup.rgba = {};
  }
}

void LrTextures::make(const ChainPlan& plan, PixelSize content, const std::vector<PixelSize>& sizes) {
  release_frame_textures();
  original_levels_ = plan.original_mipmapped ? full_mip_levels(content) : 1;
  history_.resize(static_cast<std::size_t>(plan.history) + 1);
  for (GLuint& texture : history_) texture = cleared_texture(GL_RGBA8, content, original_levels_, false);
  frame_bytes_ = history_.size() * texture_bytes("R8G8B8A8_UNORM", content, original_levels_);
  current_ = 0;
  passes_.assign(plan.passes.size(), PassTextures{});
  for (std::size_t i = 0; i < plan.passes.size(); ++i) {
    const pfx::libretro::PassPlan& pass = plan.passes[i];
    if (pass.to_output) continue;
    PassTextures& t = passes_[i];
    t.levels = pass.mipmapped ? full_mip_levels(sizes[i]) : 1;
    const bool integer = pfx::libretro::is_integer_format(pass.format);
    for (int k = 0; k < (pass.feedback ? 2 : 1); ++k) {
      t.texture[k] = cleared_texture(gl_format(pass.format), sizes[i], t.levels, integer);
      frame_bytes_ += texture_bytes(pass.format, sizes[i], t.levels);
    }
  }
  parity_ = 0;
  made_ = true;
}

void LrTextures::advance() {
  current_ = (current_ + 1) % history_.size();
  parity_ ^= 1;
}

GLuint LrTextures::original(int frames_back) const {
  const std::size_t n = history_.size();
  return history_[(current_ + n - static_cast<std::size_t>(frames_back) % n) % n];
}

GLuint LrTextures::pass_output(int pass) const {
  const PassTextures& t = passes_[static_cast<std::size_t>(pass)];
  return t.texture[1] ? t.texture[parity_] : t.texture[0];
}

GLuint LrTextures::pass_feedback(int pass) const {
  const PassTextures& t = passes_[static_cast<std::size_t>(pass)];
  return t.texture[1] ? t.texture[parity_ ^ 1] : t.texture[0];
}

GLuint LrTextures::sampler(bool linear, WrapMode wrap, bool mipmaps) {
  const auto key = std::make_tuple(linear, static_cast<int>(wrap), mipmaps);
  auto found = samplers_.find(key);
  if (found != samplers_.end()) return found->second;
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  const GLenum min = mipmaps ? (linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST)
                             : (linear ? GL_LINEAR : GL_NEAREST);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, static_cast<GLint>(gl_wrap(wrap)));
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, static_cast<GLint>(gl_wrap(wrap)));
  const float transparent_black[4] = {0, 0, 0, 0};
  glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, transparent_black);
  samplers_.emplace(key, sampler);
  return sampler;
}

void LrTextures::release_frame_textures() {
  if (!history_.empty()) glDeleteTextures(static_cast<GLsizei>(history_.size()), history_.data());
  history_.clear();
  for (PassTextures& t : passes_) glDeleteTextures(2, t.texture);
  passes_.clear();
  made_ = false;
}

void LrTextures::release() {
  release_frame_textures();
  for (Lookup& lookup : lookups_)
    if (lookup.texture) glDeleteTextures(1, &lookup.texture);
  lookups_.clear();
  for (auto& [key, sampler] : samplers_) glDeleteSamplers(1, &sampler);
  samplers_.clear();
}

}  // namespace pfx_libretro
