// Writing a bench run: bench.json (everything), bench.md (tables) and error_vs_time.png
// (gnuplot: error against the ideal reference over time as a ratio to the copy pass, one curve
// per effect). Every file is written to a temporary name and renamed when complete.
#pragma once

#include <string>

#include "bench_results.hpp"

namespace pfx::bench {

bool write_bench_json(const BenchResults& results, const std::string& path, std::string* error);
bool write_bench_markdown(const BenchResults& results, const std::string& path, std::string* error);
// Returns true without writing when no row has an ideal-reference error (*skipped says why).
bool write_error_plot(const BenchResults& results, const std::string& path, std::string* error, std::string* skipped);
std::string bench_markdown(const BenchResults& results);

}  // namespace pfx::bench
