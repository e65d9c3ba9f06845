// The GL state contract from the engine's side (docs/sdk.md §1.5 and "GL state after render"):
// an engine that leaves any item of the contract dirty gets, from the minimal fixture and from
// every shipped post effect, the picture a clean context gets, bit for bit; and after render()
// it reads back every item exactly as it set it.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>

#include <glad/gl.h>

#include <pfx/host/gl_state_guard.hpp>

#include "dirty_gl_state.hpp"
#include "gl_test_support.hpp"
#include "image_texture.hpp"

using pfx::app::Image;

namespace {

struct Subject {
  const char* label;
  std::string plugin;
  std::vector<std::string> effects;
  std::vector<std::string> settings;
};

std::vector<Subject> subjects() {
  const std::string shipped = PFX_PLUGIN_OUTPUT_DIR;
  return {{"minimal: gain and boxblur", PFX_TEST_MINIMAL_PLUGIN, {"gain", "boxblur"}, {"gain.gain=2.5", "boxblur.radius=1.5"}},
          {"bloom", shipped + "/pfx_bloom.so", {"bloom"}, {}},
          {"dof", shipped + "/pfx_dof.so", {"dof"}, {}},
          {"tiledlights", shipped + "/pfx_tiledlights.so", {"tiledlights"}, {}}};
}

// In front of the camera (which looks down -Z), so the lighting effect lights something.
const pfx_light kLights[] = {
    {{0.0f, 1.0f, -4.0f}, 10.0f, {1.0f, 0.9f, 0.8f}, 6.0f},
    {{-1.0f, -0.5f, -8.0f}, 0.0f, {0.2f, 0.4f, 1.0f}, 20.0f},
};

Image constant_image(int width, int height, float r, float g, float b) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(img.pixel_count() * 4);
  for (size_t i = 0; i < img.pixel_count(); ++i) {
    img.rgba[i * 4 + 0] = r;
    img.rgba[i * 4 + 1] = g;
    img.rgba[i * 4 + 2] = b;
    img.rgba[i * 4 + 3] = 1.0f;
  }
  return img;
}

// One subject's chain over a frame with every input, made and first rendered in a clean state.
class ContractRig {
 public:
  static constexpr int kWidth = 40, kHeight = 24;

  explicit ContractRig(const Subject& subject) : registry_(pfx::test::make_registry()) {
    std::string error;
    INFO(subject.plugin << ": " << error);
    REQUIRE(registry_->load(subject.plugin, &error));
    chain_ = std::make_unique<pfx::host::Chain>(*registry_, params_);
    for (const auto& effect : subject.effects) REQUIRE(chain_->add(effect, &error));
    for (const auto& setting : subject.settings) REQUIRE(params_.set_assignment(setting, &error));

    Image color = pfx::test::test_image(kWidth, kHeight);
    color.depth.resize(color.pixel_count());
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) color.depth[size_t(y) * kWidth + x] = 0.5f + 0.4f * float(x) + 2.0f * float(y % 5);
    textures_.color = pfx::app::upload_color_texture(color);
    textures_.depth = pfx::app::upload_depth_texture(color);
    textures_.normal = pfx::app::upload_color_texture(constant_image(kWidth, kHeight, 0.0f, 0.0f, 1.0f));
    textures_.albedo = pfx::app::upload_color_texture(constant_image(kWidth, kHeight, 0.5f, 0.5f, 0.5f));
    textures_.emissive = pfx::app::upload_color_texture(constant_image(kWidth, kHeight, 0.0f, 0.0f, 0.0f));
    output_ = pfx::app::create_color_texture(kWidth, kHeight);
    frame_ = pfx::test::make_frame(kWidth, kHeight);
    frame_.inputs = PFX_INPUT_COLOR | PFX_INPUT_DEPTH | PFX_INPUT_NORMAL | PFX_INPUT_ALBEDO | PFX_INPUT_EMISSIVE |
                    PFX_INPUT_LIGHTS;
    frame_.depth_encoding = PFX_DEPTH_LINEAR;
    frame_.lights = kLights;
    frame_.light_count = 2;
  }
  ~ContractRig() {
    for (uint32_t texture : {textures_.color, textures_.depth, textures_.normal, textures_.albedo, textures_.emissive, output_})
      pfx::app::delete_texture(texture);
  }

  // Fills the output with NaN, so that a pass that draws nothing cannot pass for one that drew
  // the last frame's picture again. Call it in a clean state.
  void poison_output() const {
    const uint16_t half_nan[4] = {0x7e00, 0x7e00, 0x7e00, 0x7e00};
    glClearTexImage(output_, 0, GL_RGBA, GL_HALF_FLOAT, half_nan);
  }
  // Renders under whatever state is current; *gl_error is what glGetError says right after.
  bool render(GLenum* gl_error) {
    frame_.frame_index++;
    std::string error;
    const bool ok = chain_->render(frame_, textures_, output_, &error);
    *gl_error = glGetError();
    UNSCOPED_INFO("render: " << error);
    return ok;
  }
  // Read back with a clean pixel store (the caller has cleaned up).
  Image output() const { return pfx::app::download_color_texture(output_, kWidth, kHeight); }
  const pfx::host::FrameReport& report() const { return chain_->report(); }
  const pfx::host::Chain& chain() const { return *chain_; }

 private:
  std::unique_ptr<pfx::host::PluginRegistry> registry_;
  pfx::host::ParamStore params_;
  std::unique_ptr<pfx::host::Chain> chain_;
  pfx::host::FrameTextures textures_;
  uint32_t output_ = 0;
  pfx_frame frame_{};
};

