// Running pfx-render as a user does, for the pfx-render tests: its exit code, stdout and stderr,
// and a scratch folder for the files it writes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace pfx::test {

struct Result {
  int exit_code = -1;
  std::string out;  // stdout; stderr goes to err
  std::string err;
};

// Runs pfx-render with `args` (a shell command line's tail) and, with_plugins, the fixture plugins
// first (never the default folder). A death by signal is reported as 128 + signal, which no test
// accepts.
Result pfx_render(const std::string& args, bool with_plugins = true);

// A folder of its own for one test case, removed with everything in it at the end.
struct Scratch {
  std::filesystem::path dir;
  Scratch();
  ~Scratch();
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
  // Only the named files: nothing left under a temporary name.
  std::vector<std::string> files() const;
};

}  // namespace pfx::test
