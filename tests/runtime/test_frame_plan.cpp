// Planning without GL: skipped effects, lifetimes, pooling, and the errors a plugin author sees.
#include <catch2/catch.hpp>

#include <pfx/host/frame_plan.hpp>

using namespace pfx::host;

namespace {

DeclaredTarget target(const std::string& name, uint32_t w, uint32_t h, pfx_format format = PFX_FORMAT_RGBA16F) {
  DeclaredTarget t;
  t.name = name;
  t.width = w;
  t.height = h;
  t.format = format;
  return t;
}

DeclaredPass pass(const std::string& name, const std::string& output, std::vector<std::string> inputs) {
  DeclaredPass p;
  p.name = name;
  p.output = output;
  for (auto& input : inputs) p.inputs.push_back({input, PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE});
  return p;
}

// color -> half (w/2) -> blurred (w/2) -> output, like a two-level blur.
Declaration blur_like(uint32_t w, uint32_t h) {
  Declaration d;
  d.targets = {target("half", w / 2, h / 2), target("blurred", w / 2, h / 2)};
  d.passes = {pass("down", "half", {"color"}), pass("blur", "blurred", {"half"}),
              pass("up", "output", {"color", "blurred"})};
  return d;
}

}  // namespace

TEST_CASE("a single effect writes the chain output directly and pools its two targets apart", "[plan]") {
  Declaration blur = blur_like(64, 32);
  FramePlan plan;
  std::string error;
  REQUIRE(plan_frame({{"blur", &blur}}, 64, 32, PFX_INPUT_COLOR, &plan, &error));
  REQUIRE(plan.passes.size() == 3);
  CHECK(plan.passes[2].output.kind == ResourceRef::CHAIN_OUTPUT);
  CHECK(plan.passes[0].inputs[0].kind == ResourceRef::FRAME_INPUT);
  // half is read by "blur" while "blurred" is written: they overlap and need two textures.
  REQUIRE(plan.resources.size() == 2);
  CHECK(plan.resources[0].slot != plan.resources[1].slot);
  CHECK(plan.peak_target_bytes == 2ull * 32 * 16 * 8);
}

TEST_CASE("two effects in a chain reuse each other's targets: peak below the sum of both alone", "[plan]") {
  const uint32_t w = 64, h = 32;
  Declaration a = blur_like(w, h), b = blur_like(w, h);
  FramePlan alone_a, alone_b, both;
  std::string error;
  REQUIRE(plan_frame({{"a", &a}}, w, h, PFX_INPUT_COLOR, &alone_a, &error));
  REQUIRE(plan_frame({{"b", &b}}, w, h, PFX_INPUT_COLOR, &alone_b, &error));
  REQUIRE(plan_frame({{"a", &a}, {"b", &b}}, w, h, PFX_INPUT_COLOR, &both, &error));
  // a's output becomes a full-size intermediate; a's two half targets are free again when b runs.
  const uint64_t half = uint64_t(w / 2) * (h / 2) * 8, full = uint64_t(w) * h * 8;
  CHECK(both.peak_target_bytes == 2 * half + full);
  CHECK(both.unpooled_target_bytes == 4 * half + full);
  CHECK(both.peak_target_bytes < alone_a.peak_target_bytes + alone_b.peak_target_bytes + full);
  // b reads a's output as its colour.
  CHECK(both.passes[3].inputs[0].kind == ResourceRef::POOLED);
  CHECK(both.resources[both.passes[3].inputs[0].resource].name == "output");
}

TEST_CASE("an intermediate output lives until the next effect's last read of colour", "[plan]") {
  Declaration a = blur_like(64, 32), b = blur_like(64, 32);
  FramePlan plan;
  std::string error;
  REQUIRE(plan_frame({{"a", &a}, {"b", &b}}, 64, 32, PFX_INPUT_COLOR, &plan, &error));
  int output = plan.passes[2].output.resource;
  CHECK(plan.resources[output].first_pass == 2);
  CHECK(plan.resources[output].last_pass == 5);  // b's "up" reads color again
}

