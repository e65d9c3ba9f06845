// Display-referred effects (PFX_DECLARATION_DISPLAY_REFERRED) in a chain: the FX plugin running a
// ReShade effect written here, which inverts the sRGB codes it is handed (255 - code, exact in
// float), beside the example plugins' linear effects. Over an 8-bit sRGB frame a run of them
// converts nothing; where a neighbour or the frame holds linear light, the chain converts once at
// that boundary, folded into sampling or drawing when the neighbour promised
// PFX_DECLARATION_SAMPLES_AND_DRAWS and a pass of "chain" otherwise. Expectations are the codes
// the inversion and the sRGB curves give, computed here.
#include <catch2/catch.hpp>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "eight_bit_rig.hpp"

namespace fs = std::filesystem;
using pfx::test::EightBitRig;
using pfx::test::every_code;
using pfx::test::linear_to_srgb_code;
using pfx::test::srgb_to_linear;

namespace {

// Point sampling, so each pixel reads its own texel; the alpha it writes is scratch (the frame's
// alpha comes back out, as FX's back buffer alpha never reaches a display).
const char* const kInvertFx = R"(#include "ReShade.fxh"
sampler Point { Texture = ReShade::BackBufferTex; MagFilter = POINT; MinFilter = POINT; };
float4 Invert(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target {
  float4 c = tex2D(Point, uv);
  return float4(1.0 - c.rgb, c.a * 0.5);
}
technique Invert { pass { VertexShader = PostProcessVS; PixelShader = Invert; } }
)";

// The same, then a pass that samples the back buffer into a texture of its own (as effects that
// keep the last frame do): the inversion cannot draw into the host's output, which is never
// sampled, so a last pass moves the picture out.
const char* const kInvertThenKeepFx = R"(#include "ReShade.fxh"
sampler Point { Texture = ReShade::BackBufferTex; MagFilter = POINT; MinFilter = POINT; };
texture Kept { Width = BUFFER_WIDTH; Height = BUFFER_HEIGHT; Format = RGBA8; };
float4 Invert(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target {
  float4 c = tex2D(Point, uv);
  return float4(1.0 - c.rgb, c.a * 0.5);
}
float4 Keep(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target { return tex2D(Point, uv); }
technique InvertThenKeep {
  pass { VertexShader = PostProcessVS; PixelShader = Invert; }
  pass { VertexShader = PostProcessVS; PixelShader = Keep; RenderTarget = Kept; }
}
)";

// The back buffer read through an sRGB sampler and written with sRGB writes: linear light in the
// shader, the codes unchanged. The effect samples an sRGB view of the host's texture and encodes
// in its shader what it draws into the host's output.
const char* const kThroughLinearFx = R"(#include "ReShade.fxh"
sampler Linear { Texture = ReShade::BackBufferTex; MagFilter = POINT; MinFilter = POINT; SRGBTexture = true; };
float4 Through(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target { return tex2D(Linear, uv); }
technique ThroughLinear { pass { VertexShader = PostProcessVS; PixelShader = Through; SRGBWriteEnable = true; } }
)";

// The inversion drawn by vertex shaders of the effect's own that wrap PostProcessVS, as SMAA's do:
// one only adds an output (an offset the pixel shader reads), so the triangle covers the target
// as PostProcessVS's does; the other then moves the position (the triangle shrinks to the middle
// of the picture), so the pixels it leaves must keep the picture.
const char* const kWrappedFx = R"(#include "ReShade.fxh"
sampler Point { Texture = ReShade::BackBufferTex; MagFilter = POINT; MinFilter = POINT; };
void AddsOffsetVS(in uint id : SV_VertexID, out float4 position : SV_Position, out float2 uv : TEXCOORD0,
                  out float4 offset : TEXCOORD1) {
  PostProcessVS(id, position, uv);
  offset = float4(uv, uv) * 0.0;
}
void ShrinksVS(in uint id : SV_VertexID, out float4 position : SV_Position, out float2 uv : TEXCOORD0,
               out float4 offset : TEXCOORD1) {
  PostProcessVS(id, position, uv);
  offset = 0.0;
  position.xy *= 0.5;
}
float4 Invert(float4 p : SV_Position, float2 uv : TEXCOORD0, float4 offset : TEXCOORD1) : SV_Target {
  float4 c = tex2D(Point, uv + offset.xy);
  return float4(1.0 - c.rgb, c.a * 0.5);
}
technique AddsOffset { pass { VertexShader = AddsOffsetVS; PixelShader = Invert; } }
technique Shrinks { pass { VertexShader = ShrinksVS; PixelShader = Invert; } }
)";

// The FX plugin reads PFX_FX_PATH at its first use: one folder for the whole test program.
std::string fx_plugin_with_invert() {
  static const fs::path folder = [] {
    fs::path f = fs::temp_directory_path() / ("pfx-display-referred-test-" + std::to_string(::getpid()));
    fs::create_directories(f);
    std::ofstream(f / "Invert.fx") << kInvertFx;
    std::ofstream(f / "InvertThenKeep.fx") << kInvertThenKeepFx;
    std::ofstream(f / "ThroughLinear.fx") << kThroughLinearFx;
    std::ofstream(f / "Wrapped.fx") << kWrappedFx;
    ::setenv("PFX_FX_PATH", f.c_str(), 1);
    return f;
  }();
  return std::string(PFX_PLUGIN_OUTPUT_DIR) + "/pfx_fx.so";
}

std::vector<std::string> chain_passes(const EightBitRig& rig) {
  std::vector<std::string> names;
  for (const std::string& name : rig.passes())
    if (name.rfind("chain:", 0) == 0) names.push_back(name);
  return names;
}

// The worst distance in codes between `got` and `expected(code, channel)` over the colour
// channels; alpha must be the frame's, exactly.
template <class Expected>
double worst_codes(const std::vector<uint8_t>& in, const std::vector<uint8_t>& got, Expected expected) {
  double worst = 0;
  for (size_t i = 0; i < in.size(); ++i) {
    if (i % 4 == 3) {
      REQUIRE(got[i] == in[i]);
      continue;
    }
    worst = std::max(worst, std::abs(got[i] - expected(double(in[i]))));
  }
  return worst;
}

}  // namespace

