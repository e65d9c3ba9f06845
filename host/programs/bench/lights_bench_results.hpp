// What pfx-bench --lights measures, as plain data for its reports.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "error_metrics.hpp"

namespace pfx::bench {

struct LightsCell {
  int width = 0, height = 0, lights = 0;
  std::string mode;
  bool ran = false;           // false: brute force predicted past the time limit (estimated)
  int frames = 0, warmup = 0; // what was timed (brute force may time fewer to stay in the limit)
  double cull_ms = 0, shade_ms = 0, total_ms = 0;  // medians; estimated when !ran
  double ratio_to_copy = 0;
  double speedup = 0;         // brute's total / this total at the same size and count (0: unknown)
  bool speedup_estimated = false;
  uint64_t lights_in_view = 0;
  uint64_t lists = 0;
  double list_mean = 0;
  uint64_t list_max = 0, list_entries = 0, ssbo_bytes = 0;
  // Dense brute-force cells: the means, over pixels with geometry, of the lights that really reach
  // the pixel, of those whose term there is not zero, and of those reaching a point of the pixel's
  // 16-pixel tile (light_reach.hpp); 0 elsewhere.
  double reach_mean = 0, lit_mean = 0, tile_reach_mean = 0;
};

struct CutoffPoint {
  std::string rule;  // the range_rule id: "cutoff" or "seed" (3 sqrt(max colour))
  double cutoff = 0;
  double total_ms = 0, ratio_to_copy = 0;
  double list_mean = 0;
  ErrorMetrics error;  // against the un-windowed sum (PFX_REFERENCE_IDEAL)
};

struct LightsResults {
  std::string renderer, timing;
  int frames = 0, warmup = 0;
  double brute_limit_s = 0;
  std::vector<std::pair<std::string, double>> copy_ms;  // "WxH" -> the copy pass
  std::vector<LightsCell> cells;
  // The dense case: the demo scene (pfx-render --demo --lights N --seed S) with more lights in the
  // same room, brute force always measured.
  std::vector<LightsCell> dense_cells;
  uint64_t dense_seed = 0;
  int error_width = 0, error_height = 0, error_lights = 0;
  std::string error_mode;
  std::vector<CutoffPoint> cutoffs;
  std::vector<std::string> notes;
};

}  // namespace pfx::bench
