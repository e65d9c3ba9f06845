// pfx-bench --lights --quick: the tiledlights benchmark's table is consistent with itself (speed-ups
// are brute force's time over the mode's, brute force beyond the limit is its linear prediction),
// the light-field scene's lights are all counted, the error against the un-windowed sum falls as
// the cutoff falls, and the dense case measures brute force (even past the limit) and every
// culled mode's speed-up against it.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

int run(const std::string& arguments) {
  const int status = std::system((std::string(PFX_BENCH) + " " + arguments + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("lights bench quick run: speed-ups, brute force predicted past its limit, error against cutoff",
          "[bench][lights]") {
  const fs::path out = fs::temp_directory_path() / ("pfx-bench-lights-" + std::to_string(::getpid()));
  // --brute-limit 0: brute force runs at 100 lights (nothing to predict from yet) and is predicted
  // at 1000.
  REQUIRE(run("--lights --quick --brute-limit 0 --plugins " PFX_TILEDLIGHTS_DIR " --out " + out.string()) == 0);
  std::ifstream in(out / "lights.json");
  REQUIRE(in);
  const auto json = nlohmann::json::parse(in);
  CHECK(json["copy_ms"]["64x36"].get<double>() > 0);
  std::map<std::pair<int, std::string>, nlohmann::json> cells;
  for (const auto& c : json["cells"]) cells[{c["lights"].get<int>(), c["mode"].get<std::string>()}] = c;
  REQUIRE(cells.size() == 8);

  const auto& brute100 = cells[{100, "brute"}];
  const auto& brute1000 = cells[{1000, "brute"}];
  CHECK(brute100["ran"] == true);
  CHECK(brute100["speedup"].get<double>() == 1.0);
  CHECK(brute100["lights_in_view"] == 100);  // every light of the scene reaches something
  CHECK(brute1000["ran"] == false);
  CHECK(brute1000["total_ms"].get<double>() == Approx(10 * brute100["total_ms"].get<double>()).epsilon(1e-9));
  for (const char* mode : {"cpu8x4", "tiled", "clustered"}) {
    for (int lights : {100, 1000}) {
      INFO(mode << " at " << lights << " lights");
      const auto& c = cells[{lights, mode}];
      const auto& brute = cells[{lights, "brute"}];
      CHECK(c["ran"] == true);
      CHECK(c["speedup"].get<double>() ==
            Approx(brute["total_ms"].get<double>() / c["total_ms"].get<double>()).epsilon(1e-9));
      CHECK(c["speedup_estimated"] == (lights == 1000));
      CHECK(c["total_ms"].get<double>() == Approx(c["cull_ms"].get<double>() + c["shade_ms"].get<double>()).epsilon(0.05));
      CHECK(c["lights_in_view"].get<int>() > 0);
      CHECK(c["lights_in_view"].get<int>() <= lights);
      CHECK(c["list_max"].get<double>() >= c["list_mean"].get<double>());
      CHECK(c["list_max"].get<int>() <= c["lights_in_view"].get<int>());
      CHECK(c["ssbo_bytes"].get<int>() >= 48 * c["lights_in_view"].get<int>());  // 48 bytes a light at least
    }
  }

  // 0.1, 0.05 and the sqrt-colour rule: a lower cutoff means longer ranges, closer to the un-windowed sum.
  const auto& points = json["error"]["points"];
  REQUIRE(points.size() == 3);
  CHECK(points[0]["cutoff"].get<double>() == 0.1);
  CHECK(points[1]["cutoff"].get<double>() == 0.05);
  CHECK(points[2]["range_rule"] == "seed");
  const double at_01 = points[0]["rmse_over_change"].get<double>(), at_005 = points[1]["rmse_over_change"].get<double>();
  CHECK(at_01 > 0);
  CHECK(at_005 < at_01);
  CHECK(at_01 < 1);
  CHECK(points[1]["list_mean"].get<double>() > points[0]["list_mean"].get<double>());

  // The dense case: the demo scene with 1000 more lights, brute force measured despite the 0 s limit.
  std::map<std::string, nlohmann::json> dense;
  for (const auto& c : json["dense"]["cells"]) dense[c["mode"].get<std::string>()] = c;
  REQUIRE(dense.size() == 4);
  CHECK(json["dense"]["seed"] == 7);
  CHECK(dense["brute"]["ran"] == true);
  CHECK(dense["brute"]["frames"] == 1);
  CHECK(dense["brute"]["lights_in_view"] == 1400);  // the demo's 400 and the 1000 more all reach something
  // The lights that really reach a pixel: some, not all (the floor is 44 m wide, the ranges 2..9 m).
  CHECK(dense["brute"]["reach_mean"].get<double>() > 10);
  CHECK(dense["brute"]["reach_mean"].get<double>() < 700);
  // Of those, the ones in front of the surface: some of the lights reaching a floor point are below
  // nothing, but those reaching a wall from behind it light nothing.
  CHECK(dense["brute"]["lit_mean"].get<double>() > 5);
  CHECK(dense["brute"]["lit_mean"].get<double>() < dense["brute"]["reach_mean"].get<double>());
  // A tile's list holds every light of its pixels: more than each pixel's own.
  CHECK(dense["brute"]["tile_reach_mean"].get<double>() > dense["brute"]["reach_mean"].get<double>());
  CHECK(dense["brute"]["tile_reach_mean"].get<double>() <= dense["brute"]["lights_in_view"].get<double>());
  for (const char* mode : {"cpu8x4", "tiled", "clustered"}) {
    INFO("dense " << mode);
    const auto& c = dense[mode];
    CHECK(c["lights"] == 1000);
    CHECK(c["speedup"].get<double>() ==
          Approx(dense["brute"]["total_ms"].get<double>() / c["total_ms"].get<double>()).epsilon(1e-9));
    CHECK(c["list_entries"].get<double>() >= c["list_max"].get<double>());
    CHECK(c["list_mean"].get<double>() ==
          Approx(c["list_entries"].get<double>() / c["lists"].get<double>()).margin(1e-3));
  }
  std::ifstream md(out / "lights.md");
  const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  CHECK(text.find("### Dense: the demo scene") != std::string::npos);
  CHECK(text.find("- dense, 400 + 1000 lights: best mode ") != std::string::npos);
  fs::remove_all(out);
}

TEST_CASE("lights bench refuses bad options with exit code 2", "[bench][lights]") {
  CHECK(run("--lights --modes brute,fast") == 2);
  CHECK(run("--lights --counts 100,-5") == 2);
  CHECK(run("--lights --cutoffs 0") == 2);
  CHECK(run("--lights --sizes 0x10") == 2);
  CHECK(run("--lights --frames 0") == 2);
  CHECK(run("--lights --error-mode fast") == 2);
  CHECK(run("--lights --dense-counts 10,x") == 2);
  CHECK(run("--lights --dense-size 5") == 2);
  CHECK(run("--lights --help") == 0);
}