TEST_CASE("display-referred effects run on an 8-bit sRGB frame as it is: no pass of the chain's, codes exact",
          "[chain][eight_bit][display_referred]") {
  EightBitRig rig(fx_plugin_with_invert());
  rig.add("fx_invert", "");
  const std::vector<uint8_t> in = every_code();
  const std::vector<uint8_t> once = rig.render(in, true);
  CHECK(chain_passes(rig).empty());
  CHECK(worst_codes(in, once, [](double code) { return 255.0 - code; }) == 0);
  // The effect reads the host's texture and draws into the host's output itself: its first pass
  // draws nothing, and the technique's one pass is the whole cost.
  CHECK(rig.passes() == std::vector<std::string>{"fx_invert:begin", "fx_invert:pass0"});
  CHECK(rig.chain->report().peak_target_bytes == 0);

  rig.add("fx_invert", "");  // a second instance: the two hand codes to each other in 8 bits
  CHECK(rig.render(in, true) == in);
  CHECK(chain_passes(rig).empty());
  CHECK(rig.chain->report().peak_target_bytes == uint64_t(pfx::test::kWidth) * pfx::test::kHeight * 4);
}

TEST_CASE("into a framebuffer of sRGB codes, a display-referred effect draws its codes as they are",
          "[chain][eight_bit][display_referred]") {
  EightBitRig rig(fx_plugin_with_invert());
  rig.add("fx_invert", "");
  const std::vector<uint8_t> in = every_code();
  CHECK(rig.render_into_framebuffer(in, true) == rig.render(in, true));
  CHECK(chain_passes(rig).empty());
}

