// obs-module-search EXPECTED_FOLDER: finds pfx-obs the way OBS Studio does (libobs's module search
// over the system's folders and a user's ~/.config/obs-studio/plugins/%module%/bin/64bit), loads
// it, and checks that the module found under EXPECTED_FOLDER loaded, offers its filters and runs
// on a libpfxhost from under the same folder (so nothing came from the build tree). For a test
// run with no environment but HOME and DISPLAY: prints what it found, exits 0 when all holds.
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <obs-module.h>
#include <obs-nix-platform.h>
#include <obs.h>

#include "obs_test_video.hpp"
// Last: Xlib's macros (None, Always) clash with names in the headers above.
#include <X11/Xlib.h>

namespace {

void print_log(int, const char* format, va_list args, void*) {
  std::vfprintf(stderr, format, args);
  std::fputc('\n', stderr);
}

struct Found {
  std::string folder, bin, data;
};

// libobs joins its folders as they are ("/usr//lib/..."): compared after normalising.
std::string normal(const char* path) { return std::filesystem::path(path).lexically_normal().string(); }

void remember_pfx_obs(void* param, const obs_module_info2* info) {
  auto* found = static_cast<Found*>(param);
  if (std::string(info->name) != "pfx-obs") return;
  std::printf("libobs's module search: pfx-obs at %s\n", info->bin_path);
  if (normal(info->bin_path).rfind(found->folder, 0) == 0) {
    found->bin = info->bin_path;
    found->data = info->data_path;
  }
}

// The file this process mapped libpfxhost from.
std::string loaded_libpfxhost() {
  std::ifstream maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);)
    if (const size_t at = line.find('/'); at != std::string::npos && line.find("libpfxhost.so", at) != std::string::npos)
      return line.substr(at);
  return "";
}

bool start_obs(Display* display) {
  obs_set_nix_platform(OBS_NIX_PLATFORM_X11_EGL);
  obs_set_nix_platform_display(display);
  if (!obs_startup("en-US", nullptr, nullptr)) return false;
  obs_video_info video = pfx::test::obs_test_video();
  return obs_reset_video(&video) == OBS_VIDEO_SUCCESS;
}

int check(const std::string& folder) {
  // What OBS Studio adds for a user's own modules (its configuration folder's plugins/).
  const char* home = std::getenv("HOME");
  const std::string user = std::string(home ? home : "") + "/.config/obs-studio/plugins/%module%";
  obs_add_module_path((user + "/bin/64bit").c_str(), (user + "/data").c_str());
  Found found{folder, "", ""};
  obs_find_modules2(remember_pfx_obs, &found);
  if (found.bin.empty()) {
    std::fprintf(stderr, "obs-module-search: libobs's module search found no pfx-obs under %s\n", folder.c_str());
    return 1;
  }
  std::printf("found %s (data %s)\n", found.bin.c_str(), found.data.c_str());
  obs_module_t* module = nullptr;
  if (obs_open_module(&module, found.bin.c_str(), found.data.c_str()) != MODULE_SUCCESS || !obs_init_module(module)) {
    std::fprintf(stderr, "obs-module-search: %s did not load\n", found.bin.c_str());
    return 1;
  }
  const std::string host = loaded_libpfxhost();
  std::printf("libpfxhost: %s\n", host.c_str());
  if (host.rfind(folder, 0) != 0) {
    std::fprintf(stderr, "obs-module-search: libpfxhost came from '%s', not from under %s\n", host.c_str(), folder.c_str());
    return 1;
  }
  // The per-effect filters exist only when the module found pfx's plugins.
  const char* bloom = obs_source_get_display_name("pfx_bloom_filter");
  const char* chain = obs_source_get_display_name("pfx_chain_filter");
  std::printf("filters: %s, %s\n", bloom ? bloom : "(no bloom filter)", chain ? chain : "(no chain filter)");
  return bloom && chain ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: obs-module-search EXPECTED_FOLDER\n");
    return 2;
  }
  base_set_log_handler(print_log, nullptr);
  Display* display = XOpenDisplay(nullptr);
  if (!display) {
    std::fprintf(stderr, "obs-module-search: no X display (run it under xvfb-run)\n");
    return 1;
  }
  int status = start_obs(display) ? check(argv[1]) : 1;
  obs_shutdown();
  XCloseDisplay(display);
  return status;
}
