// pfx-bench --lights' reports: lights.json, lights.md and two plots (time against light count per
// mode and size; error against the un-windowed sum against time as the cutoff varies).
#pragma once

#include <string>

#include "lights_bench_results.hpp"

namespace pfx::bench {

std::string lights_markdown(const LightsResults& results);
// Writes DIR/lights.json, DIR/lights.md, DIR/lights_time.png and DIR/lights_error.png (the plots
// need gnuplot; without it a note says so). False with *error naming the file that failed.
bool write_lights_reports(LightsResults& results, const std::string& dir, std::string* error);

}  // namespace pfx::bench