TEST_CASE("where the frame holds linear light, the chain encodes it for a display-referred effect and decodes after",
          "[chain][eight_bit][display_referred]") {
  EightBitRig rig(fx_plugin_with_invert());
  rig.add("fx_invert", "");
  const std::vector<uint8_t> in = every_code();
  const std::vector<uint8_t> out = rig.render(in, false);  // plain RGBA8 holding linear values
  CHECK(chain_passes(rig) == std::vector<std::string>{"chain:colour to sRGB codes", "chain:sRGB codes to output"});
  const auto expected = [](double linear_code) {
    const double code = std::round(linear_to_srgb_code(linear_code / 255.0));
    return 255.0 * srgb_to_linear(255.0 - code);
  };
  CHECK(worst_codes(in, out, expected) < 1.0);
}

TEST_CASE("beside a linear effect, the boundary is folded where it promised to sample and draw, a chain pass where not",
          "[chain][eight_bit][display_referred]") {
  const std::vector<uint8_t> in = every_code();
  // invert, halve the light, invert: what each boundary hands on is an 8-bit code either way.
  const auto expected = [](double code) {
    const double halved = std::round(linear_to_srgb_code(srgb_to_linear(255.0 - code) * 0.5));
    return 255.0 - halved;
  };
  {
    EightBitRig rig(fx_plugin_with_invert());
    rig.add("fx_invert", "");
    rig.add("tint", "tint.tint=0.5,0.5,0.5");  // promised: samples the codes decoded, draws them encoded
    rig.add("fx_invert", "");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(chain_passes(rig).empty());
    CHECK(worst_codes(in, out, expected) < 1.5);
  }
  {
    EightBitRig rig(fx_plugin_with_invert());
    rig.add("fx_invert", "");
    rig.add("gain", "gain.gain=0.5");  // did not promise: RGBA16F on both of its sides
    rig.add("fx_invert", "");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(chain_passes(rig) == std::vector<std::string>{"chain:sRGB codes to linear", "chain:linear to sRGB codes"});
    CHECK(worst_codes(in, out, expected) < 1.5);
  }
}

TEST_CASE("a technique that cannot end in the host's output moves the picture itself, one that reads and writes sRGB does not",
          "[chain][eight_bit][display_referred]") {
  const std::vector<uint8_t> in = every_code();
  {
    EightBitRig rig(fx_plugin_with_invert());
    rig.add("fx_invertthenkeep", "");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(rig.passes() == std::vector<std::string>{"fx_invertthenkeep:begin", "fx_invertthenkeep:pass0",
                                                   "fx_invertthenkeep:pass1", "fx_invertthenkeep:finish"});
    CHECK(worst_codes(in, out, [](double code) { return 255.0 - code; }) == 0);
  }
  {
    EightBitRig rig(fx_plugin_with_invert());
    rig.add("fx_throughlinear", "");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(rig.passes() == std::vector<std::string>{"fx_throughlinear:begin", "fx_throughlinear:pass0"});
    CHECK(chain_passes(rig).empty());
    // The GPU's sRGB decode and the shader's encode: within a code on llvmpipe.
    CHECK(worst_codes(in, out, [](double code) { return code; }) < 1.5);
  }
}

