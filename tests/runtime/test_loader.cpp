// The loader's message for every way a plugin can fail, and that a refused plugin leaves the
// host and the other plugins working.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "gl_test_support.hpp"

namespace fs = std::filesystem;

namespace {

std::string broken(const std::string& name) { return std::string(PFX_TEST_BROKEN_PLUGIN_DIR) + "/" + name + ".so"; }

std::string load_error(pfx::host::PluginRegistry& registry, const std::string& path) {
  std::string error;
  CHECK_FALSE(registry.load(path, &error));
  return error;
}

}  // namespace

TEST_CASE("the minimal plugin loads with both effects", "[loader]") {
  auto registry = pfx::test::make_registry();
  std::string error;
  REQUIRE(registry->load(PFX_TEST_MINIMAL_PLUGIN, &error));
  REQUIRE(registry->plugins().size() == 1);
  CHECK(registry->plugins()[0]->id == "org.pfx.test.minimal");
  CHECK(registry->find_effect("gain"));
  CHECK(registry->find_effect("boxblur"));
  CHECK_FALSE(registry->find_effect("bloom"));
}

TEST_CASE("each loader failure has its own clear message naming the file", "[loader][errors]") {
  auto registry = pfx::test::make_registry();
  std::string error;
  REQUIRE(registry->load(PFX_TEST_MINIMAL_PLUGIN, &error));
  const fs::path scratch = fs::temp_directory_path() / ("pfx-loader-test-" + std::to_string(::getpid()));
  fs::create_directories(scratch);

  const std::string missing = (scratch / "nothing.so").string();
  CHECK(load_error(*registry, missing) == missing + ": no such file");

  const std::string text = (scratch / "text.so").string();
  std::ofstream(text) << "not a library\n";
  CHECK(load_error(*registry, text) == text + ": not a shared library (no ELF header)");

  CHECK(load_error(*registry, broken("broken_no_entry")) ==
        broken("broken_no_entry") + ": no entry symbol pfx_get_entry (not a pfx plugin)");
  CHECK(load_error(*registry, broken("broken_abi_major")) ==
        broken("broken_abi_major") + ": ABI major version mismatch: plugin built for ABI 99." +
                         std::to_string(PFX_ABI_MINOR) + ", host implements ABI 1." + std::to_string(PFX_ABI_MINOR));
  CHECK(load_error(*registry, broken("broken_init_fails")) == broken("broken_init_fails") + ": init failed (status -1)");
  CHECK(load_error(*registry, broken("broken_duplicate_plugin_id")) ==
        broken("broken_duplicate_plugin_id") + ": duplicate plugin id 'org.pfx.test.minimal' (already loaded from " +
            PFX_TEST_MINIMAL_PLUGIN + ")");
  const std::string dup_effect = load_error(*registry, broken("broken_duplicate_effect_id"));
  CHECK(dup_effect.rfind(broken("broken_duplicate_effect_id") + ": duplicate effect id 'gain' (already provided by plugin 'org.pfx.test.minimal'", 0) == 0);

  // Nothing refused got in, and what was there still works.
  CHECK(registry->plugins().size() == 1);
  CHECK(registry->effects().size() == 2);
  fs::remove_all(scratch);
}

TEST_CASE("a directory load reports the refused plugins and keeps the good ones", "[loader]") {
  auto registry = pfx::test::make_registry();
  std::string error;
  REQUIRE(registry->load(PFX_TEST_MINIMAL_PLUGIN, &error));
  std::vector<std::string> errors = registry->load_directory(PFX_TEST_BROKEN_PLUGIN_DIR);
  CHECK(errors.size() == 5);
  CHECK(registry->plugins().size() == 1);
  CHECK(registry->load_directory("/nonexistent-pfx-dir") ==
        std::vector<std::string>{"/nonexistent-pfx-dir: no such plugin directory"});
}

TEST_CASE("PFX_PLUGIN_PATH adds folders after the explicit ones", "[loader]") {
  ::setenv("PFX_PLUGIN_PATH", "/a:/b::/c", 1);
  CHECK(pfx::host::PluginRegistry::search_path({"/x"}) == std::vector<std::string>{"/x", "/a", "/b", "/c"});
  ::unsetenv("PFX_PLUGIN_PATH");
  CHECK(pfx::host::PluginRegistry::search_path({"/x"}) == std::vector<std::string>{"/x"});
}

TEST_CASE("a plugin's log messages reach the host's sink attributed to the plugin", "[loader]") {
  pfx::test::CollectedLog log;
  auto registry = pfx::test::make_registry(&log);
  std::string error;
  CHECK_FALSE(registry->load(broken("broken_init_fails"), &error));
  bool attributed = false;
  for (const auto& line : log.lines) attributed |= line.find("error ") == 0 && line.find(": ") != std::string::npos;
  CHECK(attributed);
}
