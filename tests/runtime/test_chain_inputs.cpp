// Chain::inputs_needed: what each shipped effect's declaration needs of a frame, read from the
// declaration itself (the textures its passes read and its `inputs`), as a host that cannot give
// every input (pfx-inject) uses it to leave effects out instead of failing the frame.
#include <catch2/catch.hpp>

#include <pfx/host/frame_plan.hpp>

#include "gl_test_support.hpp"

TEST_CASE("Chain::inputs_needed gives what each effect's declaration reads, with or without passes", "[chain]") {
  pfx::test::gl_context();
  auto registry = pfx::test::make_registry();
  std::string error;
  for (const char* plugin : {"pfx_bloom.so", "pfx_dof.so", "pfx_tiledlights.so"})
    REQUIRE(registry->load(std::string(PFX_PLUGIN_OUTPUT_DIR) + "/" + plugin, &error));
  pfx::host::ParamStore params;
  pfx::host::Chain chain(*registry, params);
  for (const char* effect : {"bloom", "dof", "tiledlights"}) REQUIRE(chain.add(effect, &error));
  pfx_frame frame = pfx::test::make_frame(32, 16);
  frame.inputs = PFX_INPUT_COLOR | PFX_INPUT_DEPTH;
  frame.depth_encoding = PFX_DEPTH_HARDWARE;
  uint32_t needed[3] = {};
  for (size_t i = 0; i < 3; ++i) REQUIRE(chain.inputs_needed(i, frame, &needed[i], &error));
  CHECK(needed[0] == PFX_INPUT_COLOR);
  CHECK(needed[1] == (PFX_INPUT_COLOR | PFX_INPUT_DEPTH));
  // No lights: tiledlights declares no pass, yet still names the lights it would need.
  CHECK((needed[2] & PFX_INPUT_LIGHTS) != 0);
  CHECK(pfx::host::frame_input_names(needed[2] & ~frame.inputs).find("lights") != std::string::npos);
  // Switched off, an effect is still asked.
  chain.set_enabled(1, false);
  uint32_t off = 0;
  REQUIRE(chain.inputs_needed(1, frame, &off, &error));
  CHECK(off == needed[1]);
}
