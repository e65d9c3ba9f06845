// pfx-bench --lights: its options, their defaults and their parsing.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pfx::bench {

struct LightsOptions {
  bool help = false;
  std::vector<std::pair<int, int>> sizes = {{1280, 720}, {1920, 1080}};
  std::vector<int> counts = {100, 1000, 10000, 100000};
  std::vector<std::string> modes = {"brute", "cpu8x4", "tiled", "clustered"};
  int frames = 3, warmup = 1;
  double brute_limit_s = 60;
  std::pair<int, int> error_size = {640, 360};
  int error_lights = 1000;
  std::string error_mode = "tiled";
  std::vector<double> cutoffs = {0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002};
  uint64_t seed = 1;
  std::pair<int, int> dense_size = {320, 180};
  std::vector<int> dense_counts = {10000, 100000};
  uint64_t dense_seed = 7;
  std::string out_dir = "out/bench";
  std::vector<std::string> plugin_dirs;
};

// The --help text.
std::string lights_usage();

// False with *error for an unknown option or a bad value.
bool parse_lights_options(const std::vector<std::string>& list, LightsOptions* out, std::string* error);

}  // namespace pfx::bench
