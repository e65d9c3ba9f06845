// libpfxhost's side of the contract (docs/sdk.md §1.4, §1.5), read from the pixels of the probe
// fixture (tests/fixtures/probe): the same expectations the plain-C host checks in tests/c_host,
// so the runtime and a host written from the document agree.
#include <catch2/catch.hpp>

#include <glad/gl.h>

#include "gl_test_support.hpp"

namespace {

constexpr int kWidth = 7, kHeight = 5;

struct ProbeRig {
  std::unique_ptr<pfx::host::PluginRegistry> registry = pfx::test::make_registry();
  pfx::host::ParamStore params;
  std::unique_ptr<pfx::host::Chain> chain;
  std::vector<float> input, depth;
  GLuint color = 0, depth_texture = 0, output = 0;

  ProbeRig() {
    std::string error;
    REQUIRE(registry->load(PFX_TEST_PROBE_PLUGIN, &error));
    chain = std::make_unique<pfx::host::Chain>(*registry, params);
    for (int i = 0; i < kWidth * kHeight * 4; ++i) input.push_back(float(i % 13) * 0.125f - 0.5f);
    for (int i = 0; i < kWidth * kHeight; ++i) depth.push_back(float(i) / (kWidth * kHeight));
    // Rows bottom first, as GL stores them: no flipping anywhere in this test.
    glCreateTextures(GL_TEXTURE_2D, 1, &color);
    glTextureStorage2D(color, 1, GL_RGBA32F, kWidth, kHeight);
    glTextureSubImage2D(color, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, input.data());
    // An engine's depth buffer set up for shadow lookups: the host's sampler must read depth.
    glCreateTextures(GL_TEXTURE_2D, 1, &depth_texture);
    glTextureStorage2D(depth_texture, 1, GL_DEPTH_COMPONENT32F, kWidth, kHeight);
    glTextureSubImage2D(depth_texture, 0, 0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    glTextureParameteri(depth_texture, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glCreateTextures(GL_TEXTURE_2D, 1, &output);
    glTextureStorage2D(output, 1, GL_RGBA16F, kWidth, kHeight);
  }
  ~ProbeRig() {
    chain.reset();
    glDeleteTextures(1, &color);
    glDeleteTextures(1, &depth_texture);
    glDeleteTextures(1, &output);
  }

  // Runs one probe effect; false with *error when the chain refuses.
  bool run(const std::string& effect, std::string* error) {
    while (chain->size()) chain->remove(0);
    REQUIRE(chain->add(effect, error));
    pfx_frame frame = pfx::test::make_frame(kWidth, kHeight);
    frame.inputs |= PFX_INPUT_DEPTH;
    frame.depth_encoding = PFX_DEPTH_HARDWARE;
    pfx::host::FrameTextures textures;
    textures.color = color;
    textures.depth = depth_texture;
    return chain->render(frame, textures, output, error);
  }
  std::vector<float> result() const {
    std::vector<float> pixels(kWidth * kHeight * 4);
    glGetTextureImage(output, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
    return pixels;
  }
};

// Half-float output: 2^-11 relative, with a margin.
void check_pixels(const std::vector<float>& actual, const std::vector<float>& expected) {
  REQUIRE(actual.size() == expected.size());
  for (size_t i = 0; i < actual.size(); ++i) {
    INFO("pixel (" << (i / 4) % kWidth << ", " << i / 4 / kWidth << ") channel " << i % 4);
    REQUIRE(actual[i] == Approx(expected[i]).epsilon(1.0 / 1024).margin(1e-4));
  }
}

}  // namespace

TEST_CASE("probe: row 0 is the bottom row and a full-screen triangle's uv starts at the bottom-left",
          "[contract]") {
  ProbeRig rig;
  std::string error;
  REQUIRE(rig.run("coords", &error));
  std::vector<float> expected;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      expected.insert(expected.end(), {x + 0.5f, y + 0.5f, (x + 0.5f) / kWidth, (y + 0.5f) / kHeight});
  check_pixels(rig.result(), expected);
}

TEST_CASE("probe: PFX_SIZE_FRAME_SCALE rounds half away from zero, and a pass is told its sizes", "[contract]") {
  ProbeRig rig;
  std::string error;
  REQUIRE(rig.run("sizes", &error));
  std::vector<float> expected;
  for (int i = 0; i < kWidth * kHeight; ++i) expected.insert(expected.end(), {2, 3, kWidth, kHeight});  // 7/3, 5/2
  check_pixels(rig.result(), expected);
}

TEST_CASE("probe: a depth input reads as depth whatever the depth texture's own compare mode", "[contract]") {
  ProbeRig rig;
  std::string error;
  REQUIRE(rig.run("depth", &error));
  std::vector<float> expected;
  for (float d : rig.depth) expected.insert(expected.end(), {d, 0, 0, 1});
  check_pixels(rig.result(), expected);
}

TEST_CASE("probe: a custom pass writes the output as an image and the next passes read it", "[contract]") {
  ProbeRig rig;
  std::string error;
  REQUIRE(rig.run("custom", &error));
  std::vector<float> expected;
  for (float v : rig.input) expected.push_back(2 * v + 1);
  check_pixels(rig.result(), expected);
}

TEST_CASE("probe: a pass may name PFX_MAX_PASS_INPUTS inputs, and one more is refused by name", "[contract]") {
  ProbeRig rig;
  std::string error;
  REQUIRE(rig.run("inputs", &error));  // the default count is PFX_MAX_PASS_INPUTS
  std::vector<float> expected;
  for (float v : rig.input) expected.push_back(float(PFX_MAX_PASS_INPUTS) * v);
  check_pixels(rig.result(), expected);

  REQUIRE(rig.params.set_assignment("inputs.count=" + std::to_string(PFX_MAX_PASS_INPUTS + 1), &error));
  CHECK_FALSE(rig.run("inputs", &error));
  CHECK_THAT(error, Catch::Contains("pass #0 'sum': 17 inputs, more than the 16 a pass may name"));
}

TEST_CASE("probe: GL errors pending before render are not blamed on the first pass", "[contract]") {
  ProbeRig rig;
  glEnable(0xFFFF);  // GL_INVALID_ENUM, left pending by "the engine"
  std::string error;
  CHECK(rig.run("coords", &error));
  CHECK(error.empty());
}
