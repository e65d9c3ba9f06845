// pfx::host::params_at_frame_size over the FX plugin's params_at (pfx/sources.h): the parameters
// of an effect as they are at another frame size. tests/fx/frame_size/Scanlines.fx has iHeight,
// whose default and slider maximum are BUFFER_HEIGHT, and fPeriod, 4.0 at every size: the expected
// values are that file's, read by eye.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>

#include "gl_test_support.hpp"

namespace {

const pfx_param_desc* find_param(const std::vector<pfx_param_desc>& params, const char* id) {
  for (const pfx_param_desc& p : params)
    if (std::strcmp(p.id, id) == 0) return &p;
  return nullptr;
}

}  // namespace

TEST_CASE("an FX parameter written as BUFFER_HEIGHT has the frame's height as default and maximum at every size",
          "[registry][fx][frame_size]") {
  ::setenv("PFX_FX_PATH", PFX_FRAME_SIZE_FX_FOLDER, 1);  // the plugin reads its folders at its first use
  pfx::test::CollectedLog log;
  auto registry = pfx::test::make_registry(&log);
  std::string error;
  INFO(error);
  REQUIRE(registry->load(std::string(PFX_PLUGIN_OUTPUT_DIR) + "/pfx_fx.so", &error));
  REQUIRE(registry->load(std::string(PFX_PLUGIN_OUTPUT_DIR) + "/pfx_bloom.so", &error));
  const pfx::host::EffectInfo* scanlines = registry->find_effect("fx_scanlines");
  REQUIRE(scanlines);

  // As listed: a 1920x1080 frame's, flagged.
  const std::vector<pfx_param_desc> listed(scanlines->desc->params, scanlines->desc->params + scanlines->desc->param_count);
  const pfx_param_desc* height = find_param(listed, "iheight");
  REQUIRE(height);
  CHECK((height->flags & PFX_PARAM_FOLLOWS_FRAME_SIZE) != 0);
  CHECK(height->default_value.v[0] == 1080);
  CHECK(height->display_max == 1080);
  CHECK((find_param(listed, "fperiod")->flags & PFX_PARAM_FOLLOWS_FRAME_SIZE) == 0);

  for (uint32_t rows : {360u, 1u, 2161u}) {
    const std::vector<pfx_param_desc> at = pfx::host::params_at_frame_size(*scanlines, 640, rows);
    REQUIRE(at.size() == listed.size());
    INFO(rows);
    CHECK(find_param(at, "iheight")->default_value.v[0] == rows);
    CHECK(find_param(at, "iheight")->display_min == 1);
    CHECK(find_param(at, "iheight")->display_max == (rows > 1 ? rows : 2));  // an empty range is widened by 1
    CHECK(find_param(at, "fperiod")->default_value.v[0] == 4.0);
    CHECK((find_param(at, "iheight")->flags & PFX_PARAM_FOLLOWS_FRAME_SIZE) != 0);
  }
  // Sizes no frame has, and an effect whose parameters do not follow the size: nothing.
  CHECK(pfx::host::params_at_frame_size(*scanlines, 0, 360).empty());
  CHECK(pfx::host::params_at_frame_size(*scanlines, 640, 16385).empty());
  const pfx::host::EffectInfo* bloom = registry->find_effect("bloom");
  REQUIRE(bloom);
  CHECK(pfx::host::params_at_frame_size(*bloom, 640, 360).empty());
}