TEST_CASE("targets of different sizes or formats never share a texture", "[plan]") {
  Declaration d;
  d.targets = {target("a", 8, 8), target("b", 8, 8, PFX_FORMAT_R32F), target("c", 4, 8)};
  d.passes = {pass("1", "a", {"color"}), pass("2", "output", {"a"}), pass("3", "b", {"output"}),
              pass("4", "c", {"b"}), pass("5", "output", {"c"})};
  d.passes[4].load = PFX_LOAD_KEEP;
  FramePlan plan;
  std::string error;
  REQUIRE(plan_frame({{"e", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
  CHECK(plan.slots.size() == 3);
}

TEST_CASE("planning errors name the effect, the pass and the input", "[plan][errors]") {
  FramePlan plan;
  std::string error;
  SECTION("a missing frame input") {
    Declaration d;
    d.passes = {pass("gather", "output", {"color", "depth"})};
    REQUIRE_FALSE(plan_frame({{"dof", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(error == "effect 'dof' needs input 'depth', which this frame does not provide");
  }
  SECTION("lights asked for in the declaration's input bits") {
    Declaration d;
    d.inputs = PFX_INPUT_LIGHTS;
    d.passes = {pass("shade", "output", {"color"})};
    REQUIRE_FALSE(plan_frame({{"lit", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(error == "effect 'lit' needs lights, which this frame does not provide");
  }
  SECTION("reading a target before it is written") {
    Declaration d;
    d.targets = {target("t", 4, 4)};
    d.passes = {pass("p", "output", {"t"})};
    REQUIRE_FALSE(plan_frame({{"e", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(error == "effect 'e' pass 'p' reads target 't' before any pass writes it");
  }
  SECTION("an undeclared name") {
    Declaration d;
    d.passes = {pass("p", "output", {"nothing"})};
    REQUIRE_FALSE(plan_frame({{"e", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(error.find("'nothing', which is neither a frame input nor a declared target") != std::string::npos);
  }
  SECTION("never writing output") {
    Declaration d;
    d.targets = {target("t", 4, 4)};
    d.passes = {pass("p", "t", {"color"})};
    REQUIRE_FALSE(plan_frame({{"e", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(error == "effect 'e' never writes 'output'");
  }
  SECTION("keeping contents nobody wrote") {
    Declaration d;
    d.passes = {pass("p", "output", {"color"})};
    d.passes[0].load = PFX_LOAD_KEEP;
    REQUIRE_FALSE(plan_frame({{"e", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(error.find("keeps the contents of 'output'") != std::string::npos);
  }
  SECTION("adding into a pooled texture without clearing it") {
    Declaration d;
    d.passes = {pass("p", "output", {"color"})};
    d.passes[0].blend = PFX_BLEND_ADD;
    REQUIRE_FALSE(plan_frame({{"e", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(error.find("adds into 'output' on its first write without clearing it") != std::string::npos);
  }
  SECTION("a feedback loop") {
    Declaration d;
    d.targets = {target("t", 4, 4)};
    d.passes = {pass("a", "t", {"color"}), pass("b", "t", {"t"}), pass("c", "output", {"t"})};
    REQUIRE_FALSE(plan_frame({{"e", &d}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(error == "effect 'e' pass 'b' reads and writes 't' in the same pass");
  }
}

TEST_CASE("declarations are copied with sizes resolved against the frame", "[plan]") {
  pfx_target_desc targets[2] = {};
  targets[0].struct_size = targets[1].struct_size = sizeof(pfx_target_desc);
  targets[0].name = "half";
  targets[0].size_mode = PFX_SIZE_FRAME_SCALE;
  targets[0].scale_x = targets[0].scale_y = 0.5f;
  targets[1].name = "fixed";
  targets[1].size_mode = PFX_SIZE_FIXED;
  targets[1].width = 7;
  targets[1].height = 1;
  pfx_declaration raw{};
  raw.struct_size = sizeof raw;
  raw.targets = targets;
  raw.target_count = 2;
  Declaration copy;
  std::string error;
  REQUIRE(copy_declaration(raw, 1917, 1079, &copy, &error));
  CHECK(copy.targets[0].width == 959);  // round(958.5)
  CHECK(copy.targets[0].height == 540);
  CHECK(copy.targets[1].width == 7);
  // A 1x1 frame still gets 1x1 targets, never 0x0.
  REQUIRE(copy_declaration(raw, 1, 1, &copy, &error));
  CHECK(copy.targets[0].width == 1);
  CHECK(copy.targets[0].height == 1);

  targets[1].name = "output";
  CHECK_FALSE(copy_declaration(raw, 8, 8, &copy, &error));
  CHECK(error == "target 'output' uses a reserved name");
  targets[1].name = "fixed";
  targets[1].width = 0;
  CHECK_FALSE(copy_declaration(raw, 8, 8, &copy, &error));
  CHECK(error == "target 'fixed' is 0x1, outside 1..16384");
}

namespace {

// One pass from "color" to "output", with the promises `flags`.
Declaration one_pass(uint32_t flags) {
  Declaration d;
  d.passes = {pass("main", "output", {"color"})};
  d.flags = flags;
  return d;
}

// The chain's conversion passes of a plan, in order.
std::vector<Conversion> conversions(const FramePlan& plan) {
  std::vector<Conversion> found;
  for (const PlannedPass& p : plan.passes)
    if (p.conversion != Conversion::NONE) found.push_back(p.conversion);
  return found;
}

}  // namespace

TEST_CASE("display-referred neighbours hand sRGB codes to each other in 8 bits, with no conversion between them",
          "[plan][display_referred]") {
  const Declaration fx = one_pass(PFX_DECLARATION_DISPLAY_REFERRED);
  FramePlan plan;
  std::string error;
  REQUIRE(plan_frame({{"a", &fx}, {"b", &fx}, {"c", &fx}}, 64, 32, PFX_INPUT_COLOR, &plan, &error));
  CHECK(conversions(plan).empty());
  REQUIRE(plan.resources.size() == 2);
  for (const PlannedResource& r : plan.resources) {
    CHECK(r.format == PFX_FORMAT_RGBA8);
    CHECK(r.display_codes);
  }
  for (const PlannedPass& p : plan.passes) CHECK(p.display_referred);
  CHECK(plan.peak_target_bytes == uint64_t(2) * 64 * 32 * 4);  // half of RGBA16F's
}

TEST_CASE("beside a linear effect, codes are folded into its sampling and drawing only where it promised",
          "[plan][display_referred]") {
  const Declaration fx = one_pass(PFX_DECLARATION_DISPLAY_REFERRED);
  const Declaration promised = one_pass(PFX_DECLARATION_SAMPLES_AND_DRAWS);
  const Declaration plain = one_pass(0);
  std::string error;
  SECTION("a linear effect that promised reads and writes the codes itself") {
    FramePlan plan;
    REQUIRE(plan_frame({{"fx", &fx}, {"tint", &promised}, {"fx2", &fx}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(conversions(plan).empty());
    REQUIRE(plan.resources.size() == 2);
    CHECK(plan.resources[0].display_codes);
    CHECK(plan.resources[1].display_codes);
    CHECK_FALSE(plan.passes[1].display_referred);
  }
  SECTION("one that did not gets RGBA16F through a conversion on each side") {
    FramePlan plan;
    REQUIRE(plan_frame({{"fx", &fx}, {"gain", &plain}, {"fx2", &fx}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(conversions(plan) == std::vector<Conversion>{Conversion::TO_LINEAR, Conversion::TO_DISPLAY});
    REQUIRE(plan.passes.size() == 5);
    // fx writes codes; the conversion reads them and writes the RGBA16F colour gain reads.
    const PlannedPass& to_linear = plan.passes[1];
    CHECK(to_linear.inputs[0].resource == plan.passes[0].output.resource);
    CHECK(plan.resources[to_linear.output.resource].format == PFX_FORMAT_RGBA16F);
    CHECK(plan.passes[2].inputs[0].resource == to_linear.output.resource);
    CHECK(plan.resources[plan.passes[2].output.resource].format == PFX_FORMAT_RGBA16F);
    const PlannedPass& to_display = plan.passes[3];
    CHECK(plan.resources[to_display.output.resource].display_codes);
    CHECK(plan.passes[4].inputs[0].resource == to_display.output.resource);
    CHECK(plan.passes[4].output.kind == ResourceRef::CHAIN_OUTPUT);
  }
  SECTION("two linear effects keep RGBA16F between them") {
    FramePlan plan;
    REQUIRE(plan_frame({{"tint", &promised}, {"gain", &plain}}, 8, 8, PFX_INPUT_COLOR, &plan, &error));
    CHECK(conversions(plan).empty());
    CHECK(plan.resources[0].format == PFX_FORMAT_RGBA16F);
    CHECK_FALSE(plan.resources[0].display_codes);
  }
}
