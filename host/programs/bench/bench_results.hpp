// What one pfx-bench run measured, before it is written out as JSON, Markdown and a plot.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "error_metrics.hpp"
#include "shift_probe.hpp"

namespace pfx::bench {

struct PassMedian {
  std::string pass;
  double median_ms = 0;
};

struct BenchRow {
  std::string effect, settings;
  int width = 0, height = 0;
  double median_ms = 0;
  double copy_ms = 0;        // median of the copy pass timed before each of this row's frames
  double ratio_to_copy = 0;  // median_ms / copy_ms
  uint64_t peak_target_bytes = 0;
  int pass_count = 0;
  std::vector<PassMedian> passes;
  std::optional<ErrorMetrics> error_model, error_ideal;
  std::optional<ErrorMetrics> error_truth;  // against --truth
  std::optional<int> halo_px;               // with --halo-mask
  std::optional<ShiftFigures> shift;        // absent with --no-shift or for a no-op row
  std::string note;  // e.g. "no-op with these settings"
};

struct SizeUnit {
  int width = 0, height = 0;
  std::string source;  // "demo image" or the --input file
  double copy_ms = 0;  // median of the plain copy pass
};

struct BenchResults {
  std::string renderer, timing;
  int frames = 0, warmup = 0;
  std::vector<SizeUnit> units;
  std::vector<BenchRow> rows;
  std::vector<std::string> notes;
};

}  // namespace pfx::bench
