// Dense scenes: many lights in one room, so that tiles and clusters hold far more lights than a
// fixed-size list would (the old lists held 512 and fell back to every light past that). Every
// list must hold all of its lights, exactly as brute force and the CPU reference sum them; the
// index buffer is sized from the CPU's bound, and where a memory budget is below that bound the
// exact total is read back and the frame is still exact; below the exact total it is refused.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "lights_rig.hpp"

using namespace lights_test;

namespace {

// `count` lights in a 4 m x 1.8 m x 4 m room around the box of floor_and_box, intensity 1..3 (ranges
// 4.4..7.7 m at the default cutoff): every one of them reaches most of the room.
pfx::app::Scene crowded_room(int count) {
  pfx::app::Scene scene = floor_and_box();
  uint64_t state = 12345;
  auto next = [&state] {  // a small LCG: the same lights on every platform
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < count; ++i) {
    const float x = float(-2 + 4 * next()), y = float(0.2 + 1.8 * next()), z = float(-2 + 4 * next());
    const int c = 1 + int(next() * 7) % 7;
    scene.lights.push_back(point_light(x, y, z, float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1),
                                       float(1 + 2 * next())));
  }
  return scene;
}

bool log_mentions(const Rendered& r, const std::string& text) {
  for (const auto& line : r.log)
    if (line.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("many lights in one room: lists far past 512 lights hold them all, exact against brute force and the "
          "reference",
          "[tiledlights][gl][hard]") {
  Rig rig;
  const Captured captured = capture(crowded_room(3000), 48, 32);
  check_modes(rig, captured);  // brute force against the reference, every mode against brute force
  for (const char* mode : {"tiled", "clustered", "cpu8x4"}) {
    INFO(mode);
    rig.set(std::string("mode=") + mode);
    const Rendered r = rig.render(captured);
    REQUIRE(r.error.empty());
    // Lists longer than the old fixed capacity, and on average too.
    CHECK(r.report["list_max"].get<int>() > 1000);
    if (std::string(mode) != "cpu8x4") CHECK(r.report["list_entries"].get<double>() > 512.0 * r.report["lists"].get<double>() * 0.25);
  }
}

TEST_CASE("clusters and tiles of any size hold every light of a crowded room", "[tiledlights][gl][hard]") {
  Rig rig;
  const Captured captured = capture(crowded_room(1500), 40, 24);
  rig.set("mode=brute");
  const Rendered brute = rig.render(captured);
  REQUIRE(brute.error.empty());
  for (const char* setting : {"tile_size=4", "tile_size=128", "cluster_tile_size=8", "slices=64", "slices=1"}) {
    INFO(setting);
    rig.set(setting);
    for (const char* mode : {"tiled", "clustered"}) {
      INFO(mode);
      rig.set(std::string("mode=") + mode);
      const Rendered r = rig.render(captured);
      REQUIRE(r.error.empty());
      check_list_figures(r.report);
      require_identical(r.output, brute.output, captured.width);
    }
  }
}

TEST_CASE("a list budget below the CPU's bound: the exact total is read back and the frame is still exact",
          "[tiledlights][gl][hard]") {
  Rig rig;
  const Captured captured = capture(crowded_room(2000), 48, 32);
  rig.set("mode=brute");
  const Rendered brute = rig.render(captured);
  REQUIRE(brute.error.empty());
  // Small tiles, so that the tiles' depth bounds cut lights the CPU's (depth-blind) bound counts.
  const char* small_tiles[] = {"tile_size=4", "cluster_tile_size=8"};
  for (const char* mode : {"tiled", "clustered"}) {
    INFO(mode);
    Rig fresh;  // a fresh instance: buffers grown by an earlier frame would hide the readback
    for (const char* setting : small_tiles) fresh.set(setting);
    fresh.set(std::string("mode=") + mode);
    const Rendered sized = fresh.render(captured);
    REQUIRE(sized.error.empty());
    const uint64_t entries = sized.report["list_entries"], bound = sized.report["list_bound"];
    REQUIRE(entries < bound);  // the bound is loose: there is room for a budget between them
    Rig budgeted;
    for (const char* setting : small_tiles) budgeted.set(setting);
    budgeted.set(std::string("mode=") + mode);
    budgeted.set("max_list_indices=" + std::to_string(entries));
    const Rendered r = budgeted.render(captured);
    INFO(r.error);
    REQUIRE(r.error.empty());
    CHECK(r.report["list_readbacks"] == 1);
    CHECK(r.report["list_entries"] == entries);
    CHECK(r.report["index_capacity"].get<uint64_t>() <= entries);
    CHECK(r.report["inconsistent_lists"] == 0);
    require_identical(r.output, brute.output, captured.width);

    // One index short of what the lists need: refused, naming the numbers, never cut short.
    budgeted.set("max_list_indices=" + std::to_string(entries - 1));
    const Rendered refused = budgeted.render(captured);
    CHECK_FALSE(refused.error.empty());
    CHECK(log_mentions(refused, "the light lists need " + std::to_string(entries) + " indices, more than the " +
                                    std::to_string(entries - 1)));
    // And with room again the same instance renders the same image.
    budgeted.set("max_list_indices=0");
    const Rendered again = budgeted.render(captured);
    REQUIRE(again.error.empty());
    require_identical(again.output, brute.output, captured.width);
  }
}
