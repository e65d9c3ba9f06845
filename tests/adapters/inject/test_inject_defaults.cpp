// pfx-inject as a new user first meets it: no --chain, no --set. The default chain is what fits an
// application's frame (effects that need lights or normals left out, depth of field only on depth
// judged usable, focused on the centre), with the effects' defaults for display-referred frames.
#include <catch2/catch.hpp>

#include <cstdlib>

#include "inject_run.hpp"

using namespace pfx::test;
using pfx::app::DisplayImage;

namespace {

// Frame 3 of APP under pfx-inject with `args` (clock stopped), as presented.
DisplayImage presented(const ScratchFolder& folder, const std::string& name, std::vector<std::string> args,
                       const std::vector<std::string>& app, std::string* log) {
  args.insert(args.end(), {"--quit-after", "3", "--capture", "3:" + folder.file(name)});
  const InjectRun run = run_injected(folder, name, args, app);
  INFO(run.result.output << run.log);
  REQUIRE(run.result.exit_code == 0);
  if (log) *log = run.log;
  return read_png_file(folder.file(name + ".png"));
}

int channel_max(const DisplayImage& image, size_t pixel) {
  const uint8_t* p = &image.pixels[pixel * 3];
  return std::max({p[0], p[1], p[2]});
}

// Mean absolute difference per channel, in 8-bit codes, over the box [x0, x1) x [y0, y1).
double mean_difference(const DisplayImage& a, const DisplayImage& b, int x0, int y0, int x1, int y1) {
  double sum = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t i = (static_cast<size_t>(y) * a.width + x) * 3 + c;
        sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
      }
  return sum / (3.0 * (x1 - x0) * (y1 - y0));
}

}  // namespace

TEST_CASE("the default chain on glxgears: lights left out, and bloom visible around the gears") {
  ScratchFolder folder("default-glxgears");
  std::string log;
  const DisplayImage chain = presented(folder, "default", {}, {PFX_GLXGEARS}, &log);
  const DisplayImage app = presented(folder, "app", {"--dry-run"}, {PFX_GLXGEARS}, nullptr);
  INFO(log);
  CHECK(log.find("left out of the default chain, as an application's frame cannot give what they need: "
                 "tiledlights (needs lights)") != std::string::npos);
  CHECK(log.find("chain: dof,bloom,glare") != std::string::npos);
  CHECK(log.find("read as hardware depth") != std::string::npos);
  REQUIRE(chain.width == app.width);
  REQUIRE(chain.height == app.height);
  // Light spread into the black around the gears: pixels black in the application's frame that
  // the chain lit up to at least code 16.
  size_t black = 0, lit = 0;
  for (size_t i = 0; i < static_cast<size_t>(app.width) * app.height; ++i) {
    if (channel_max(app, i) > 2) continue;
    ++black;
    if (channel_max(chain, i) >= 16) ++lit;
  }
  INFO(lit << " of " << black << " black pixels lit");
  CHECK(lit >= black / 20);
}

TEST_CASE("the default chain on glmark2 shadow keeps the centre sharp: depth of field focuses there") {
  ScratchFolder folder("default-shadow");
  const std::vector<std::string> app = {PFX_GLMARK2, "-s", "240x136", "-b", "shadow"};
  std::string log;
  const DisplayImage chain = presented(folder, "default", {}, app, &log);
  INFO(log);
  CHECK(log.find("chain: dof,bloom,glare") != std::string::npos);
  // The same chain without depth of field: where dof is in focus the two are the same picture.
  const DisplayImage without_dof = presented(folder, "no-dof", {"--chain", "bloom,glare"}, app, nullptr);
  const int w = chain.width, h = chain.height;
  // The centre tenth of the frame (the horse's body) against the whole frame.
  const double centre = mean_difference(chain, without_dof, w * 9 / 20, h * 9 / 20, w * 11 / 20, h * 11 / 20);
  const double whole = mean_difference(chain, without_dof, 0, 0, w, h);
  // Focused at the default 10 m instead, the centre blurs.
  const DisplayImage fixed_focus = presented(folder, "fixed", {"--set", "dof.autofocus=off"}, app, nullptr);
  const double centre_fixed =
      mean_difference(fixed_focus, without_dof, w * 9 / 20, h * 9 / 20, w * 11 / 20, h * 11 / 20);
  INFO("centre " << centre << ", whole frame " << whole << ", centre with the focus at 10 m " << centre_fixed);
  CHECK(centre <= 0.5);
  CHECK(whole > centre);
  CHECK(centre_fixed >= 2);
}

TEST_CASE("glmark2 terrain's depth holds one value: the log says so and the frame is the depth-free chain's") {
  ScratchFolder folder("default-terrain");
  const std::vector<std::string> app = {PFX_GLMARK2, "-s", "160x90", "-b", "terrain"};
  std::string log;
  const DisplayImage chain = presented(folder, "default", {}, app, &log);
  INFO(log);
  CHECK(log.find("depth: ") != std::string::npos);
  CHECK(log.find("one value everywhere (") != std::string::npos);
  CHECK(log.find(": not used") != std::string::npos);
  CHECK(log.find("dof off: needs depth (the depth buffer holds one value everywhere") != std::string::npos);
  const DisplayImage without_dof = presented(folder, "no-dof", {"--chain", "bloom,glare"}, app, nullptr);
  CHECK(same_pixels(chain, without_dof));
}
