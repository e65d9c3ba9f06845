#include "display_pass.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glad/gl.h>
#include <pfx/cpp/gl_program.hpp>

namespace pfx::app {
namespace {

// The same steps as tonemap_pixel(), per channel in the same order. Curve numbers follow
// ToneCurve's order: 0 linear, 1 reinhard, 2 aces.
const char* const kDisplayShader = R"(#version 450 core
layout(binding = 0) uniform sampler2D u_image;
layout(location = 0) uniform float u_scale;    // 2^exposure
layout(location = 1) uniform int u_curve;
layout(location = 2) uniform vec4 u_viewport;  // x, y, width, height in window pixels
layout(location = 3) uniform bool u_codes;     // the texture holds display codes: shown as they are
layout(location = 0) out vec4 o_color;

float curve(float x) {
  if (!(x > 0.0)) return 0.0;
  if (isinf(x)) return 1.0;
  x = min(x, 1.0e9);
  float y = x;
  if (u_curve == 1) y = x / (1.0 + x);
  if (u_curve == 2) y = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
  return clamp(y, 0.0, 1.0);
}

float srgb(float x) {
  return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

void main() {
  vec2 uv = (gl_FragCoord.xy - u_viewport.xy) / u_viewport.zw;
  vec3 c = texture(u_image, uv).rgb;
  if (u_codes) {
    o_color = vec4(c, 1.0);
    return;
  }
  if (any(isnan(c))) {
    o_color = vec4(1.0, 0.0, 1.0, 1.0);
    return;
  }
  vec3 display;
  for (int i = 0; i < 3; ++i) {
    bool fixed_point = c[i] == 0.0 || isinf(c[i]);
    display[i] = srgb(curve(fixed_point ? c[i] : c[i] * u_scale));
  }
  o_color = vec4(display, 1.0);
}
)";

}  // namespace

Viewport fit_viewport(int frame_width, int frame_height, int window_width, int window_height) {
  Viewport v;
  if (frame_width < 1 || frame_height < 1 || window_width < 1 || window_height < 1) return v;
  const double scale = std::min(double(window_width) / frame_width, double(window_height) / frame_height);
  v.width = std::max(1, int(std::lround(frame_width * scale)));
  v.height = std::max(1, int(std::lround(frame_height * scale)));
  v.x = (window_width - v.width) / 2;
  v.y = (window_height - v.height) / 2;
  return v;
}

DisplayPass::DisplayPass() {
  std::string error;
  program_ = pfx::gl::build_fullscreen_program(kDisplayShader, &error);
  glCreateVertexArrays(1, &vertex_array_);
  glCreateSamplers(1, &sampler_);
  // Nearest, not linear: a bilinear tap weighs neighbours by zero, and 0 x inf = NaN, so an
  // infinite or NaN pixel would spread over its neighbours on screen. Each screen pixel shows one
  // frame pixel as it is.
  glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

DisplayPass::~DisplayPass() {
  glDeleteProgram(program_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteSamplers(1, &sampler_);
}

void DisplayPass::draw(uint32_t texture, const Viewport& viewport, int window_width, int window_height,
                       const ToneMapSettings& tone) const {
  draw_texture(texture, viewport, window_width, window_height, tone, false);
}

void DisplayPass::draw_codes(uint32_t texture, const Viewport& viewport, int window_width, int window_height) const {
  draw_texture(texture, viewport, window_width, window_height, ToneMapSettings{}, true);
}

void DisplayPass::draw_texture(uint32_t texture, const Viewport& viewport, int window_width, int window_height,
                               const ToneMapSettings& tone, bool codes) const {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, window_width, window_height);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (!program_ || !texture) return;
  glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
  glProgramUniform1f(program_, 0, static_cast<float>(std::exp2(tone.exposure_ev)));
  glProgramUniform1i(program_, 1, static_cast<int>(tone.curve));
  glProgramUniform4f(program_, 2, float(viewport.x), float(viewport.y), float(viewport.width), float(viewport.height));
  glProgramUniform1i(program_, 3, codes ? 1 : 0);
  glUseProgram(program_);
  glBindTextureUnit(0, texture);
  glBindSampler(0, sampler_);
  glBindVertexArray(vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(0, 0);
  glBindVertexArray(0);
  glUseProgram(0);
  glViewport(0, 0, window_width, window_height);
}

}  // namespace pfx::app
