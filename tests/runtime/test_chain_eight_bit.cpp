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

#include "eight_bit_rig.hpp"

namespace {

using pfx::test::EightBitRig;
using pfx::test::every_code;
using pfx::test::kHeight;
using pfx::test::kWidth;
using pfx::test::linear_to_srgb_code;
using pfx::test::srgb_to_linear;

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
  EightBitRig rig;
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
  EightBitRig rig;
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
    EightBitRig rig;  // the promised tint first: the colour goes in as it is; gain's output is converted
    rig.add("tint", "tint.tint=0.5,0.5,0.5");
    rig.add("gain", "gain.gain=1.5");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(rig.passes() == std::vector<std::string>{"tint:tint", "gain:gain", "chain:RGBA16F to 8-bit output"});
    CHECK(worst_codes(in, out, 0.75, true) < 1.5);
  }
  {
    EightBitRig rig;  // gain first: its colour is converted; the promised tint draws the 8-bit output
    rig.add("gain", "gain.gain=1.5");
    rig.add("tint", "tint.tint=0.5,0.5,0.5");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(rig.passes() == std::vector<std::string>{"chain:8-bit colour to RGBA16F", "gain:gain", "tint:tint"});
    CHECK(worst_codes(in, out, 0.75, true) < 1.5);
  }
}

TEST_CASE("with no effect to run, an 8-bit frame is copied to an 8-bit output bit for bit", "[chain][eight_bit]") {
  EightBitRig rig;
  rig.add("tint", "tint.tint=1,1,1");  // white: declares no pass
  const std::vector<uint8_t> in = every_code();
  for (const bool srgb : {true, false}) {
    CHECK(rig.render(in, srgb) == in);
    CHECK(rig.passes().empty());
  }
}

TEST_CASE("with no effect to run, a colour the host swizzled is copied as it samples, not as it is stored",
          "[chain][eight_bit]") {
  EightBitRig rig;
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
  EightBitRig rig;
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
    EightBitRig rig;
    rig.add("gain", "gain.gain=0.5");
    const std::vector<uint8_t> out = rig.render_into_framebuffer(in, true);
    CHECK(rig.passes() ==
          std::vector<std::string>{"chain:8-bit colour to RGBA16F", "gain:gain", "chain:RGBA16F to 8-bit output"});
    CHECK(out == rig.render(in, true));
    CHECK(worst_codes(in, out, 0.5, true) < 1.5);
  }
  {
    EightBitRig rig;  // promised, but a framebuffer cannot be sampled: its output goes through RGBA16F
    rig.add("readback", "");
    const std::vector<uint8_t> out = rig.render_into_framebuffer(in, true);
    CHECK(rig.passes() ==
          std::vector<std::string>{"readback:first", "readback:keep", "readback:last", "chain:RGBA16F to 8-bit output"});
    CHECK(worst_codes(in, out, 0.512, true) < 1.5);
    for (size_t i = 3; i < in.size(); i += 4) REQUIRE(out[i] == in[i]);
  }
}

TEST_CASE("into a framebuffer with no effect to run, the frame is copied bit for bit", "[chain][eight_bit]") {
  EightBitRig rig;
  rig.add("tint", "tint.tint=1,1,1");
  const std::vector<uint8_t> in = every_code();
  for (const bool srgb : {true, false}) {
    CHECK(rig.render_into_framebuffer(in, srgb) == in);
    CHECK(rig.passes().empty());
  }
}

TEST_CASE("a framebuffer said to hold sRGB codes that cannot encode them is refused", "[chain][eight_bit]") {
  EightBitRig rig;
  rig.add("tint", "tint.tint=0.5,0.25,2");
  std::vector<uint8_t> out;
  std::string error;
  CHECK_FALSE(rig.render_into_framebuffer(every_code(), true, GL_RGBA8, &out, &error));
  CHECK(error == "the output framebuffer holds sRGB codes but its draw buffer is not sRGB-capable");
}
