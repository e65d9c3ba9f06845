#include "inject_run.hpp"

#include <unistd.h>

#include <link.h>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "exr_io.hpp"
#include "png_io.hpp"

namespace pfx::test {

ScratchFolder::ScratchFolder(const std::string& name) {
  std::string pattern = (std::filesystem::temp_directory_path() / ("pfx-inject-" + name + "-XXXXXX")).string();
  REQUIRE(mkdtemp(pattern.data()) != nullptr);
  path_ = pattern;
}

ScratchFolder::~ScratchFolder() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string loaded_library(const char* name) {
  std::pair<const char*, std::string> search{name, ""};
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* data) {
        auto* wanted = static_cast<std::pair<const char*, std::string>*>(data);
        if (!info->dlpi_name || !std::strstr(info->dlpi_name, wanted->first)) return 0;
        wanted->second = info->dlpi_name;
        return 1;
      },
      &search);
  return search.second;
}

std::string sanitizer_runtime() {
#if defined(__SANITIZE_ADDRESS__)
  return loaded_library("libasan.so");
#else
  return "";
#endif
}

InjectRun run_injected(const ScratchFolder& folder, const std::string& name, const std::vector<std::string>& inject_args,
                       const std::vector<std::string>& app_args, bool frozen_clock,
                       const std::vector<std::string>& environment) {
  const std::string log = folder.file(name + ".log");
  std::vector<std::string> argv = {"/usr/bin/env"};
#if defined(__SANITIZE_ADDRESS__)
  // A sanitizer build of pfx-inject started with libfaketime preloaded would refuse to run
  // (AddressSanitizer wants to be the first library); the injected application gets the runtime
  // first from pfx-inject itself.
  const char* asan_options = std::getenv("ASAN_OPTIONS");
  argv.push_back(std::string("ASAN_OPTIONS=") + (asan_options ? asan_options : "") + ":verify_asan_link_order=0");
#endif
  if (frozen_clock) {
    // Absolute and without '@': the clock stands still, so an animation shows one picture.
    argv.push_back("FAKETIME=2020-01-01 00:00:00");
    argv.push_back(std::string("LD_PRELOAD=") + PFX_FAKETIME_LIBRARY);
  }
  argv.insert(argv.end(), environment.begin(), environment.end());
  argv.push_back(PFX_INJECT);
  argv.push_back("--plugins");
  argv.push_back(PFX_PLUGIN_OUTPUT_DIR);
  argv.insert(argv.end(), inject_args.begin(), inject_args.end());
  argv.push_back("--log");
  argv.push_back(log);
  argv.push_back("--");
  argv.insert(argv.end(), app_args.begin(), app_args.end());
  InjectRun run;
  run.result = run_program(argv, 120);
  run.log = read_text_file(log);
  return run;
}

std::string read_text_file(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string plugin_folder_with(const ScratchFolder& folder, const std::string& plugin) {
  const std::string plugins = folder.file("plugins");
  std::filesystem::create_directory(plugins);
  std::filesystem::copy_file(plugin, plugins + "/" + std::filesystem::path(plugin).filename().string());
  return plugins;
}

std::vector<std::string> glmark2_scene(const std::string& scene) { return {PFX_GLMARK2, "-s", "96x64", "-b", scene}; }

app::Image read_exr_file(const std::string& path) {
  app::Image image;
  std::string error;
  INFO(path << ": " << error);
  REQUIRE(app::read_exr(path, &image, &error));
  return image;
}

app::DisplayImage read_png_file(const std::string& path) {
  app::DisplayImage image;
  std::string error;
  INFO(path << ": " << error);
  REQUIRE(app::read_png(path, &image, &error));
  return image;
}

bool same_pixels(const app::Image& a, const app::Image& b) {
  return a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size() &&
         std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

bool same_pixels(const app::DisplayImage& a, const app::DisplayImage& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels && a.pixels == b.pixels;
}

}  // namespace pfx::test
