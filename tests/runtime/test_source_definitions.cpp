// Chain::set_source_definitions over the FX plugin's set_definitions (pfx/sources.h): a running
// instance compiles with new definitions at its next frame, a malformed list is refused and
// changes nothing, a list that does not compile leaves the last good version running, and
// instances added later get the chain's list. The FX file is written here; its grey level is a
// macro with an #ifndef default.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "gl_test_support.hpp"
#include "image_texture.hpp"

namespace fs = std::filesystem;

namespace {

const char* const kLevelFx = R"(#include "ReShade.fxh"
#ifndef PFX_TEST_LEVEL
#define PFX_TEST_LEVEL 0.25
#endif
float4 Main(float4 p : SV_Position, float2 uv : TEXCOORD) : SV_Target { return float4(PFX_TEST_LEVEL.xxx, 1.0); }
technique Level { pass { VertexShader = PostProcessVS; PixelShader = Main; } }
)";

// The effect writes `level` into its 8-bit, sRGB-encoded back buffer; the chain's output is that
// code decoded to linear light (the sRGB curve, computed here on its own).
double expected_linear(double level) {
  const double code = std::round(level * 255.0) / 255.0;
  return code <= 0.04045 ? code / 12.92 : std::pow((code + 0.055) / 1.055, 2.4);
}

bool any_line_has(const pfx::test::CollectedLog& log, const std::string& text) {
  for (const auto& line : log.lines)
    if (line.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("FX instances take a chain's preprocessor definitions, now and when added later",
          "[chain][fx][definitions]") {
  const fs::path folder = fs::temp_directory_path() / ("pfx-definitions-test-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "Level.fx") << kLevelFx;
  ::setenv("PFX_FX_PATH", folder.c_str(), 1);  // the plugin reads its folders at its first use

  pfx::test::CollectedLog log;
  auto registry = pfx::test::make_registry(&log);
  std::string error;
  INFO(error);
  REQUIRE(registry->load(std::string(PFX_PLUGIN_OUTPUT_DIR) + "/pfx_fx.so", &error));
  pfx::host::ParamStore params;
  for (const auto& effect : registry->effects()) params.add_effect(effect.desc);
  pfx::host::Chain chain(*registry, params);
  pfx::app::Image picture;
  picture.width = picture.height = 4;
  picture.rgba.assign(4 * 4 * 4, 0.5f);
  auto grey = [&] {
    pfx::host::FrameTextures textures;
    textures.color = pfx::app::upload_color_texture(picture);
    const uint32_t output = pfx::app::create_color_texture(4, 4);
    std::string render_error;
    const bool ok = chain.render(pfx::test::make_frame(4, 4), textures, output, &render_error);
    const pfx::app::Image result = pfx::app::download_color_texture(output, 4, 4);
    pfx::app::delete_texture(textures.color);
    pfx::app::delete_texture(output);
    INFO(render_error);
    REQUIRE(ok);
    return static_cast<double>(result.rgba[0]);
  };

  REQUIRE(chain.add("fx_level", &error));
  CHECK(grey() == Approx(expected_linear(0.25)).margin(1e-3));  // the file's default

  // After its first frame: the next one compiles with the definitions, as after an edit.
  REQUIRE(chain.set_source_definitions(" PFX_TEST_LEVEL = 0.75 ", &error));
  CHECK(grey() == Approx(expected_linear(0.75)).margin(1e-3));

  // Refused whole: the name is no identifier; the chain and the instance keep what they had.
  CHECK_FALSE(chain.set_source_definitions("PFX_TEST_LEVEL=0.5,2BAD", &error));
  CHECK(error.find("fx_level") != std::string::npos);
  CHECK(any_line_has(log, "'2BAD' is not a macro name"));
  CHECK(chain.source_definitions() == " PFX_TEST_LEVEL = 0.75 ");
  CHECK(grey() == Approx(expected_linear(0.75)).margin(1e-3));

  // An instance added later gets the chain's list.
  REQUIRE(chain.set_source_definitions("PFX_TEST_LEVEL=0.5", &error));
  chain.remove(0);
  REQUIRE(chain.add("fx_level", &error));
  CHECK(grey() == Approx(expected_linear(0.5)).margin(1e-3));

  // A list that does not compile: logged, and the last version that compiled keeps running.
  REQUIRE(chain.set_source_definitions("PFX_TEST_LEVEL=(", &error));
  CHECK(grey() == Approx(expected_linear(0.5)).margin(1e-3));
  CHECK(any_line_has(log, "with the new preprocessor definitions"));

  // "" is none: the default again.
  REQUIRE(chain.set_source_definitions("", &error));
  CHECK(grey() == Approx(expected_linear(0.25)).margin(1e-3));
  fs::remove_all(folder);
}
