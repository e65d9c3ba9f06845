#include "copy_pass.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include <glad/gl.h>
#include <pfx/cpp/gl_program.hpp>

#include "image_texture.hpp"

namespace pfx::gl {
namespace {

const char* kFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D source;
out vec4 color;
void main() { color = texelFetch(source, ivec2(gl_FragCoord.xy), 0); })";

}  // namespace

CopyPass::CopyPass() {
  std::string error;
  program_ = pfx::gl::build_fullscreen_program(kFragment, &error);
  if (!program_) throw std::runtime_error("copy pass shader: " + error);
  glCreateVertexArrays(1, &vertex_array_);
  glCreateFramebuffers(1, &framebuffer_);
}

CopyPass::~CopyPass() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgram(program_);
}

void CopyPass::run(uint32_t source, uint32_t target, int width, int height) {
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, target, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glUseProgram(program_);
  glBindTextureUnit(0, source);
  glBindVertexArray(vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

double median_copy_pass_ms(int width, int height, int repeats) {
  CopyPass pass;
  const uint32_t source = app::create_color_texture(width, height);
  const uint32_t target = app::create_color_texture(width, height);
  std::vector<double> times;
  for (int i = 0; i < repeats + 3; ++i) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    pass.run(source, target, width, height);
    glFinish();
    if (i >= 3) times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  app::delete_texture(source);
  app::delete_texture(target);
  if (times.empty()) return 0;
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace pfx::gl
