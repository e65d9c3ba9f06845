#include "import_stages.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include <pfx/host/thread_pool.hpp>

#include "bench_timing.hpp"
#include "import_measure.hpp"
#include "obj_import.hpp"

namespace pfx::bench {

namespace {

const StageBreakdown* with_threads(const StageTable& table, unsigned threads) {
  for (const auto& b : table.by_threads)
    if (b.threads == threads && b.ok) return &b;
  return nullptr;
}

}  // namespace

double StageBreakdown::parallel_seconds() const {
  double total = 0;
  for (const auto& s : stages) total += s.parallel ? s.seconds : 0;
  return total;
}

double StageBreakdown::serial_seconds() const {
  double total = 0;
  for (const auto& s : stages) total += s.parallel ? 0 : s.seconds;
  return total;
}

int print_stages(const std::string& path, unsigned threads) {
  // The pool a host would offer, of exactly `threads` (the importer starts no thread of its own).
  pfx::host::ThreadPool pool(std::max(1u, threads));
  pfx_obj::ImportOptions options;
  options.pool = pool.service();
  options.threads = threads;
  pfx_obj::ObjMesh mesh;
  std::string error;
  if (!pfx_obj::import_obj_file(path, options, &mesh, &error)) {
    std::printf("error %s\n", error.c_str());
    return 0;
  }
  for (const auto& stage : mesh.stages)
    std::printf("%d %.9f %.9f %s\n", stage.parallel ? 1 : 0, stage.seconds, stage.cpu_seconds, stage.name);
  return 0;
}

StageBreakdown measure_stages(const std::string& path, unsigned threads, int runs) {
  StageBreakdown result;
  result.threads = threads;
  std::vector<std::vector<double>> wall, cpu;
  for (int r = 0; r < runs; ++r) {
    std::string text;
    int status = 0;
    if (!run_self({"pfx-bench", "--import-load", kStagesLoader, path, std::to_string(threads)}, &text, &status)) {
      result.error = "cannot start a process";
      return result;
    }
    std::istringstream in(text);
    std::vector<StageTime> stages;
    std::string first;
    while (in >> first) {
      if (first == "error") {
        std::getline(in, result.error);
        result.error = result.error.empty() ? "import failed" : result.error.substr(1);
        return result;
      }
      StageTime stage;
      stage.parallel = first == "1";
      in >> stage.seconds >> stage.cpu_seconds;
      in.get();
      std::getline(in, stage.name);
      stages.push_back(stage);
    }
    if (stages.empty()) {
      result.error = "the stage process reported nothing";
      return result;
    }
    if (r == 0) {
      for (const auto& stage : stages) result.stages.push_back({stage.name, stage.parallel, 0, 0});
      wall.resize(stages.size());
      cpu.resize(stages.size());
    }
    for (size_t s = 0; s < stages.size() && s < wall.size(); ++s) {
      wall[s].push_back(stages[s].seconds);
      cpu[s].push_back(stages[s].cpu_seconds);
    }
  }
  for (size_t s = 0; s < result.stages.size(); ++s) {
    result.stages[s].seconds = median(wall[s]);
    result.stages[s].cpu_seconds = median(cpu[s]);
  }
  result.ok = true;
  return result;
}

std::string stage_markdown(const std::vector<StageTable>& tables) {
  std::string text =
      "### pfx stages\n\nEach stage of pfx's import (the plugin's code, each run an import in a new process; medians). "
      "Parallel stages run on every thread, serial ones on one. Wall time counts waiting for a core on a shared "
      "machine; CPU time is that of all the process's threads during the stage.\n\n";
  char line[512];
  for (const auto& table : tables) {
    const StageBreakdown* one = with_threads(table, 1);
    for (const auto& b : table.by_threads) {
      if (!b.ok) {
        std::snprintf(line, sizeof line, "%.1f MB, %u thread(s): failed: %s\n\n", table.file_mb, b.threads,
                      b.error.substr(0, 200).c_str());
        text += line;
        continue;
      }
      std::snprintf(line, sizeof line, "%.1f MB, %u thread(s):\n\n| stage | runs on | wall s | CPU s |\n|---|---|---:|---:|\n",
                    table.file_mb, b.threads);
      text += line;
      for (const auto& s : b.stages) {
        std::snprintf(line, sizeof line, "| %s | %s | %.4f | %.4f |\n", s.name.c_str(), s.parallel ? "all threads" : "one",
                      s.seconds, s.cpu_seconds);
        text += line;
      }
      std::snprintf(line, sizeof line, "| **parallel stages** | | %.4f | |\n| **serial stages** | | %.4f | |\n\n",
                    b.parallel_seconds(), b.serial_seconds());
      text += line;
    }
    if (!one) continue;
    double one_cpu = 0;
    for (const auto& s : one->stages) one_cpu += s.cpu_seconds;
    for (const auto& b : table.by_threads) {
      if (!b.ok || b.threads == 1) continue;
      // On idle cores, the run's serial CPU time stays and its parallel CPU time divides.
      double serial_cpu = 0, parallel_cpu = 0;
      for (const auto& s : b.stages) (s.parallel ? parallel_cpu : serial_cpu) += s.cpu_seconds;
      const double idle_wall = serial_cpu + parallel_cpu / b.threads;
      const double total_one = one->parallel_seconds() + one->serial_seconds();
      const double total = b.parallel_seconds() + b.serial_seconds();
      std::snprintf(line, sizeof line,
                    "%.1f MB, %u threads against 1 thread: whole import %.2fx by wall time (parallel stages %.2fx); "
                    "serial stages %.1f %% of this run's CPU time; on %u idle cores its CPU times predict %.2fx "
                    "(1-thread CPU %.4f s / (serial %.4f s + parallel %.4f s / %u)).\n\n",
                    table.file_mb, b.threads, total > 0 ? total_one / total : 0,
                    b.parallel_seconds() > 0 ? one->parallel_seconds() / b.parallel_seconds() : 0,
                    100 * serial_cpu / std::max(1e-12, serial_cpu + parallel_cpu), b.threads,
                    idle_wall > 0 ? one_cpu / idle_wall : 0, one_cpu, serial_cpu, parallel_cpu, b.threads);
      text += line;
    }
  }
  return text;
}

}  // namespace pfx::bench
