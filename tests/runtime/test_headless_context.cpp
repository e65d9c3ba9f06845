// The GL driver a HeadlessContext loads stays loaded after the context is gone, so the blocks the
// driver allocates once per process stay reachable (no LeakSanitizer report from an unloaded
// module) and a second context does not load the driver again. A program of its own: the check
// needs the first context of the process.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "headless_context.hpp"
#include "keep_loaded.hpp"

namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TEST_CASE("the libraries EGL loads for a context stay loaded after the context is gone", "[gl][context]") {
  const std::vector<std::string> before = pfx::app::loaded_shared_objects();
  std::vector<std::string> with_context;
  {
    std::string error;
    auto context = pfx::app::HeadlessContext::create(&error);
    INFO(error);
    REQUIRE(context);
    with_context = pfx::app::loaded_shared_objects();
  }
  std::vector<std::string> loaded_for_context;
  for (const std::string& name : with_context)
    if (!contains(before, name)) loaded_for_context.push_back(name);
  // At least the driver (Mesa: swrast_dri.so with libLLVM) came with the first context.
  REQUIRE_FALSE(loaded_for_context.empty());
  const std::vector<std::string> after = pfx::app::loaded_shared_objects();
  for (const std::string& name : loaded_for_context) {
    INFO(name);
    CHECK(contains(after, name));
  }
  // A second context finds everything loaded already.
  std::string error;
  auto again = pfx::app::HeadlessContext::create(&error);
  REQUIRE(again);
  for (const std::string& name : pfx::app::loaded_shared_objects()) {
    INFO(name);
    CHECK(contains(after, name));
  }
}
