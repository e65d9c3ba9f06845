#include "host_programs.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include "cli_text.hpp"
#include "png_io.hpp"

#if defined(__SANITIZE_ADDRESS__)
#include <link.h>
#endif

namespace pfx::test {
namespace {

#if defined(__SANITIZE_ADDRESS__)
// This test is instrumented, the hosts are not: the runtime must be the first library of a host
// that loads an instrumented adapter, so it is preloaded from where this process has it.
std::string sanitizer_runtime() {
  std::string found;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* out) {
        if (info->dlpi_name && std::strstr(info->dlpi_name, "libasan.so")) {
          *static_cast<std::string*>(out) = info->dlpi_name;
          return 1;
        }
        return 0;
      },
      &found);
  return found;
}
#endif

}  // namespace

std::vector<std::string> host_environment(const std::vector<std::string>& extra) {
  std::vector<std::string> environment = {
      "FREI0R_PATH=" PFX_FREI0R_DIR,
      "PFX_PLUGIN_PATH=" PFX_ADAPTER_TEST_PLUGIN_DIR,
      "GST_PLUGIN_PATH=" PFX_GST_PLUGIN_DIR,
      "GST_REGISTRY=" PFX_GST_REGISTRY,
      "GST_GL_PLATFORM=egl",
      "GST_GL_WINDOW=egl-device",
  };
#if defined(__SANITIZE_ADDRESS__)
  const char* options = std::getenv("ASAN_OPTIONS");
  environment.push_back("LD_PRELOAD=" + sanitizer_runtime());
  // The hosts' own allocations are not ours to judge, and they exit with some alive; our
  // adapters' memory is checked by the load tests and by the tests that host them in-process.
  environment.push_back(std::string("ASAN_OPTIONS=") + (options ? options : "") +
                        ":verify_asan_link_order=0:detect_leaks=0");
#endif
  environment.insert(environment.end(), extra.begin(), extra.end());
  return environment;
}

std::vector<std::string> host_command(const std::vector<std::string>& argv, const std::vector<std::string>& extra) {
  std::vector<std::string> command = {"/usr/bin/env"};
  for (const auto& item : host_environment(extra)) command.push_back(item);
  command.insert(command.end(), argv.begin(), argv.end());
  return command;
}

RunResult run_host(const std::vector<std::string>& argv, const std::vector<std::string>& extra, double timeout_seconds) {
  return run_program(host_command(argv, extra), timeout_seconds);
}

app::DisplayImage read_rgba(const std::string& path) {
  app::DisplayImage image;
  std::string error;
  INFO(path << ": " << error);
  REQUIRE(app::read_png(path, &image, &error));
  if (image.channels == 3) {
    std::vector<uint8_t> rgba;
    for (size_t i = 0; i < image.pixels.size(); i += 3) {
      rgba.insert(rgba.end(), image.pixels.begin() + i, image.pixels.begin() + i + 3);
      rgba.push_back(255);
    }
    image.pixels = std::move(rgba);
    image.channels = 4;
  }
  return image;
}

std::vector<uint8_t> rgb_of(const app::DisplayImage& image) {
  std::vector<uint8_t> rgb;
  for (size_t i = 0; i < image.pixels.size(); i += image.channels)
    rgb.insert(rgb.end(), image.pixels.begin() + i, image.pixels.begin() + i + 3);
  return rgb;
}

size_t occurrences(const std::string& text, const std::string& what) {
  size_t count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++count;
  return count;
}

std::vector<uint8_t> read_bytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(file), {});
}

RunResult gst_launch(const std::string& pipeline, bool quiet, const std::vector<std::string>& extra) {
  std::vector<std::string> argv = {PFX_GST_LAUNCH};
  if (quiet) argv.push_back("-q");
  for (const auto& word : app::split_list(pipeline, ' ')) argv.push_back(word);
  return run_host(argv, extra);
}

}  // namespace pfx::test
