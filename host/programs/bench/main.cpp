// pfx-bench: the measuring host. Speed against error for every effect, in one process and one
// run, with times as ratios to a plain copy pass (bench_options.cpp has the whole story).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <pfx/host/plugin_registry.hpp>

#include "bench_options.hpp"
#include "bench_report.hpp"
#include "bench_runner.hpp"
#include "exit_codes.hpp"
#include "import_bench.hpp"
#include "import_measure.hpp"
#include "lights_bench.hpp"
#include "headless_context.hpp"
#include "plugin_directory.hpp"
#include "suite.hpp"

using namespace pfx::bench;
using namespace pfx::exit_code;

namespace {

int error_exit(int code, const std::string& message) {
  std::fprintf(stderr, "pfx-bench: %s\n", message.c_str());
  return code;
}

// The suite's rows for loaded effects (filtered by --effects), plus a defaults row for every
// loaded effect the suite does not name.
std::vector<SuiteRow> select_rows(const std::vector<SuiteRow>& suite, const pfx::host::PluginRegistry& registry,
                                  const std::vector<std::string>& only, std::vector<std::string>* notes) {
  auto wanted = [&](const std::string& id) {
    return only.empty() || std::find(only.begin(), only.end(), id) != only.end();
  };
  std::vector<SuiteRow> rows;
  for (const auto& row : suite) {
    if (!wanted(row.effect)) continue;
    if (!registry.find_effect(row.effect)) {
      notes->push_back("effect '" + row.effect + "' is not loaded: its suite rows were skipped");
      continue;
    }
    rows.push_back(row);
  }
  for (const auto& effect : registry.effects()) {
    std::string id = effect.desc->id;
    bool named = std::any_of(suite.begin(), suite.end(), [&](const SuiteRow& r) { return r.effect == id; });
    if (wanted(id) && !named) rows.push_back(SuiteRow{id, {}});
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  // The OBJ import benchmark is a mode of its own (no GL): import_bench.cpp.
  if (argc > 1 && std::string(argv[1]) == "--import") return import_bench_main(std::vector<std::string>(argv + 2, argv + argc));
  // One load of that benchmark, in a process of its own (import_measure.hpp).
  if (argc > 1 && std::string(argv[1]) == "--import-load") return import_load_main(std::vector<std::string>(argv + 2, argv + argc));
  // The tiledlights benchmark against the light count renders scenes of its own: lights_bench.cpp.
  if (argc > 1 && std::string(argv[1]) == "--lights") return lights_bench_main(std::vector<std::string>(argv + 2, argv + argc));
  BenchOptions options;
  std::string message;
  if (!parse_bench_options(std::vector<std::string>(argv + 1, argv + argc), &options, &message)) {
    std::fprintf(stderr, "pfx-bench: %s\n\n%s", message.c_str(), bench_usage().c_str());
    return kUsage;
  }
  if (options.help) {
    std::fputs(bench_usage().c_str(), stdout);
    return kOk;
  }
  std::string suite_text = default_suite_text();
  if (!options.suite_file.empty()) {
    std::ifstream in(options.suite_file);
    if (!in) return error_exit(kUsage, options.suite_file + ": cannot read the suite file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    suite_text = buffer.str();
  }
  std::vector<SuiteRow> suite;
  if (!parse_suite(suite_text, &suite, &message)) return error_exit(kUsage, message);
  std::vector<BenchFrame> frames;
  if (!make_bench_frames(options, &frames, &message)) return error_exit(kBadInput, message);

  auto context = pfx::app::HeadlessContext::create(&message);
  if (!context) return error_exit(kInternal, message);
  pfx::host::PluginRegistry registry(
      [](const char* name) { return pfx::app::HeadlessContext::get_proc_address(nullptr, name); },
      pfx::host::stderr_log_sink(PFX_LOG_WARNING), "pfx-bench");
  for (const auto& error : pfx::app::load_plugins(registry, options.plugin_dirs))
    std::fprintf(stderr, "pfx-bench: warning: %s\n", error.c_str());
  for (const auto& id : options.effects)
    if (!registry.find_effect(id)) return error_exit(kEffectError, "--effects: effect '" + id + "' is not loaded");

  std::vector<std::string> notes;
  std::vector<SuiteRow> rows = select_rows(suite, registry, options.effects, &notes);
  BenchResults results = run_bench(options, registry, context->renderer(), rows, frames);
  if (!options.sets.empty()) {
    std::string all;
    for (const auto& set : options.sets) all += (all.empty() ? "" : ", ") + set;
    notes.push_back("set in every row: " + all);
  }
  results.notes.insert(results.notes.begin(), notes.begin(), notes.end());
  if (rows.empty()) results.notes.push_back("no effect loaded: only the copy pass was measured");

  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) return error_exit(kInternal, "cannot create " + options.out_dir + ": " + ec.message());
  const std::string dir = options.out_dir + "/";
  std::string skipped;
  if (!write_error_plot(results, dir + "error_vs_time.png", &message, &skipped)) return error_exit(kInternal, message);
  if (!skipped.empty()) results.notes.push_back(skipped);
  if (!write_bench_json(results, dir + "bench.json", &message) ||
      !write_bench_markdown(results, dir + "bench.md", &message))
    return error_exit(kInternal, message);
  std::fputs(bench_markdown(results).c_str(), stdout);
  std::fprintf(stderr, "pfx-bench: wrote %sbench.json, %sbench.md%s\n", dir.c_str(), dir.c_str(),
               skipped.empty() ? (", " + dir + "error_vs_time.png").c_str() : "");
  return kOk;
}