// "" when the two are the same bits, else where they first differ.
std::string first_difference(const Image& expected, const Image& actual) {
  for (size_t i = 0; i < expected.rgba.size(); ++i)
    if (std::memcmp(&expected.rgba[i], &actual.rgba[i], sizeof(float)) != 0) {
      const size_t pixel = i / 4;
      return "pixel (" + std::to_string(pixel % ContractRig::kWidth) + ", " + std::to_string(pixel / ContractRig::kWidth) +
             ") channel " + std::to_string(i % 4) + ": " + std::to_string(actual.rgba[i]) + " instead of " +
             std::to_string(expected.rgba[i]);
    }
  return "";
}

Image clean_reference(ContractRig& rig) {
  GLenum gl_error = GL_NO_ERROR;
  rig.poison_output();
  REQUIRE(rig.render(&gl_error));
  REQUIRE(gl_error == GL_NO_ERROR);
  REQUIRE_FALSE(rig.report().passes.empty());  // the subject really runs passes with these settings
  Image reference = rig.output();
  // The subject is deterministic: a second clean frame is the same bits.
  rig.poison_output();
  REQUIRE(rig.render(&gl_error));
  REQUIRE(first_difference(reference, rig.output()) == "");
  return reference;
}

}  // namespace

TEST_CASE("an engine's leftover GL state, item by item, changes no pixel and survives render()", "[contract][gl-state]") {
  pfx::test::gl_context();
  const pfx::app::DirtyGlState dirty;
  for (const Subject& subject : subjects()) {
    INFO(subject.label);
    ContractRig rig(subject);
    const Image reference = clean_reference(rig);
    for (const pfx::app::DirtyGlItem& item : dirty.items()) {
      INFO("engine state: " << item.name);
      rig.poison_output();
      const std::vector<double> clean_value = item.read();
      item.make_dirty();
      const std::vector<double> engine_value = item.read();
      // An item the driver ignored would leave the state as it was and test nothing below.
      CHECK(engine_value != clean_value);
      const std::vector<std::vector<double>> everything = dirty.read_all();
      GLenum gl_error = GL_NO_ERROR;
      const bool ok = rig.render(&gl_error);
      const std::vector<double> after = item.read();
      const std::vector<std::vector<double>> everything_after = dirty.read_all();
      item.make_clean();
      CHECK(ok);
      CHECK(gl_error == GL_NO_ERROR);
      CHECK(after == engine_value);
      CHECK(everything_after == everything);
      CHECK(first_difference(reference, rig.output()) == "");
    }
  }
}

