// A chain's plan (chain_plan.hpp) and the content size (content_size.hpp), on presets written here:
// each expected size and format is worked out by hand from RetroArch's rules.
#include <catch2/catch.hpp>

#include "chain_plan.hpp"
#include "content_size.hpp"
#include "memory_files.hpp"

using namespace pfx::libretro;
using pfx::test::MemoryFiles;

namespace {

Preset plan_preset(const std::string& text) {
  MemoryFiles files;
  files.texts["/p/a.slangp"] = text;
  Preset preset;
  std::string error;
  const bool read = read_preset("/p/a.slangp", files.reader(), &preset, &error);
  INFO(error);
  REQUIRE(read);
  return preset;
}

// A pass that reads texture `name` (as the reflection would say).
PassInterface reading(SemanticKind kind, int index) {
  PassInterface pass;
  pass.samplers.push_back({"t", {kind, index}, 1});
  return pass;
}

std::vector<std::pair<int, int>> as_pairs(const std::vector<PixelSize>& sizes) {
  std::vector<std::pair<int, int>> pairs;
  for (const PixelSize& s : sizes) pairs.push_back({s.width, s.height});
  return pairs;
}

}  // namespace

TEST_CASE("chain plan: passes without a scale run at their source's size and the last one draws into the output",
          "[plan]") {
  const Preset preset = plan_preset("shaders = 3\nshader0 = a.slang\nshader1 = b.slang\nshader2 = c.slang\n");
  const ChainPlan plan = plan_chain(preset, {"", "", ""}, {{}, {}, {}});
  CHECK_FALSE(plan.finish);
  CHECK(plan.passes[2].to_output);
  CHECK_FALSE(plan.passes[0].to_output);
  CHECK(as_pairs(pass_sizes(preset, plan, {320, 240}, {1920, 1080})) ==
        std::vector<std::pair<int, int>>{{320, 240}, {320, 240}, {1920, 1080}});
}

TEST_CASE("chain plan: source, viewport and absolute scales, rounded half away from zero, kept within 1..16384",
          "[plan]") {
  const Preset preset = plan_preset(
      "shaders = 5\n"
      "shader0 = a.slang\nscale_type0 = source\nscale0 = 2.5\n"        // 5 x 3 -> 12.5 -> 13, 7.5 -> 8
      "shader1 = a.slang\nscale_type_x1 = viewport\nscale_x1 = 0.5\n"  // x: 101 * 0.5 = 50.5 -> 51; y: source
      "shader2 = a.slang\nscale_type_x2 = source\nscale_x2 = 0.001\nscale_type_y2 = source\nscale_y2 = 1e6\n"  // 1,
                                                                                                               // 16384
      "shader3 = a.slang\nscale_type3 = absolute\nscale_x3 = 7\nscale_y3 = 9\n"
      "shader4 = a.slang\n");
  const ChainPlan plan = plan_chain(preset, {"", "", "", "", ""}, {{}, {}, {}, {}, {}});
  CHECK(as_pairs(pass_sizes(preset, plan, {5, 3}, {101, 41})) ==
        std::vector<std::pair<int, int>>{{13, 8}, {51, 8}, {1, 16384}, {7, 9}, {101, 41}});
}

TEST_CASE(
    "chain plan: a last pass with a scale renders into its own texture and a blit follows, unless it is the "
    "viewport's size",
    "[plan]") {
  const Preset scaled = plan_preset("shaders = 1\nshader0 = a.slang\nscale_type0 = source\nscale0 = 3\n");
  const ChainPlan plan = plan_chain(scaled, {""}, {{}});
  CHECK(plan.finish);
  CHECK_FALSE(plan.passes[0].to_output);
  CHECK(as_pairs(pass_sizes(scaled, plan, {10, 20}, {640, 480})) == std::vector<std::pair<int, int>>{{30, 60}});

  const Preset viewport = plan_preset("shaders = 1\nshader0 = a.slang\nscale_type0 = viewport\n");
  CHECK_FALSE(plan_chain(viewport, {""}, {{}}).finish);
  const Preset srgb = plan_preset("shaders = 1\nshader0 = a.slang\nscale_type0 = viewport\nsrgb_framebuffer0 = true\n");
  CHECK(plan_chain(srgb, {""}, {{}}).finish);  // RetroArch's blit reads it decoded
}

TEST_CASE("chain plan: framebuffer formats: sRGB over float over #pragma format, the flags only with a scale",
          "[plan]") {
  const Preset preset = plan_preset(
      "shaders = 5\n"
      "shader0 = a.slang\nscale_type0 = source\nsrgb_framebuffer0 = true\nfloat_framebuffer0 = true\n"
      "shader1 = a.slang\nscale_type1 = source\nfloat_framebuffer1 = true\n"
      "shader2 = a.slang\nfloat_framebuffer2 = true\n"
      "shader3 = a.slang\n"
      "shader4 = a.slang\n");
  const ChainPlan plan = plan_chain(preset, {"R16_SFLOAT", "R16_SFLOAT", "R32_SFLOAT", "", "R32_SFLOAT"},
                                    {{}, {}, {}, {}, {}});
  CHECK(plan.passes[0].format == "R8G8B8A8_SRGB");
  CHECK(plan.passes[1].format == "R16G16B16A16_SFLOAT");
  CHECK(plan.passes[2].format == "R32_SFLOAT");  // no scale: the flag is ignored
  CHECK(plan.passes[3].format == "R8G8B8A8_UNORM");
  CHECK(plan.passes[4].format == "R8G8B8A8_UNORM");  // straight into the 8-bit output
}

TEST_CASE("chain plan: history depth, feedback and mipmaps come from what the passes read and the next pass asks",
          "[plan]") {
  const Preset preset = plan_preset(
      "shaders = 3\nshader0 = a.slang\nmipmap_input0 = true\nshader1 = a.slang\nmipmap_input1 = true\nshader2 = "
      "a.slang\n");
  const ChainPlan plan = plan_chain(
      preset, {"", "", ""},
      {reading(SemanticKind::kOriginalHistory, 3), reading(SemanticKind::kPassFeedback, 2),
       reading(SemanticKind::kOriginalHistory, 1)});
  CHECK(plan.history == 3);
  CHECK(plan.original_mipmapped);
  CHECK(plan.passes[0].mipmapped);
  CHECK_FALSE(plan.passes[1].mipmapped);
  CHECK(plan.passes[2].feedback);
  CHECK(plan.finish);  // the last pass's feedback is read: it needs a texture of its own
  CHECK_FALSE(plan.passes[2].to_output);
}

TEST_CASE("content size: the frame's own, one side with the frame's aspect, or both as given", "[plan]") {
  CHECK(content_size({1920, 1080}, 0, 0) == PixelSize{1920, 1080});
  CHECK(content_size({1920, 1080}, 0, 240) == PixelSize{427, 240});  // 426.67
  CHECK(content_size({1920, 1080}, 320, 0) == PixelSize{320, 180});
  CHECK(content_size({1920, 1080}, 320, 240) == PixelSize{320, 240});
  CHECK(content_size({1, 1}, 0, 1) == PixelSize{1, 1});
  CHECK(content_size({16384, 1}, 0, 2) == PixelSize{16384, 2});  // kept within 16384
}
