#include "adapter_report.hpp"

#include <cstdio>

namespace pfx::adapter_bench {
namespace {

// The time a frame of the host's row named `name` took (the last of that name); 0 for none.
double row_ms(const std::vector<Row>& rows, const std::string& host, const std::string& name) {
  double ms = 0;
  for (const auto& other : rows)
    if (other.host == host && other.name == name) ms = other.ms_per_frame;
  return ms;
}

// What the row added to its baseline's time a frame; 0 for a row without a baseline.
double added_ms(const std::vector<Row>& rows, const Row& row) {
  return row.baseline.empty() ? 0 : row.ms_per_frame - row_ms(rows, row.host, row.baseline);
}

void print_table(const std::vector<Row>& rows, double copy) {
  std::printf(
      "| host | filter | frames/s | ms a frame | added ms a frame | added, in copy passes "
      "|\n|---|---|---|---|---|---|\n");
  for (const auto& row : rows) {
    if (!row.not_run.empty()) {
      std::printf("| %s | %s | | | | not measured:%s |\n", row.host.c_str(), row.name.c_str(), row.not_run.c_str());
      continue;
    }
    const double added = added_ms(rows, row);
    std::printf("| %s | %s | %.1f | %.1f | %s | %s |\n", row.host.c_str(), row.name.c_str(), 1000 / row.ms_per_frame,
                row.ms_per_frame, row.baseline.empty() ? "" : std::to_string(added).substr(0, 6).c_str(),
                row.baseline.empty() ? "" : std::to_string(added / copy).substr(0, 5).c_str());
  }
}

// A row measured from another filtered row adds a second copy of the same effect: only its
// passes. What the first copy added beyond that is the way in and out of pfx around it.
void print_beyond_passes(const std::vector<Row>& rows, double copy) {
  for (const auto& row : rows) {
    const Row* once = nullptr;
    for (const auto& other : rows)
      if (other.host == row.host && other.name == row.baseline && !other.baseline.empty()) once = &other;
    if (!once || !row.not_run.empty() || !once->not_run.empty()) continue;
    const double around = added_ms(rows, *once) - (row.ms_per_frame - once->ms_per_frame);
    std::printf(
        "\n%s, %s: beyond its effects' passes (what it added less what the second copy added): %.2f ms, "
        "%.2f copy passes\n",
        row.host.c_str(), once->name.c_str(), around, around / copy);
  }
}

}  // namespace

void print_report(const std::vector<Row>& rows, const RunFacts& facts) {
  std::printf(
      "renderer: %s\nsize: %s, frames %d and %d, median of %d runs; copy pass %.2f ms (%.2f before, %.2f after)\n\n",
      facts.renderer.c_str(), facts.size.c_str(), facts.short_frames, facts.long_frames, facts.runs, facts.copy_ms,
      facts.copy_before_ms, facts.copy_after_ms);
  print_table(rows, facts.copy_ms);
  print_beyond_passes(rows, facts.copy_ms);
}

std::string report_json(const std::vector<Row>& rows, const RunFacts& facts) {
  std::string json = "{\"renderer\": \"" + facts.renderer + "\", \"size\": \"" + facts.size +
                     "\", \"copy_pass_ms\": " + std::to_string(facts.copy_ms) + ", \"rows\": [";
  for (const auto& row : rows) {
    json += std::string(&row == &rows.front() ? "" : ", ") + "{\"host\": \"" + row.host + "\", \"filter\": \"" +
            row.name;
    if (!row.not_run.empty())
      json += "\", \"not_run\": true}";
    else
      json += "\", \"ms_per_frame\": " + std::to_string(row.ms_per_frame) +
              ", \"added_ms\": " + std::to_string(added_ms(rows, row)) + "}";
  }
  return json + "]}\n";
}

}  // namespace pfx::adapter_bench
