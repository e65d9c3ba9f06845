#include "gl_frame.hpp"

namespace pfx::vk {
namespace {

// The frame's bytes as R, G, B, A: a read-back ignores the swizzle, and GL_BGRA reads a texture
// holding B, G, R, A bytes in that order.
void read_rgba(GLuint texture, int width, int height, bool bgra, uint8_t* out) {
  if (!out) return;
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(texture, 0, bgra ? GL_BGRA : GL_RGBA, GL_UNSIGNED_BYTE, width * height * 4, out);
}

// A chain that failed may have left draws queued that read the go-between: the GL finishes them
// before Vulkan uses that memory again (or frees it), as after a frame that ran.
bool finish_failed() {
  glFinish();
  return false;
}

}  // namespace

bool GlFrame::create(const host::PluginRegistry& registry, const app::ChainRecipe& recipe, std::string* error) {
  if (!frame_.create(error)) return false;
  std::vector<std::string> notes;
  chain_ = adapters::FrameChain::build(registry, recipe, "set", &notes, error);
  return chain_ != nullptr;
}

GlFrame::~GlFrame() {
  chain_.reset();
  shared_.release();
  if (staging_) glDeleteTextures(1, &staging_);
}

GLuint GlFrame::staging(int width, int height, bool ten_bit) {
  if (staging_ && staging_width_ == width && staging_height_ == height && staging_ten_bit_ == ten_bit) return staging_;
  if (staging_) glDeleteTextures(1, &staging_);
  glCreateTextures(GL_TEXTURE_2D, 1, &staging_);
  glTextureStorage2D(staging_, 1, ten_bit ? GL_RGB10_A2 : GL_RGBA8, width, height);
  staging_width_ = width;
  staging_height_ = height;
  staging_ten_bit_ = ten_bit;
  return staging_;
}

bool GlFrame::run(void* host_bytes, int width, int height, Texels texels, app::Transfer transfer, double time_seconds,
                  uint64_t frame_index, const Readback& readback, std::string* error) {
  while (glGetError() != GL_NO_ERROR) {
  }
  const bool bgra = texels.bgra;
  // The packed texels as they lie in memory: bytes R, G, B, A, or R from the lowest bits up.
  const GLenum host_type = texels.ten_bit ? GL_UNSIGNED_INT_2_10_10_10_REV : GL_UNSIGNED_BYTE;
  const GLuint io = host_bytes ? staging(width, height, texels.ten_bit) : shared_.texture();
  if (host_bytes) {
    // Rows of 4-byte texels: any unpack alignment fits; the bridge's context has no unpack buffer.
    glTextureSubImage2D(io, 0, 0, 0, width, height, GL_RGBA, host_type, host_bytes);
  }
  read_rgba(io, width, height, bgra, readback.app_pixels);
  frame_.resize(width, height);
  frame_.decode_texture(io, transfer, bgra);
  GLuint result = 0;
  if (!chain_->render(frame_, time_seconds, frame_index, &result, error)) return finish_failed();
  frame_.encode_texture(result, io, transfer, bgra);
  read_rgba(io, width, height, bgra, readback.result_pixels);
  if (host_bytes) {
    glGetTextureImage(io, 0, GL_RGBA, host_type, width * height * 4, host_bytes);
  }
  glFinish();
  return adapters::no_gl_error(error);
}

bool GlFrame::run_on_layers(int width, int height, app::Transfer transfer, double time_seconds,
                            uint64_t frame_index, const Readback& readback, std::string* error) {
  while (glGetError() != GL_NO_ERROR) {
  }
  const gl::EightBitTexture& in = shared_.layer(0);
  const gl::EightBitTexture& out = shared_.layer(1);
  if (readback.app_pixels) in.read_top_first(readback.app_pixels, width, height);
  if (!chain_->render(in.as(transfer), out.as(transfer), width, height, time_seconds, frame_index, error))
    return finish_failed();
  if (readback.result_pixels) out.read_top_first(readback.result_pixels, width, height);
  glFinish();
  return adapters::no_gl_error(error);
}

}  // namespace pfx::vk
