// docs/hosts.md against the adapters: its parameter tables are what pfx-frei0r-effects makes from
// the plugins' descriptors, its before/after pictures differ, and the ffmpeg picture is what the
// command beside it gives.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "host_programs.hpp"
#include "render_process.hpp"

namespace fs = std::filesystem;
using pfx::test::read_rgba;
using pfx::test::run_host;
using pfx::test::Scratch;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("docs/hosts.md's frei0r parameter tables are the ones the plugins' descriptors give", "[adapters][docs]") {
  auto r = pfx::test::run_program({PFX_FREI0R_EFFECTS, "--plugins", PFX_PLUGIN_OUTPUT_DIR, "--markdown"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string doc = read_text(PFX_SOURCE_DIR "/docs/hosts.md");
  const std::string begin = "<!-- parameter tables: pfx-frei0r-effects --markdown -->\n", end = "<!-- end of the tables -->";
  const size_t from = doc.find(begin), to = doc.find(end);
  REQUIRE(from != std::string::npos);
  REQUIRE(to != std::string::npos);
  CHECK(doc.substr(from + begin.size(), to - from - begin.size()) == r.output + "\n");
}

TEST_CASE("docs/hosts before and after pictures differ, and the ffmpeg one is what its command gives", "[adapters][docs]") {
  const fs::path folder = PFX_SOURCE_DIR "/docs/hosts";
  int pairs = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const std::string suffix = "-before.png";
    if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    const fs::path after = folder / (name.substr(0, name.size() - suffix.size()) + "-after.png");
    INFO(name);
    REQUIRE(fs::exists(after));
    const auto before_image = read_rgba(entry.path().string()), after_image = read_rgba(after.string());
    CHECK(before_image.width == after_image.width);
    CHECK(before_image.pixels != after_image.pixels);
    ++pairs;
  }
  CHECK(pairs >= 2);
  // The command docs/hosts.md shows for it.
  Scratch scratch;
  auto r = run_host({PFX_FFMPEG, "-hide_banner", "-loglevel", "error", "-i", (folder / "cygnus-loop-before.png").string(),
                     "-vf", "frei0r=filter_name=pfx_chain:filter_params=bloom\\,glare", "-update", "1", "-y",
                     scratch / "after.png"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(read_rgba(scratch / "after.png").pixels == read_rgba((folder / "cygnus-loop-after.png").string()).pixels);
}
