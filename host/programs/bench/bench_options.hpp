// pfx-bench's command line.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "camera_options.hpp"

namespace pfx::bench {

struct BenchOptions {
  bool help = false;
  std::vector<std::string> plugin_dirs;
  std::string out_dir = "out/bench";
  std::vector<std::pair<int, int>> sizes = {{1280, 720}, {1920, 1080}};
  int frames = 15, warmup = 3;
  std::vector<std::string> effects;  // empty: every loaded effect
  std::string suite_file;            // empty: the built-in suite
  bool quick = false;
  bool shift = true;                 // measure shift invariance per row (--no-shift: skip)
  std::string timing = "auto";
  // --input (repeatable): frames to measure on instead of the demo image at each size; an EXR's Z
  // channel is linear depth. --truth and --halo-mask give, per input in the same order, the image
  // every output should ideally be and the object (R > 0.5) whose halo is measured.
  std::vector<std::string> inputs, truths, halo_masks;
  std::string layer;                 // --layer NAME: the part or layer of every --input to read
  double halo_tolerance = 0.05;
  pfx::app::CameraOptions camera;    // --camera fovy=..,near=..,far=..
  std::vector<std::string> sets;     // --set effect.param=value, applied to every row first
};

bool parse_bench_options(const std::vector<std::string>& args, BenchOptions* out, std::string* error);
std::string bench_usage();

}  // namespace pfx::bench
