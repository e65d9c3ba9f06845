// pfx-frei0r-effects, which chooses the effects that get a frei0r plugin of their own: an effect
// that promises to need colour alone (PFX_EFFECT_COLOR_ONLY) is taken at its word, with no instance
// made, and one without the promise is made and asked.
#include <catch2/catch.hpp>

#include <filesystem>

#include "host_programs.hpp"
#include "render_process.hpp"
#include "view_process.hpp"

namespace fs = std::filesystem;

TEST_CASE("pfx-frei0r-effects takes an effect's colour-only promise without making it, and asks the others",
          "[adapters][frei0r]") {
  pfx::test::Scratch scratch;
  // A fixture that promises colour alone but whose pass names "depth" too, and one that asks for
  // colour alone without the promise.
  for (const char* name : {"broken_false_color_only", "broken_false_promise"})
    fs::copy_file(std::string(PFX_TEST_MISBEHAVING_PLUGIN_DIR) + "/" + name + ".so",
                  scratch / (std::string(name) + ".so"));
  auto r = pfx::test::run_program({PFX_FREI0R_EFFECTS, "--plugins", scratch.dir.string(), "--list"});
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // Made and declared, it would have said "needs depth": the promise was trusted.
  CHECK(r.output.find("broken_false_color_only: colour only (a frei0r plugin of its own)") != std::string::npos);
  CHECK(r.output.find("broken_false_promise: colour only (a frei0r plugin of its own)") != std::string::npos);
}
