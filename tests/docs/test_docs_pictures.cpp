// Every before/after pair of pictures in docs/ differs where it says an effect acted: a picture
// that claims an effect must show it (a pfx-inject pair was once the same file twice), and no
// picture is another under a second name.
//
// Which pictures are pairs, found by name so a new pair is checked without touching this file:
//   1. NAME-before.png and NAME-after.png in the same folder, anywhere under docs/ (docs/inject,
//      and docs/hosts/<adapter>-before.png / -after.png for the video-host adapters).
//   2. In a folder of one input's pictures (docs/effects/EFFECT/, docs/fx/, docs/libretro/), the
//      input is before.png or input.png, and every other picture there of the input's size is an
//      effect run over it with some setting: each is a pair with the input. A picture of another size
//      must be one of the plots named in kPlots, or the test fails: nothing is left out silently.
// A pair meant to be the same picture (two settings that give the same result) goes in
// kMeantToBeEqual, and the page showing it says so beside the pictures.
//
// "Differs" means visibly: at least kChangedShare of the pixels differ by kVisibleCodes 8-bit
// codes or more in some channel, where the effect acts (bloom around the highlights, depth of
// field away from the focus): a picture with a few stray pixels changed claims more than it shows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "png_io.hpp"

namespace fs = std::filesystem;

namespace {

constexpr int kVisibleCodes = 8;
constexpr double kChangedShare = 0.005;
// Plots beside an effect's pictures: charts, not the effect run over its input.
const std::set<std::string> kPlots = {"error_vs_time.png", "radius_target.png"};
const std::set<std::string> kMeantToBeEqual = {};

struct Pair {
  fs::path before, after;
};

std::vector<Pair> pairs_under(const fs::path& docs) {
  std::vector<Pair> pairs;
  for (const auto& entry : fs::recursive_directory_iterator(docs)) {
    const fs::path& path = entry.path();
    const std::string name = path.filename().string();
    const std::string suffix = "-after.png";
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      pairs.push_back({path.parent_path() / (name.substr(0, name.size() - suffix.size()) + "-before.png"), path});
  }
  for (const auto& effect : fs::recursive_directory_iterator(docs)) {
    if (!effect.is_directory()) continue;
    fs::path input;
    for (const char* name : {"before.png", "input.png"})
      if (fs::exists(effect.path() / name)) input = effect.path() / name;
    if (input.empty()) continue;
    for (const auto& entry : fs::directory_iterator(effect.path()))
      if (entry.path().extension() == ".png" && entry.path() != input) pairs.push_back({input, entry.path()});
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.after < b.after; });
  return pairs;
}

pfx::app::DisplayImage read(const fs::path& path) {
  pfx::app::DisplayImage image;
  std::string error;
  INFO(path.string() << ": " << error);
  REQUIRE(pfx::app::read_png(path.string(), &image, &error));
  return image;
}

// The share of pixels whose largest channel difference (RGB) is at least kVisibleCodes.
double changed_share(const pfx::app::DisplayImage& a, const pfx::app::DisplayImage& b) {
  size_t changed = 0;
  const size_t pixels = static_cast<size_t>(a.width) * a.height;
  for (size_t i = 0; i < pixels; ++i) {
    int largest = 0;
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest, std::abs(int(a.pixels[i * a.channels + c]) - int(b.pixels[i * b.channels + c])));
    if (largest >= kVisibleCodes) ++changed;
  }
  return double(changed) / double(pixels);
}

}  // namespace

TEST_CASE("every before/after picture pair in docs/ shows its effect") {
  const fs::path docs = PFX_DOCS_DIR;
  const std::vector<Pair> pairs = pairs_under(docs);
  // The rule finds the pairs the pages show (pfx-inject's two, bloom's and dof's pictures).
  CHECK(pairs.size() >= 20);
  for (const auto& pair : pairs) {
    const std::string name = fs::relative(pair.after, docs).string();
    INFO(name << " against " << fs::relative(pair.before, docs).string());
    REQUIRE(fs::exists(pair.before));
    const auto before = read(pair.before), after = read(pair.after);
    if (before.width != after.width || before.height != after.height) {
      CHECK(kPlots.count(pair.after.filename().string()) == 1);
      continue;
    }
    const double share = changed_share(before, after);
    INFO("changed share " << share);
    if (kMeantToBeEqual.count(name)) CHECK(share == 0);
    else CHECK(share >= kChangedShare);
  }
}

// Two settings that give the same picture get one picture and a sentence, not the same file twice
// under two names that a reader takes for two results.
TEST_CASE("no two pictures in docs/ are the same file") {
  std::map<std::string, fs::path> seen;  // bytes -> the first picture holding them
  for (const auto& entry : fs::recursive_directory_iterator(PFX_DOCS_DIR)) {
    if (entry.path().extension() != ".png") continue;
    std::ifstream file(entry.path(), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const auto [first, added] = seen.emplace(std::move(bytes), entry.path());
    INFO(entry.path().string() << " is byte for byte " << first->second.string());
    CHECK(added);
  }
  CHECK(seen.size() >= 20);
}