namespace {

void log_nowhere(void*, pfx_log_level, const char*) {}
pfx_gl_proc context_proc(void*, const char* name) { return pfx::app::HeadlessContext::get_proc_address(nullptr, name); }

// The names of the passes the FX effect declares to a host of ABI 1.`minor`, and its promises.
std::vector<std::string> declared_to_host_of(uint32_t minor, uint32_t* flags) {
  pfx_host host{};
  host.struct_size = sizeof host;
  host.abi_major = PFX_ABI_MAJOR;
  host.abi_minor = minor;
  host.host_name = "test host";
  host.log = log_nowhere;
  host.get_proc_address = context_proc;
  void* library = dlopen(fx_plugin_with_invert().c_str(), RTLD_NOW | RTLD_LOCAL);
  REQUIRE(library);
  const pfx_entry* entry = reinterpret_cast<pfx_get_entry_fn>(dlsym(library, PFX_ENTRY_SYMBOL))();
  REQUIRE(entry->init(&host) == PFX_OK);
  auto effects = static_cast<const pfx_effect_factory*>(entry->get_factory(PFX_EFFECTS_FACTORY_ID));
  const pfx_effect_desc* invert = nullptr;
  for (uint32_t i = 0; i < effects->effect_count(); ++i)
    if (std::string(effects->get_effect(i)->id) == "fx_invert") invert = effects->get_effect(i);
  REQUIRE(invert);
  void* instance = nullptr;
  REQUIRE(invert->create(&host, &instance) == PFX_OK);
  const pfx_frame frame = pfx::test::make_frame(8, 8);
  std::vector<pfx_value> values(invert->param_count + 1);  // never empty: data() is then no array
  pfx_declaration declaration{};
  declaration.struct_size = sizeof declaration;
  REQUIRE(invert->declare(instance, &frame, values.data(), &declaration) == PFX_OK);
  std::vector<std::string> names;
  for (uint32_t i = 0; i < declaration.pass_count; ++i) names.push_back(declaration.passes[i].name);
  *flags = declaration.flags;
  invert->destroy(instance);
  entry->deinit();
  dlclose(library);
  return names;
}

}  // namespace

TEST_CASE("to a host older than ABI 1.6 the FX effect works in linear light and converts by itself",
          "[chain][display_referred][abi]") {
  pfx::test::gl_context();
  uint32_t flags = 0;
  CHECK(declared_to_host_of(5, &flags) == std::vector<std::string>{"encode", "pass0", "decode"});
  CHECK(flags == PFX_DECLARATION_SAMPLES_AND_DRAWS);
  CHECK(declared_to_host_of(6, &flags) == std::vector<std::string>{"begin", "pass0"});
  CHECK(flags == (PFX_DECLARATION_SAMPLES_AND_DRAWS | PFX_DECLARATION_DISPLAY_REFERRED));
}

TEST_CASE("a vertex shader that wraps PostProcessVS covers the frame as PostProcessVS does, one that moves the "
          "position keeps the picture around its triangle",
          "[chain][eight_bit][display_referred]") {
  const std::vector<uint8_t> in = every_code();
  {
    EightBitRig rig(fx_plugin_with_invert());
    rig.add("fx_addsoffset", "");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(rig.passes() == std::vector<std::string>{"fx_addsoffset:begin", "fx_addsoffset:pass0"});
    CHECK(worst_codes(in, out, [](double code) { return 255.0 - code; }) == 0);
  }
  {
    EightBitRig rig(fx_plugin_with_invert());
    rig.add("fx_shrinks", "");
    const std::vector<uint8_t> out = rig.render(in, true);
    CHECK(rig.passes() == std::vector<std::string>{"fx_shrinks:copy in", "fx_shrinks:pass0", "fx_shrinks:finish"});
    // The triangle, shrunk about the centre, covers the middle of the picture (drawn from the
    // picture stretched twice over); the corners keep the picture, every channel.
    const int w = pfx::test::kWidth, h = pfx::test::kHeight;
    const auto at = [&](int x, int y, int c) { return size_t((y * w + x) * 4 + c); };
    CHECK(out[at(w / 2, h / 2, 0)] != in[at(w / 2, h / 2, 0)]);
    for (int c = 0; c < 4; ++c) {
      CHECK(out[at(0, 0, c)] == in[at(0, 0, c)]);
      CHECK(out[at(w - 1, h - 1, c)] == in[at(w - 1, h - 1, c)]);
      CHECK(out[at(w - 1, 0, c)] == in[at(w - 1, 0, c)]);
    }
  }
}
