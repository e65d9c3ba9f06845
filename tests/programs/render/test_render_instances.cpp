// pfx-render with an effect twice in the chain: --chain bloom,glare,bloom --set bloom#2.strength=...
// sets the second bloom only, the picture is what the three effects give run one at a time with
// those values, and the report names the instances; instances that do not exist are refused.
#include <catch2/catch.hpp>

#include <cmath>

#include <nlohmann/json.hpp>

#include "exr_io.hpp"
#include "render_process.hpp"

using pfx::test::pfx_render;
using pfx::test::Result;
using pfx::test::Scratch;

namespace {

// The shipped bloom plugin (bloom and glare) over the procedural HDR image.
Result render_bloom(const std::string& args) {
  Result r = pfx_render("--plugins " PFX_PLUGIN_OUTPUT_DIR " " + args, false);
  INFO("pfx-render " << args << "\n" << r.err);
  REQUIRE(r.exit_code == 0);
  return r;
}

pfx::app::Image read(const std::string& path) {
  pfx::app::Image image;
  std::string error;
  INFO(error);
  REQUIRE(pfx::app::read_exr(path, &image, &error));
  return image;
}

double max_rgb_difference(const pfx::app::Image& a, const pfx::app::Image& b) {
  REQUIRE(a.rgba.size() == b.rgba.size());
  double most = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i)
    if (i % 4 != 3) most = std::max(most, double(std::fabs(a.rgba[i] - b.rgba[i])));
  return most;
}

}  // namespace

TEST_CASE("pfx-render --set bloom#2 sets the second bloom only and the chain renders as its instances one at a time",
          "[render][instances]") {
  Scratch scratch;
  const std::string frame = "--demo-image --size 48x32 --float ";
  Result r = render_bloom(frame + "--chain bloom,glare,bloom --set bloom.strength=0.2 --set bloom#2.strength=1.5 " +
                          "--set bloom#2.mode=gaussian --json --out " + scratch / "chain.exr");

  // The same three effects one pfx-render each, through 32-bit EXRs (the chain's intermediates
  // are half floats, which a float file holds exactly), each bloom alone with its own values.
  render_bloom(frame + "--chain bloom --set bloom.strength=0.2 --out " + scratch / "1.exr");
  render_bloom("--float --input " + scratch / "1.exr" + " --chain glare --out " + scratch / "2.exr");
  render_bloom("--float --input " + scratch / "2.exr" + " --chain bloom --set bloom.strength=1.5 " +
               "--set bloom.mode=gaussian --out " + scratch / "3.exr");
  const pfx::app::Image chain = read(scratch / "chain.exr");
  CHECK(max_rgb_difference(chain, read(scratch / "3.exr")) == 0);

  // The values matter: both blooms with the second's values (what one shared set gave) is
  // another picture.
  render_bloom(frame + "--chain bloom,glare,bloom --set bloom.strength=1.5 --set bloom.mode=gaussian " +
               "--set bloom#2.strength=1.5 --set bloom#2.mode=gaussian --out " + scratch / "shared.exr");
  CHECK(max_rgb_difference(chain, read(scratch / "shared.exr")) > 0.01);

  // The report names the second instance bloom#2 wherever it names effects.
  const auto json = nlohmann::json::parse(r.out);
  CHECK(json["effects"] == nlohmann::json::array({"bloom", "glare", "bloom#2"}));
  CHECK(json["passes"].front()["effect"] == "bloom");
  CHECK(json["passes"].back()["effect"] == "bloom#2");
  CHECK(json["effect_reports"]["bloom"]["mode"] == "chain");
  CHECK(json["effect_reports"]["bloom#2"]["mode"] == "gaussian");
}

TEST_CASE("bloom#1 is bloom and a chain with one instance per effect reads as before", "[render][instances]") {
  Scratch scratch;
  const std::string frame = "--demo-image --size 32x24 --float --chain bloom,glare ";
  render_bloom(frame + "--set bloom.strength=0.7 --out " + scratch / "plain.exr");
  render_bloom(frame + "--set bloom#1.strength=0.7 --out " + scratch / "numbered.exr");
  CHECK(max_rgb_difference(read(scratch / "plain.exr"), read(scratch / "numbered.exr")) == 0);
  const auto json = nlohmann::json::parse(render_bloom(frame + "--json").out);
  CHECK(json["effects"] == nlohmann::json::array({"bloom", "glare"}));
  for (const auto& [name, figures] : json["effect_reports"].items()) CHECK(name.find('#') == std::string::npos);
}

TEST_CASE("an instance that is not in the chain is refused with exit 2 naming the key and the count",
          "[render][instances][errors]") {
  Result r = pfx_render("--demo-image --size 8x8 --chain gain,boxblur,gain --json --set gain#3.gain=2");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--set 'gain#3.gain': there is no gain#3, effect 'gain' has 2 instances") != std::string::npos);
  r = pfx_render("--demo-image --size 8x8 --chain gain --json --set gain#0.gain=2");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("'gain#0.gain': instances are numbered from 1 (effect 'gain' has 1 instance)") !=
        std::string::npos);
  r = pfx_render("--demo-image --size 8x8 --chain gain,gain --json --set gain#x.gain=2");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("'gain#x.gain': 'x' is not an instance number (effect 'gain' has 2 instances") !=
        std::string::npos);
}