TEST_CASE("an engine's leftover GL state, every item at once, changes no pixel and survives render()", "[contract][gl-state]") {
  pfx::test::gl_context();
  const pfx::app::DirtyGlState dirty;
  for (const Subject& subject : subjects()) {
    INFO(subject.label);
    ContractRig rig(subject);
    const Image reference = clean_reference(rig);
    for (int frame = 0; frame < 2; ++frame) {  // the second with the plan and pool already made
      rig.poison_output();
      const std::vector<std::vector<double>> clean_values = dirty.read_all();
      dirty.make_all_dirty();
      const std::vector<std::vector<double>> engine_values = dirty.read_all();
      for (size_t i = 0; i < engine_values.size(); ++i) {
        INFO("engine state: " << dirty.items()[i].name);
        CHECK(engine_values[i] != clean_values[i]);  // really dirtied, or the checks below test nothing
      }
      GLenum gl_error = GL_NO_ERROR;
      const bool ok = rig.render(&gl_error);
      const std::vector<std::vector<double>> after = dirty.read_all();
      dirty.make_all_clean();
      CHECK(ok);
      CHECK(gl_error == GL_NO_ERROR);
      for (size_t i = 0; i < after.size(); ++i) {
        INFO("engine state: " << dirty.items()[i].name);
        CHECK(after[i] == engine_values[i]);
      }
      CHECK(first_difference(reference, rig.output()) == "");
    }
  }
}

TEST_CASE("a clean engine's state reads back unchanged after render()", "[contract][gl-state]") {
  pfx::test::gl_context();
  const pfx::app::DirtyGlState dirty;
  for (const Subject& subject : subjects()) {
    INFO(subject.label);
    ContractRig rig(subject);
    const std::vector<std::vector<double>> before = dirty.read_all();
    GLenum gl_error = GL_NO_ERROR;
    REQUIRE(rig.render(&gl_error));
    const std::vector<std::vector<double>> after = dirty.read_all();
    for (size_t i = 0; i < after.size(); ++i) {
      INFO("state: " << dirty.items()[i].name);
      CHECK(after[i] == before[i]);
    }
  }
}

TEST_CASE("inside a GlStateGuard the state is saved once: the picture is the clean one and the guard puts "
          "every item back", "[contract][gl-state]") {
  pfx::test::gl_context();
  const pfx::app::DirtyGlState dirty;
  for (const Subject& subject : subjects()) {
    INFO(subject.label);
    ContractRig rig(subject);
    const Image reference = clean_reference(rig);
    rig.poison_output();
    dirty.make_all_dirty();
    const std::vector<std::vector<double>> engine_values = dirty.read_all();
    GLenum gl_error = GL_NO_ERROR;
    bool ok = false;
    {
      pfx::host::GlStateGuard guard(rig.chain());
      // A host's own pass between the guard and render() may leave state the chain's passes do
      // not set one by one (pfx-inject's copy in binds its framebuffer and program): render()
      // sets the chain's starting values again.
      GLuint framebuffer = 0;
      glCreateFramebuffers(1, &framebuffer);
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
      glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
      glEnable(GL_SCISSOR_TEST);
      glScissor(0, 0, 1, 1);
      ok = rig.render(&gl_error);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glDeleteFramebuffers(1, &framebuffer);
    }
    const std::vector<std::vector<double>> after = dirty.read_all();
    dirty.make_all_clean();
    CHECK(ok);
    CHECK(gl_error == GL_NO_ERROR);
    for (size_t i = 0; i < after.size(); ++i) {
      INFO("engine state: " << dirty.items()[i].name);
      CHECK(after[i] == engine_values[i]);
    }
    CHECK(first_difference(reference, rig.output()) == "");
  }
}
