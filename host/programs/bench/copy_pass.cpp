#include "copy_pass.hpp"

#include <stdexcept>
#include <string>

#include <glad/gl.h>
#include <pfx/cpp/gl_program.hpp>

namespace pfx::bench {
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

}  // namespace pfx::bench
