// A display frame handed to the chain as 8-bit textures (chain.hpp's FrameTextures): an effect that
// promised PFX_DECLARATION_SAMPLES_AND_DRAWS (the C++ example's tint) samples and draws them as
// they are, with no pass of the chain's; one that did not (the C example's gain) gets RGBA16F
// through the chain's own conversion on its side. Either way the bytes are what the sRGB curve,
// the effect's arithmetic and the curve back give, computed here in double precision. A host's
// framebuffer as the output (a renderbuffer here, standing in for a window's back buffer, which
// cannot be sampled either) gets what an 8-bit texture gets.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "eight_bit_texture.hpp"
#include "gl_test_support.hpp"

namespace {

double srgb_to_linear(double code) {
  const double v = code / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
double linear_to_srgb_code(double linear) {
  const double l = std::clamp(linear, 0.0, 1.0);
  return 255.0 * (l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1 / 2.4) - 0.055);
}

// Every code in each colour channel, across a 64x12 frame (an odd mix per pixel), alpha varied.
constexpr int kWidth = 64, kHeight = 12;
std::vector<uint8_t> every_code() {
  std::vector<uint8_t> bytes(size_t(kWidth) * kHeight * 4);
  for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
    bytes[i * 4 + 0] = uint8_t(i % 256);
    bytes[i * 4 + 1] = uint8_t((i * 7 + 3) % 256);
    bytes[i * 4 + 2] = uint8_t((i * 13 + 101) % 256);
    bytes[i * 4 + 3] = uint8_t((i * 5) % 256);
  }
  return bytes;
}

