#include "depth_probe.hpp"

#include <algorithm>

#include <pfx/cpp/gl_program.hpp>

namespace pfx::inject {
namespace {

constexpr int kMaxGrid = 64;

// Texel (i + 0.5) * size / grid of each grid cell: evenly spread, edges included in the limit.
const char* kSampleShader = R"(#version 450 core
layout(binding = 0) uniform sampler2D depth;
layout(location = 0) uniform ivec2 source_size;
layout(location = 1) uniform ivec2 grid_size;
layout(location = 0) out float value;
void main() {
  ivec2 cell = ivec2(gl_FragCoord.xy);
  ivec2 texel = ivec2((vec2(cell) + 0.5) * vec2(source_size) / vec2(grid_size));
  value = texelFetch(depth, min(texel, source_size - 1), 0).r;
}
)";

}  // namespace

bool DepthProbe::create(std::string* error) {
  std::string message;
  program_ = pfx::gl::build_fullscreen_program(kSampleShader, &message);
  if (!program_) {
    *error = "the depth probe program did not build: " + message;
    return false;
  }
  glCreateVertexArrays(1, &vertex_array_);
  glCreateFramebuffers(1, &framebuffer_);
  glCreateBuffers(1, &buffer_);
  glNamedBufferStorage(buffer_, kMaxGrid * kMaxGrid * sizeof(float), nullptr, 0);
  return true;
}

DepthProbe::~DepthProbe() {
  if (fence_) glDeleteSync(fence_);
  glDeleteBuffers(1, &buffer_);
  glDeleteTextures(1, &target_);
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgram(program_);
}

void DepthProbe::resize(int columns, int rows) {
  if (columns == columns_ && rows == rows_) return;
  glDeleteTextures(1, &target_);
  glCreateTextures(GL_TEXTURE_2D, 1, &target_);
  glTextureStorage2D(target_, 1, GL_R32F, columns, rows);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, target_, 0);
  columns_ = columns;
  rows_ = rows;
}

void DepthProbe::start(GLuint depth, int width, int height) {
  resize(std::min(width, kMaxGrid), std::min(height, kMaxGrid));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, columns_, rows_);
  glUseProgram(program_);
  glProgramUniform2i(program_, 0, width, height);
  glProgramUniform2i(program_, 1, columns_, rows_);
  glBindVertexArray(vertex_array_);
  glBindTextureUnit(0, depth);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Into the buffer, not client memory: the copy is queued and the present goes on.
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_);
  glGetTextureImage(target_, 0, GL_RED, GL_FLOAT, columns_ * rows_ * static_cast<GLsizei>(sizeof(float)), nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  if (fence_) glDeleteSync(fence_);
  fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

bool DepthProbe::finish(bool wait, std::vector<float>* samples) {
  if (!fence_) return false;
  const GLenum state =
      glClientWaitSync(fence_, wait ? GL_SYNC_FLUSH_COMMANDS_BIT : 0, wait ? GLuint64(5'000'000'000) : 0);
  if (state != GL_ALREADY_SIGNALED && state != GL_CONDITION_SATISFIED) return false;
  glDeleteSync(fence_);
  fence_ = nullptr;
  samples->resize(static_cast<size_t>(columns_) * rows_);
  glGetNamedBufferSubData(buffer_, 0, static_cast<GLsizeiptr>(samples->size() * sizeof(float)), samples->data());
  return true;
}

}  // namespace pfx::inject
