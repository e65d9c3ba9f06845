// libpfxinject.so's exported functions: the linker reads them from exports.map, the code from the
// hook table (hook_table.hpp). The two must name the same functions, or a hook is either never
// reached (not exported) or exported without being handed out by the lookups.
#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "hook_table.hpp"

namespace {

// The names between "global:" and "local:" of a version script, comments left out.
std::set<std::string> exported_names(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string script = text.str();
  for (size_t start; (start = script.find("/*")) != std::string::npos;)
    script.erase(start, script.find("*/", start) + 2 - start);
  const size_t global = script.find("global:");
  const size_t local = script.find("local:");
  REQUIRE(global != std::string::npos);
  REQUIRE(local != std::string::npos);
  std::set<std::string> names;
  std::istringstream list(script.substr(global + 7, local - global - 7));
  for (std::string name; std::getline(list, name, ';');) {
    name.erase(0, name.find_first_not_of(" \t\n"));
    name.erase(name.find_last_not_of(" \t\n") + 1);
    if (!name.empty()) names.insert(name);
  }
  return names;
}

}  // namespace

TEST_CASE("exports.map names the hook table's functions and dlsym, and nothing else", "[inject]") {
  std::set<std::string> table = {"dlsym"};
  for (const auto& hook : pfx::inject::kHooks) table.insert(hook.name);
  CHECK(table.size() == pfx::inject::kHookCount + 1);  // no name twice
  CHECK(exported_names(PFX_INJECT_EXPORTS_MAP) == table);
}

TEST_CASE("the hook table finds each of its names and no other", "[inject]") {
  for (size_t hook = 0; hook < pfx::inject::kHookCount; ++hook)
    CHECK(pfx::inject::hook_index(pfx::inject::kHooks[hook].name) == static_cast<int>(hook));
  for (const char* other : {"glXSwapBuffer", "eglSwapBuffersWithDamage", "glXSwapBuffersX", "", "dlsym"})
    CHECK(pfx::inject::hook_index(other) == -1);
  CHECK(pfx::inject::hook_index(nullptr) == -1);
}
