// A chain over an 8-bit frame as the hosts of display frames hand it (chain.hpp's FrameTextures):
// the frame of every code, the example plugins loaded, and the frame rendered into an 8-bit
// texture or a framebuffer, with the curves of the sRGB transfer computed here in double
// precision for the expectations.
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "eight_bit_texture.hpp"
#include "gl_test_support.hpp"

namespace pfx::test {

inline double srgb_to_linear(double code) {
  const double v = code / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
inline double linear_to_srgb_code(double linear) {
  const double l = std::clamp(linear, 0.0, 1.0);
  return 255.0 * (l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1 / 2.4) - 0.055);
}

// Every code in each colour channel, across a 64x12 frame (an odd mix per pixel), alpha varied.
constexpr int kWidth = 64, kHeight = 12;
inline std::vector<uint8_t> every_code() {
  std::vector<uint8_t> bytes(size_t(kWidth) * kHeight * 4);
  for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
    bytes[i * 4 + 0] = uint8_t(i % 256);
    bytes[i * 4 + 1] = uint8_t((i * 7 + 3) % 256);
    bytes[i * 4 + 2] = uint8_t((i * 13 + 101) % 256);
    bytes[i * 4 + 3] = uint8_t((i * 5) % 256);
  }
  return bytes;
}

struct EightBitRig {
  std::unique_ptr<pfx::host::PluginRegistry> registry;
  pfx::host::ParamStore params;
  std::unique_ptr<pfx::host::Chain> chain;
  // `extra_plugin`: one more plugin to load beside the examples and the probe.
  explicit EightBitRig(const std::string& extra_plugin = "") {
    pfx::test::gl_context();
    registry = pfx::test::make_registry();
    std::string error;
    INFO(error);
    if (!extra_plugin.empty()) REQUIRE(registry->load(extra_plugin, &error));
    REQUIRE(registry->load(PFX_TEST_MINIMAL_PLUGIN, &error));
    REQUIRE(registry->load(PFX_TEST_FIRST_EFFECT_PLUGIN, &error));
    REQUIRE(registry->load(PFX_TEST_PROBE_PLUGIN, &error));
    chain = std::make_unique<pfx::host::Chain>(*registry, params);
  }
  void add(const std::string& effect, const std::string& assignment) {
    std::string error;
    INFO(error);
    REQUIRE(chain->add(effect, &error));
    if (!assignment.empty()) REQUIRE(params.set_assignment(assignment, &error));
  }
  // The frame through the chain, 8-bit in and out (sRGB views, or plain RGBA8 holding linear values).
  // swap_red_blue: the colour texture is sampled through a swizzle that trades red and blue.
  std::vector<uint8_t> render(const std::vector<uint8_t>& bytes, bool srgb, bool swap_red_blue = false) {
    const auto transfer = srgb ? pfx::app::Transfer::SRGB : pfx::app::Transfer::LINEAR;
    pfx::gl::EightBitTexture in, out;
    in.create(kWidth, kHeight);
    out.create(kWidth, kHeight);
    in.upload_top_first(bytes.data(), kWidth, kHeight);
    if (swap_red_blue) {
      const GLint swizzle[4] = {GL_BLUE, GL_GREEN, GL_RED, GL_ALPHA};
      glTextureParameteriv(in.as(transfer), GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    }
    pfx::host::FrameTextures textures;
    textures.color = in.as(transfer);
    std::string error;
    const bool rendered = chain->render(pfx::test::make_frame(kWidth, kHeight), textures, out.as(transfer), &error);
    std::vector<uint8_t> result(bytes.size());
    out.read_top_first(result.data(), kWidth, kHeight);
    in.release();
    out.release();
    INFO(error);
    REQUIRE(rendered);
    return result;
  }
  // The same, drawn into a framebuffer whose colour is a renderbuffer of `format`, told that it
  // holds sRGB codes or not; false with *error when the chain refuses.
  bool render_into_framebuffer(const std::vector<uint8_t>& bytes, bool srgb, GLenum format,
                               std::vector<uint8_t>* result, std::string* error) {
    const auto transfer = srgb ? pfx::app::Transfer::SRGB : pfx::app::Transfer::LINEAR;
    pfx::gl::EightBitTexture in;
    in.create(kWidth, kHeight);
    in.upload_top_first(bytes.data(), kWidth, kHeight);
    GLuint renderbuffer = 0, framebuffer = 0;
    glCreateRenderbuffers(1, &renderbuffer);
    glNamedRenderbufferStorage(renderbuffer, format, kWidth, kHeight);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferRenderbuffer(framebuffer, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer);
    pfx::host::FrameTextures textures;
    textures.color = in.as(transfer);
    pfx::host::FramebufferOutput output;
    output.framebuffer = framebuffer;
    output.srgb = srgb;
    const bool rendered = chain->render(pfx::test::make_frame(kWidth, kHeight), textures, output, error);
    // Read as the bits are (no conversion with GL_FRAMEBUFFER_SRGB off), bottom row first.
    std::vector<uint8_t> bottom_first(bytes.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, bottom_first.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    result->resize(bytes.size());
    const size_t row = size_t(kWidth) * 4;
    for (int y = 0; y < kHeight; ++y)
      std::copy_n(bottom_first.begin() + long(y * row), row, result->begin() + long((kHeight - 1 - y) * row));
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &renderbuffer);
    in.release();
    return rendered;
  }
  std::vector<uint8_t> render_into_framebuffer(const std::vector<uint8_t>& bytes, bool srgb) {
    std::vector<uint8_t> result;
    std::string error;
    const bool rendered = render_into_framebuffer(bytes, srgb, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, &result, &error);
    INFO(error);
    REQUIRE(rendered);
    return result;
  }
  std::vector<std::string> passes() const {
    std::vector<std::string> names;
    for (const auto& pass : chain->report().passes) names.push_back(pass.effect + ":" + pass.pass);
    return names;
  }
};

}  // namespace pfx::test
