// Runs the measurements of one pfx-bench invocation.
#pragma once

#include <pfx/host/plugin_registry.hpp>

#include "bench_frames.hpp"
#include "bench_options.hpp"
#include "bench_results.hpp"
#include "suite.hpp"

namespace pfx::bench {

// rows: the suite, already filtered to loaded effects; frames: make_bench_frames'. Progress goes to
// stderr, one line a row.
BenchResults run_bench(const BenchOptions& options, const pfx::host::PluginRegistry& registry,
                       const std::string& renderer, const std::vector<SuiteRow>& rows,
                       const std::vector<BenchFrame>& frames);

}  // namespace pfx::bench
