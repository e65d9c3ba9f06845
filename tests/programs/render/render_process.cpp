#include "render_process.hpp"

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace fs = std::filesystem;

namespace pfx::test {

Result pfx_render(const std::string& args, bool with_plugins) {
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

Scratch::Scratch() : dir(fs::temp_directory_path() / ("pfx-render-files-" + std::to_string(::getpid()))) {
  fs::create_directories(dir);
}

Scratch::~Scratch() { fs::remove_all(dir); }

std::vector<std::string> Scratch::files() const {
  std::vector<std::string> names;
  for (const auto& item : fs::directory_iterator(dir)) names.push_back(item.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace pfx::test
