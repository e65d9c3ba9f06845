#include "inject_bench.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "app_launch.hpp"
#include "atomic_file.hpp"

namespace pfx::inject {
namespace {

struct Configuration {
  std::string name;
  InjectSettings settings;
  std::vector<double> frame_ms, copy_pass_ms;
  std::string chain;
};

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

bool read_stats(const std::string& path, Configuration* configuration, std::string* error) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  const auto root = nlohmann::json::parse(text.str(), nullptr, false);
  if (root.is_discarded() || !root.contains("frame_ms")) {
    *error = "no frame times: the application ended before it presented the frames asked for (or never presented)";
    return false;
  }
  configuration->frame_ms.push_back(root["frame_ms"].get<double>());
  if (root["copy_pass_ms"].get<double>() > 0) configuration->copy_pass_ms.push_back(root["copy_pass_ms"].get<double>());
  configuration->chain = root["chain"].get<std::string>();
  return true;
}

}  // namespace

int run_bench(const InjectOptions& options, const std::string& library) {
  std::vector<Configuration> configurations(3);
  configurations[0].name = "application alone";
  configurations[0].settings.bypass = true;
  configurations[1].name = "empty chain";
  configurations[1].settings = options.settings;
  configurations[1].settings.chain = std::vector<std::string>{};
  configurations[1].settings.captures.clear();
  configurations[2].name = "chain";
  configurations[2].settings = options.settings;
  configurations[2].settings.captures.clear();
  const std::string stats_path = "/tmp/pfx-inject-bench-" + std::to_string(getpid()) + ".json";
  for (int run = 0; run < options.bench_runs; ++run) {
    for (auto& configuration : configurations) {
      InjectSettings settings = configuration.settings;
      settings.quit_after = static_cast<uint64_t>(options.bench_frames);
      settings.stats_file = stats_path;
      std::fprintf(stderr, "pfx-inject --bench: run %d of %d, %s\n", run + 1, options.bench_runs,
                   configuration.name.c_str());
      std::string error;
      std::remove(stats_path.c_str());
      const int code = run_application(options.command, child_environment(settings, library), &error);
      if (code != 0 || !read_stats(stats_path, &configuration, &error)) {
        std::fprintf(stderr, "pfx-inject --bench: %s run failed (exit %d)%s%s\n", configuration.name.c_str(), code,
                     error.empty() ? "" : ": ", error.c_str());
        std::remove(stats_path.c_str());
        return code ? code : exit_code::kInjectBench;
      }
    }
  }
  std::remove(stats_path.c_str());

  std::vector<double> units;
  for (const auto& configuration : configurations)
    units.insert(units.end(), configuration.copy_pass_ms.begin(), configuration.copy_pass_ms.end());
  const double unit = median(units);
  const double alone = median(configurations[0].frame_ms);
  nlohmann::ordered_json json;
  json["application"] = options.command;
  json["frames_per_run"] = options.bench_frames;
  json["runs"] = options.bench_runs;
  json["copy_pass_ms"] = unit;
  std::printf("pfx-inject --bench: %s, %d frames per run, %d runs each (medians)\n", options.command[0].c_str(),
              options.bench_frames, options.bench_runs);
  std::printf("| configuration | chain | frame ms | added ms | added, in copy passes |\n|---|---|---:|---:|---:|\n");
  for (const auto& configuration : configurations) {
    const double frame = median(configuration.frame_ms);
    const double added = frame - alone;
    const bool first = &configuration == &configurations[0];
    char added_text[32] = "-", passes_text[32] = "-";
    if (!first) std::snprintf(added_text, sizeof added_text, "%.3f", added);
    if (!first && unit > 0) std::snprintf(passes_text, sizeof passes_text, "%.2f", added / unit);
    std::printf("| %s | %s | %.3f | %s | %s |\n", configuration.name.c_str(), first ? "-" : configuration.chain.c_str(),
                frame, added_text, passes_text);
    json["configurations"].push_back({{"name", configuration.name},
                                      {"chain", first ? "" : configuration.chain},
                                      {"frame_ms", frame},
                                      {"frame_ms_runs", configuration.frame_ms},
                                      {"added_ms", first ? 0.0 : added},
                                      {"added_copy_passes", first || unit <= 0 ? 0.0 : added / unit}});
  }
  std::printf("copy pass (the unit): %.3f ms, a full-frame RGBA16F copy timed inside the application\n", unit);
  if (!options.bench_json.empty()) {
    std::string error;
    if (!app::write_text_atomically(options.bench_json, json.dump(2) + "\n", &error)) {
      std::fprintf(stderr, "pfx-inject --bench: %s\n", error.c_str());
      return exit_code::kInjectBench;
    }
  }
  return 0;
}

}  // namespace pfx::inject
