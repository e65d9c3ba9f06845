// pfx-adapter-bench's report: a Markdown table of the rows on stdout, what a chain's way in and
// out costs beyond its effects' passes, and the rows as JSON.
#pragma once

#include <string>
#include <vector>

#include "adapter_rows.hpp"

namespace pfx::adapter_bench {

// How the rows were measured, and the unit they are quoted in.
struct RunFacts {
  std::string renderer, size;  // size: "WxH"
  int short_frames = 0, long_frames = 0, runs = 0;
  double copy_ms = 0, copy_before_ms = 0, copy_after_ms = 0;
};

void print_report(const std::vector<Row>& rows, const RunFacts& facts);
std::string report_json(const std::vector<Row>& rows, const RunFacts& facts);

}  // namespace pfx::adapter_bench
