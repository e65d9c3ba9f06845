#include "copy_pass.hpp"

#include <stdexcept>
#include <string>

#include <glad/gl.h>

namespace pfx::bench {
namespace {

const char* kVertex = R"(#version 450 core
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})";

const char* kFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D source;
out vec4 color;
void main() { color = texelFetch(source, ivec2(gl_FragCoord.xy), 0); })";

GLuint compile(GLenum stage, const char* text) {
  GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("copy pass shader: ") + log);
  }
  return shader;
}

}  // namespace

CopyPass::CopyPass() {
  GLuint vs = compile(GL_VERTEX_SHADER, kVertex), fs = compile(GL_FRAGMENT_SHADER, kFragment);
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
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
