// Running an application under pfx-inject from the tests: in a scratch folder of its own, with
// the injector's log in a file, and (unless asked otherwise) with libfaketime stopping the clock.
#pragma once

#include <string>
#include <vector>

#include "image.hpp"
#include "view_process.hpp"

namespace pfx::test {

struct InjectRun {
  RunResult result;
  std::string log;  // what the injector wrote to --log
};

// A fresh folder under the system's temporary folder, removed by the destructor.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name);
  ~ScratchFolder();
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

// The path of AddressSanitizer's runtime in this process, or "" outside the sanitizer build: an
// application that is not sanitized gets it first in LD_PRELOAD when a sanitized pfx library goes
// into it.
std::string sanitizer_runtime();
// The path of the library of this process whose file name holds `name` ("libstdc++.so"), or "".
std::string loaded_library(const char* name);

// pfx-inject INJECT_ARGS --log FOLDER/NAME.log -- APP_ARGS, with the clock stopped at
// 2020-01-01 00:00:00 when frozen_clock, and `environment` (NAME=VALUE) added.
InjectRun run_injected(const ScratchFolder& folder, const std::string& name, const std::vector<std::string>& inject_args,
                       const std::vector<std::string>& app_args, bool frozen_clock = true,
                       const std::vector<std::string>& environment = {});

// FOLDER/plugins holding a copy of one plugin (`plugin`: its path) and nothing else; its path.
std::string plugin_folder_with(const ScratchFolder& folder, const std::string& plugin);

// glmark2 at a small window size, one scene.
std::vector<std::string> glmark2_scene(const std::string& scene);

// The whole file as text; empty when it cannot be read.
std::string read_text_file(const std::string& path);
app::Image read_exr_file(const std::string& path);
app::DisplayImage read_png_file(const std::string& path);
// Exactly equal pixels (bit for bit, NaN included) and sizes.
bool same_pixels(const app::Image& a, const app::Image& b);
bool same_pixels(const app::DisplayImage& a, const app::DisplayImage& b);

}  // namespace pfx::test
