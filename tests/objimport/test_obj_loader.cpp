// The loader's checks on importer descriptors: each fault of the fixture plugins is refused with
// its own message naming the file and the importer, and leaves the registry as it was.
#include <catch2/catch.hpp>

#include <pfx/host/plugin_registry.hpp>

namespace {

std::string fixture(const std::string& fault) { return std::string(PFX_TEST_IMPORTER_FIXTURES) + "/importer_" + fault + ".so"; }

}  // namespace

TEST_CASE("obj loader: importer descriptors are checked at load", "[objimport][loader]") {
  pfx::host::PluginRegistry registry([](const char*) { return pfx_gl_proc{nullptr}; }, nullptr, "test_obj_loader");
  std::string error;
  REQUIRE(registry.load(PFX_TEST_OBJ_PLUGIN, &error));
  REQUIRE(registry.load(fixture("valid"), &error));
  CHECK(registry.find_importer_for_path("a.fixture"));
  const std::pair<const char*, std::string> cases[] = {
      {"uppercase_extension", "importer #0: importer 'fixture': extension 'OBJX' must be lower case"},
      {"dot_extension", "importer #0: importer 'fixture': extension #0 is empty or starts with '.'"},
      {"no_extensions", "importer #0: importer 'fixture': declares no file extension"},
      {"no_release", "importer #0: importer 'fixture': import and release are required"},
      {"bad_id", "importer #0: importer id must be non-empty [a-z0-9_]+"},
      {"incomplete_factory", "importer factory is incomplete"},
  };
  for (const auto& [fault, message] : cases) {
    INFO(fault);
    CHECK_FALSE(registry.load(fixture(fault), &error));
    CHECK(error == fixture(fault) + ": " + message);
  }
  CHECK_FALSE(registry.load(fixture("duplicate_id"), &error));
  CHECK(error.rfind(fixture("duplicate_id") + ": duplicate importer id 'obj' (already provided by plugin "
                                              "'org.pfx.objimport' from ", 0) == 0);
  CHECK(registry.plugins().size() == 2);
  CHECK(registry.importers().size() == 2);
}
