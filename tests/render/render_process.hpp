// Runs pfx-render as a user does, for the tests in this folder: its exit code and what it
// printed, and a scratch folder for its files.
#pragma once

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pfx_test {

namespace fs = std::filesystem;

struct Result {
  int exit_code = -1;
  std::string out;  // stdout; stderr goes to err
  std::string err;
};

// Runs pfx-render with the fixture plugins (never the default folder) and returns its exit code
// and output. A death by signal is reported as 128 + signal, which no test accepts.
inline Result pfx_render(const std::string& args, bool with_plugins = true) {
  static int counter = 0;
  const fs::path err_file = fs::temp_directory_path() / ("pfx-render-test-" + std::to_string(::getpid()) + "-" +
                                                         std::to_string(counter++) + ".err");
  std::string command = std::string(PFX_RENDER) + (with_plugins ? " --plugins " PFX_TEST_PLUGIN_DIR : "") + " " +
                        args + " 2>" + err_file.string();
  Result result;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  char buffer[4096];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream in(err_file);
  result.err.assign(std::istreambuf_iterator<char>(in), {});
  fs::remove(err_file);
  return result;
}

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("pfx-render-files-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
  std::string operator/(const std::string& name) const { return (dir / name).string(); }
  // Only the named files: nothing left under a temporary name.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& item : fs::directory_iterator(dir)) names.push_back(item.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

}  // namespace pfx_test