struct Rig {
  std::unique_ptr<pfx::host::PluginRegistry> registry;
  pfx::host::ParamStore params;
  std::unique_ptr<pfx::host::Chain> chain;
  Rig() {
    pfx::test::gl_context();
    registry = pfx::test::make_registry();
    std::string error;
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

// The worst distance, in codes, of `got` from each colour channel times its scale (decoded by the
// transfer and encoded back); alpha kept.
double worst_codes(const std::vector<uint8_t>& in, const std::vector<uint8_t>& got, const double (&scale)[3], bool srgb) {
  double worst = 0;
  for (size_t i = 0; i < in.size(); ++i) {
    const size_t c = i % 4;
    double expected = in[i];
    if (c != 3)
      expected = srgb ? linear_to_srgb_code(srgb_to_linear(in[i]) * scale[c])
                      : std::clamp(in[i] * scale[c], 0.0, 255.0);
    worst = std::max(worst, std::abs(got[i] - expected));
  }
  return worst;
}
double worst_codes(const std::vector<uint8_t>& in, const std::vector<uint8_t>& got, double scale, bool srgb) {
  const double scales[3] = {scale, scale, scale};
  return worst_codes(in, got, scales, srgb);
}

}  // namespace

TEST_CASE("an effect that promised to sample and draw runs on an 8-bit frame as it is, with no pass of the chain's",
          "[chain][eight_bit]") {
  Rig rig;
  rig.add("tint", "tint.tint=0.5,0.25,2");
  const std::vector<uint8_t> in = every_code();
  for (const bool srgb : {true, false}) {
    INFO((srgb ? "sRGB" : "linear"));
    const std::vector<uint8_t> out = rig.render(in, srgb);
    CHECK(rig.passes() == std::vector<std::string>{"tint:tint"});
    // Within a code of the exact curves: the GPU's sRGB decode and encode are exact to well within
    // half a code on GPUs, but Mesa's llvmpipe approximates both, so a code may land on its neighbour.
    const double scale[3] = {0.5, 0.25, 2.0};
    CHECK(worst_codes(in, out, scale, srgb) < 1.5);
    for (size_t i = 3; i < in.size(); i += 4) REQUIRE(out[i] == in[i]);
    // Not a copy: the tint changed the frame.
    CHECK(out != in);
  }
  CHECK(rig.chain->report().peak_target_bytes == 0);
}

TEST_CASE("an effect that did not promise gets RGBA16F: the chain converts the 8-bit frame on each side, timed as its own passes",
          "[chain][eight_bit]") {
  Rig rig;
  rig.add("gain", "gain.gain=0.5");
  const std::vector<uint8_t> in = every_code();
  const std::vector<uint8_t> out = rig.render(in, true);
  CHECK(rig.passes() ==
        std::vector<std::string>{"chain:8-bit colour to RGBA16F", "gain:gain", "chain:RGBA16F to 8-bit output"});
  CHECK(worst_codes(in, out, 0.5, true) < 1.5);
  for (size_t i = 3; i < in.size(); i += 4) REQUIRE(out[i] == in[i]);
  // The two RGBA16F copies are the frame's target memory.
  CHECK(rig.chain->report().peak_target_bytes == uint64_t(2) * kWidth * kHeight * 8);
}

TEST_CASE("in a chain of both, only the side whose effect did not promise is converted", "[chain][eight_bit]") {
  const std::vector<uint8_t> in = every_code();
  {
    Rig rig;  // the promised tint first: the colour goes in as it is; gain's output is converted
    rig.add("tint", "tint.tint=0.5,0.5,0.5");
    rig.add("gain", "gain.gain=1.5");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(rig.passes() == std::vector<std::string>{"tint:tint", "gain:gain", "chain:RGBA16F to 8-bit output"});
    CHECK(worst_codes(in, out, 0.75, true) < 1.5);
  }
  {
    Rig rig;  // gain first: its colour is converted; the promised tint draws the 8-bit output
    rig.add("gain", "gain.gain=1.5");
    rig.add("tint", "tint.tint=0.5,0.5,0.5");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(rig.passes() == std::vector<std::string>{"chain:8-bit colour to RGBA16F", "gain:gain", "tint:tint"});
    CHECK(worst_codes(in, out, 0.75, true) < 1.5);
  }
}

TEST_CASE("with no effect to run, an 8-bit frame is copied to an 8-bit output bit for bit", "[chain][eight_bit]") {
  Rig rig;
  rig.add("tint", "tint.tint=1,1,1");  // white: declares no pass
  const std::vector<uint8_t> in = every_code();
  for (const bool srgb : {true, false}) {
    CHECK(rig.render(in, srgb) == in);
    CHECK(rig.passes().empty());
  }
}

TEST_CASE("with no effect to run, a colour the host swizzled is copied as it samples, not as it is stored",
          "[chain][eight_bit]") {
  Rig rig;
  rig.add("tint", "tint.tint=1,1,1");
  const std::vector<uint8_t> in = every_code();
  std::vector<uint8_t> swapped = in;
  for (size_t i = 0; i < in.size(); i += 4) std::swap(swapped[i], swapped[i + 2]);
  // Linear codes move exactly; sRGB ones are decoded and encoded again, within a code on llvmpipe.
  CHECK(rig.render(in, false, true) == swapped);
  const std::vector<uint8_t> out = rig.render(in, true, true);
  CHECK(rig.passes().empty());
  CHECK(worst_codes(swapped, out, 1.0, true) < 1.5);
}

TEST_CASE("a framebuffer as the output gets the bytes an 8-bit texture gets, drawn by the effect itself",
          "[chain][eight_bit]") {
  Rig rig;
  rig.add("tint", "tint.tint=0.5,0.25,2");
  const std::vector<uint8_t> in = every_code();
  for (const bool srgb : {true, false}) {
    INFO((srgb ? "sRGB" : "linear"));
    const std::vector<uint8_t> into_texture = rig.render(in, srgb);
    const std::vector<uint8_t> into_framebuffer = rig.render_into_framebuffer(in, srgb);
    CHECK(rig.passes() == std::vector<std::string>{"tint:tint"});
    CHECK(into_framebuffer == into_texture);
    CHECK(into_framebuffer != in);
  }
  CHECK(rig.chain->report().peak_target_bytes == 0);
}

TEST_CASE("into a framebuffer, an effect that did not promise, or reads its output back, is drawn there by the chain",
          "[chain][eight_bit]") {
  const std::vector<uint8_t> in = every_code();
  {
    Rig rig;
    rig.add("gain", "gain.gain=0.5");
    const std::vector<uint8_t> out = rig.render_into_framebuffer(in, true);
    CHECK(rig.passes() ==
          std::vector<std::string>{"chain:8-bit colour to RGBA16F", "gain:gain", "chain:RGBA16F to 8-bit output"});
    CHECK(out == rig.render(in, true));
    CHECK(worst_codes(in, out, 0.5, true) < 1.5);
  }
  {
    Rig rig;  // promised, but a framebuffer cannot be sampled: its output goes through RGBA16F
    rig.add("readback", "");
    const std::vector<uint8_t> out = rig.render_into_framebuffer(in, true);
    CHECK(rig.passes() ==
          std::vector<std::string>{"readback:first", "readback:keep", "readback:last", "chain:RGBA16F to 8-bit output"});
    CHECK(worst_codes(in, out, 0.512, true) < 1.5);
    for (size_t i = 3; i < in.size(); i += 4) REQUIRE(out[i] == in[i]);
  }
}

TEST_CASE("into a framebuffer with no effect to run, the frame is copied bit for bit", "[chain][eight_bit]") {
  Rig rig;
  rig.add("tint", "tint.tint=1,1,1");
  const std::vector<uint8_t> in = every_code();
  for (const bool srgb : {true, false}) {
    CHECK(rig.render_into_framebuffer(in, srgb) == in);
    CHECK(rig.passes().empty());
  }
}

TEST_CASE("a framebuffer said to hold sRGB codes that cannot encode them is refused", "[chain][eight_bit]") {
  Rig rig;
  rig.add("tint", "tint.tint=0.5,0.25,2");
  std::vector<uint8_t> out;
  std::string error;
  CHECK_FALSE(rig.render_into_framebuffer(every_code(), true, GL_RGBA8, &out, &error));
  CHECK(error == "the output framebuffer holds sRGB codes but its draw buffer is not sRGB-capable");
}
