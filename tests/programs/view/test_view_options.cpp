// pfx-view's command line: defaults, and every usage error with its message.
#include <catch2/catch.hpp>

#include "view_options.hpp"

using namespace pfx::app;

namespace {

std::string usage_error(const std::vector<std::string>& args) {
  ViewOptions options;
  std::string error;
  CHECK_FALSE(parse_view_options(args, &options, &error));
  return error;
}

}  // namespace

TEST_CASE("pfx-view defaults to the demo scene, a window-sized frame and watching plugins", "[view][options]") {
  ViewOptions options;
  std::string error;
  REQUIRE(parse_view_options({}, &options, &error));
  CHECK(options.input == ViewInput::DemoScene);
  CHECK_FALSE(options.size_given);
  CHECK(options.window_width == 1280);
  CHECK(options.window_height == 720);
  CHECK(options.watch);
  CHECK(options.frames == 0);

  REQUIRE(parse_view_options({"--demo-image", "--size", "320x200", "--frames", "3", "--screenshot", "a.png"}, &options, &error));
  CHECK(options.input == ViewInput::DemoImage);
  CHECK(options.window_width == 320);  // the window follows --size unless --window is given
  CHECK(options.window_height == 200);
  REQUIRE(parse_view_options({"--size", "320x200", "--window", "800x600", "--camera", "fovy=30,far=inf"}, &options, &error));
  CHECK(options.window_width == 800);
  CHECK(options.camera.fovy_degrees == 30);
  CHECK(options.camera_keys == std::vector<std::string>{"fovy", "far"});
}

TEST_CASE("pfx-view usage errors name the option", "[view][options][errors]") {
  CHECK(usage_error({"--bogus"}) == "unknown option '--bogus' (see --help)");
  CHECK(usage_error({"--demo", "--demo-image"}) ==
        "give at most one of --demo, --demo-image, --scene FILE.obj or --input IMG");
  CHECK(usage_error({"--scene", "a.obj", "--input", "b.exr"}) ==
        "give at most one of --demo, --demo-image, --scene FILE.obj or --input IMG");
  CHECK(usage_error({"--depth", "d.exr"}) == "--depth goes with --input");
  CHECK(usage_error({"--input", "a.exr", "--size", "10x10"}) ==
        "--size applies to --demo and --demo-image (an input image has its own size)");
  CHECK(usage_error({"--demo-image", "--lights", "5"}) == "--lights and --seed go with --demo or --scene");
  CHECK(usage_error({"--screenshot", "a.png"}) == "--screenshot and --window-shot go with --frames N");
  CHECK(usage_error({"--frames", "1", "--screenshot", "a.jpg"}) == "--screenshot a.jpg: the file name must end in .png");
  CHECK(usage_error({"--frames", "0"}) == "--frames 0: expected a whole number from 1 to 1000000");
  CHECK(usage_error({"--frames", "-3"}) == "--frames -3: expected a whole number from 1 to 1000000");
  CHECK(usage_error({"--size", "0x10"}) == "--size 0x10: expected WxH with 1 <= W, H <= 16384");
  CHECK(usage_error({"--exposure", "nan"}) == "--exposure nan: not a number");
  CHECK(usage_error({"--tone", "filmic"}) == "unknown tone curve 'filmic' (choose one of: linear, reinhard, aces)");
  CHECK(usage_error({"--camera", "near=0"}) == "--camera: near must be a positive finite distance");
  CHECK(usage_error({"--preset"}) == "--preset needs a value");
}

TEST_CASE("pfx-view --attach: the panel of an injected chain, scripted edits, and what does not go with it",
          "[view][options]") {
  pfx::app::ViewOptions options;
  std::string error;
  REQUIRE(pfx::app::parse_view_options({"--attach", "s.json", "--timings", "t.json", "--frames", "9", "--edit",
                                        "3:bloom.strength=2", "--edit", "4:bloom#2.tint=1,0.5,0"},
                                       &options, &error));
  CHECK(options.attach == "s.json");
  CHECK(options.timings == "t.json");
  REQUIRE(options.edits.size() == 2);
  CHECK(options.edits[0].frame == 3);
  CHECK(options.edits[0].assignment == "bloom.strength=2");
  CHECK(options.edits[1].assignment == "bloom#2.tint=1,0.5,0");
  CHECK(usage_error({"--attach", "s.json", "--demo-image"}) ==
        "--attach shows no picture: leave out the input, --size and --screenshot");
  CHECK(usage_error({"--timings", "t.json"}) == "--timings goes with --attach");
  CHECK(usage_error({"--attach", "s.json", "--edit", "3:bloom.strength=2"}) == "--edit goes with --frames N");
  CHECK(usage_error({"--demo-image", "--edit", "3:bloom.strength=2"}) == "--edit goes with --frames N");
  // A scripted viewer takes edits too: a value that moves mid-run.
  pfx::app::ViewOptions viewer;
  REQUIRE(pfx::app::parse_view_options({"--demo-image", "--frames", "9", "--edit", "3:bloom.strength=2"}, &viewer, &error));
  CHECK(viewer.edits.size() == 1);
  CHECK(usage_error({"--attach", "s.json", "--frames", "5", "--edit", "bloom.strength=2"}) ==
        "--edit bloom.strength=2: expected FRAME:EFFECT.PARAM=VALUE");
  CHECK(usage_error({"--attach", "s.json", "--frames", "5", "--edit", "0:bloom.strength=2"}) ==
        "--edit 0:bloom.strength=2: expected FRAME:EFFECT.PARAM=VALUE");
}
