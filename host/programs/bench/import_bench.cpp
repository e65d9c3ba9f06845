#include "import_bench.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "bench_timing.hpp"
#include "arg_reader.hpp"
#include "cli_text.hpp"
#include "exit_codes.hpp"
#include "import_files.hpp"
#include "import_loaders.hpp"
#include "import_measure.hpp"
#include "plugin_directory.hpp"

namespace fs = std::filesystem;

namespace pfx::bench {

namespace {

struct ImportRow {
  ObjLayout layout = ObjLayout::kTriangles;
  double size_mb = 0;      // requested
  uint64_t bytes = 0;      // actual
  std::string loader;
  unsigned threads = 1;
  int runs = 0;
  double median_seconds = 0;
  double median_cpu_seconds = 0;
  uint64_t peak_bytes = 0;  // the largest over the runs
  LoadCounts counts;
  double mb_per_s() const { return median_seconds > 0 ? bytes / 1e6 / median_seconds : 0; }
  double mb_per_cpu_s() const { return median_cpu_seconds > 0 ? bytes / 1e6 / median_cpu_seconds : 0; }
};

double load_average() {
  double load[1] = {0};
  return ::getloadavg(load, 1) == 1 ? load[0] : 0;
}

const ImportRow* find_row(const std::vector<ImportRow>& rows, ObjLayout layout, double size, const std::string& loader,
                         unsigned threads) {
  for (const auto& row : rows)
    if (row.layout == layout && row.size_mb == size && row.loader == loader && row.threads == threads && row.counts.ok)
      return &row;
  return nullptr;
}

std::string markdown(const std::vector<ImportRow>& rows,
                     const ImportBenchOptions& options) {
  std::string text = "## OBJ import (pfx-bench --import)\n\n";
  char line[512];
  std::snprintf(line, sizeof line, "Median of %d runs, taken in rounds (one load of every row per round); each load in a new process; "
                "peak = resident memory the load added (mapped file pages included); CPU s = user + system time of "
                "all the load's threads (unlike wall time, it does not count waiting for a core on a shared "
                "machine). %u hardware threads; load average %.1f at the start.\n\n",
                options.runs, std::max(1u, static_cast<unsigned>(::sysconf(_SC_NPROCESSORS_ONLN))), load_average());
  text += line;
  text += "| layout | file MB | loader | threads | wall s | MB/s (wall) | CPU s | MB/CPU s | peak MB | vertices | triangles |\n";
  text += "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& row : rows) {
    if (!row.counts.ok) {
      std::snprintf(line, sizeof line, "| %s | %.1f | %s | %u | failed: %s | | | | | | |\n", layout_name(row.layout), row.bytes / 1e6, row.loader.c_str(),
                    row.threads, row.counts.error.substr(0, 200).c_str());
    } else {
      std::snprintf(line, sizeof line, "| %s | %.1f | %s | %u | %.3f | %.1f | %.3f | %.1f | %.1f | %llu | %llu |\n",
                    layout_name(row.layout), row.bytes / 1e6, row.loader.c_str(), row.threads, row.median_seconds, row.mb_per_s(),
                    row.median_cpu_seconds, row.mb_per_cpu_s(), row.peak_bytes / 1e6,
                    static_cast<unsigned long long>(row.counts.vertices),
                    static_cast<unsigned long long>(row.counts.triangles));
    }
    text += line;
  }
  text += "\n| layout | file MB | pfx 1 thread / tinyobjloader: wall (CPU) | pfx 2 threads / tinyobjloader: wall | "
          "pfx 2 threads / 1 thread: wall | pfx 1 thread / assimp: wall (CPU) | peak MB pfx 1, 2 threads / tinyobjloader |\n";
  text += "|---|---:|---:|---:|---:|---:|---|\n";
  for (ObjLayout layout : options.layouts)
    for (double size : options.sizes_mb) {
      const ImportRow* one = find_row(rows, layout, size, "pfx", 1);
      const ImportRow* two = find_row(rows, layout, size, "pfx", 2);
      const ImportRow* tiny = find_row(rows, layout, size, "tinyobjloader", 1);
      const ImportRow* assimp = find_row(rows, layout, size, "assimp", 1);
      auto ratio = [](const ImportRow* a, const ImportRow* b, bool with_cpu) -> std::string {
        if (!a || !b || b->mb_per_s() <= 0 || b->mb_per_cpu_s() <= 0) return "—";
        char value[64];
        if (with_cpu)
          std::snprintf(value, sizeof value, "%.2f (%.2f)", a->mb_per_s() / b->mb_per_s(), a->mb_per_cpu_s() / b->mb_per_cpu_s());
        else
          std::snprintf(value, sizeof value, "%.2f", a->mb_per_s() / b->mb_per_s());
        return value;
      };
      auto peak = [](const ImportRow* row) -> std::string {
        char value[32];
        std::snprintf(value, sizeof value, "%.1f", row ? row->peak_bytes / 1e6 : 0.0);
        return row ? value : "—";
      };
      std::snprintf(line, sizeof line, "| %s | %.1f | %s | %s | %s | %s | %s, %s / %s |\n", layout_name(layout),
                    one ? one->bytes / 1e6 : size, ratio(one, tiny, true).c_str(), ratio(two, tiny, false).c_str(),
                    ratio(two, one, false).c_str(), ratio(one, assimp, true).c_str(), peak(one).c_str(), peak(two).c_str(),
                    peak(tiny).c_str());
      text += line;
    }
  text += "\nVertices: pfx and assimp count distinct corners (deduplicated); tinyobjloader counts `v` "
          "positions (it does not deduplicate).\n";
  return text;
}

nlohmann::ordered_json json(const std::vector<ImportRow>& rows) {
  nlohmann::ordered_json root;
  root["rows"] = nlohmann::ordered_json::array();
  for (const auto& row : rows) {
    nlohmann::ordered_json r;
    r["layout"] = layout_name(row.layout);
    r["size_mb"] = row.size_mb;
    r["bytes"] = row.bytes;
    r["loader"] = row.loader;
    r["threads"] = row.threads;
    r["ok"] = row.counts.ok;
    if (!row.counts.ok) r["error"] = row.counts.error;
    r["runs"] = row.runs;
    r["seconds"] = row.median_seconds;
    r["mb_per_s"] = row.mb_per_s();
    r["cpu_seconds"] = row.median_cpu_seconds;
    r["mb_per_cpu_s"] = row.mb_per_cpu_s();
    r["peak_bytes"] = row.peak_bytes;
    r["vertices"] = row.counts.vertices;
    r["triangles"] = row.counts.triangles;
    root["rows"].push_back(r);
  }
  return root;
}

bool write_text(const std::string& path, const std::string& text, std::string* error) {
  return pfx::app::write_atomically(path, [&](const std::string& temp, std::string* reason) {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    out.close();
    if (!out) *reason = "write failed";
    return static_cast<bool>(out);
  }, error);
}

// The folder the files are generated in: --dir, or a new one under /tmp.
bool make_work_dir(ImportBenchOptions* options) {
  if (options->work_dir.empty())
    options->work_dir = (fs::temp_directory_path() / ("pfx-bench-import-" + std::to_string(::getpid()))).string();
  std::error_code ec;
  fs::create_directories(options->work_dir, ec);
  if (ec) {
    std::fprintf(stderr, "pfx-bench: cannot create %s: %s\n", options->work_dir.c_str(), ec.message().c_str());
    return false;
  }
  return true;
}

// One file's rows: every loader at each of its thread counts; a loader not built in is a failed row.
void add_file_rows(const ImportBenchOptions& options, const std::vector<std::string>& built, ObjLayout layout,
                   double size, const GeneratedObj& file, std::vector<ImportRow>* rows) {
  for (const auto& loader : options.loaders) {
    const std::vector<unsigned> thread_counts = loader_is_multithreaded(loader) ? options.threads
                                                                                : std::vector<unsigned>{1};
    for (unsigned threads : thread_counts) {
      ImportRow row;
      row.layout = layout;
      row.size_mb = size;
      row.bytes = file.bytes;
      row.loader = loader;
      row.threads = threads;
      if (std::find(built.begin(), built.end(), loader) == built.end())
        row.counts.error = "not built into this pfx-bench (package missing at configure time)";
      rows->push_back(row);
    }
  }
}

// Every row's loads in rounds — one load of each row per round — so that whatever changes on
// the machine during the run (memory handed back to the hypervisor, other work) falls on every
// loader alike instead of on whichever row came first. A row stops at its first failed load.
void measure_in_rounds(const ImportBenchOptions& options, const GeneratedObj& file, ObjLayout layout,
                       std::vector<ImportRow>::iterator first, std::vector<ImportRow>::iterator last) {
  const size_t count = static_cast<size_t>(last - first);
  std::vector<std::vector<double>> seconds(count), cpu_seconds(count);
  std::vector<bool> stopped(count, false);
  for (size_t i = 0; i < count; ++i) stopped[i] = !first[i].counts.error.empty();
  for (int r = 0; r < options.runs; ++r) {
    for (size_t i = 0; i < count; ++i) {
      ImportRow& row = first[i];
      if (stopped[i]) continue;
      std::fprintf(stderr, "pfx-bench: round %d of %d, %s, %u thread(s), %s, %.0f MB\n", r + 1, options.runs,
                   row.loader.c_str(), row.threads, layout_name(layout), file.bytes / 1e6);
      LoadMeasure m = measure_in_new_process(row.loader, file.path, row.threads, options.plugin_dirs);
      row.counts = m.counts;
      if (!m.counts.ok) {
        stopped[i] = true;
        continue;
      }
      seconds[i].push_back(m.seconds);
      cpu_seconds[i].push_back(m.cpu_seconds);
      row.peak_bytes = std::max(row.peak_bytes, m.peak_bytes);
      ++row.runs;
    }
  }
  for (size_t i = 0; i < count; ++i) {
    first[i].median_seconds = median(seconds[i]);
    first[i].median_cpu_seconds = median(cpu_seconds[i]);
  }
}

// A file in each layout at each size, generated and read into the page cache, then its rows
// measured. False with *error when a file cannot be made; the rows so far stay.
bool measure_files(const ImportBenchOptions& options, const std::vector<std::string>& built,
                   std::vector<ImportRow>* rows, std::string* error) {
  for (ObjLayout layout : options.layouts)
    for (double size : options.sizes_mb) {
      GeneratedObj file;
      std::fprintf(stderr, "pfx-bench: generating a %g MB OBJ file (%s) in %s\n", size, layout_name(layout),
                   options.work_dir.c_str());
      if (!generate_obj(options.work_dir, layout, size, &file, error) || !warm_file(file.path, error)) return false;
      const size_t first_row = rows->size();
      add_file_rows(options, built, layout, size, file, rows);
      measure_in_rounds(options, file, layout, rows->begin() + static_cast<long>(first_row), rows->end());
    }
  return true;
}

// DIR/import.json and DIR/import.md, and the tables on stdout.
bool write_reports(const std::vector<ImportRow>& rows, const ImportBenchOptions& options, std::string* error) {
  std::error_code ec;
  fs::create_directories(options.out_dir, ec);
  const std::string text = markdown(rows, options);
  if (!write_text(options.out_dir + "/import.json", json(rows).dump(2) + "\n", error) ||
      !write_text(options.out_dir + "/import.md", text, error))
    return false;
  std::fputs(text.c_str(), stdout);
  std::fprintf(stderr, "pfx-bench: wrote %s/import.json, %s/import.md\n", options.out_dir.c_str(),
               options.out_dir.c_str());
  return true;
}

}  // namespace

std::string import_bench_usage() {
  return
      "usage: pfx-bench --import [--layouts a,b,...] [--sizes MB,...] [--threads N,...] [--loaders a,b,...]\n"
      "                          [--runs N] [--dir DIR] [--keep] [--out DIR] [--plugins DIR]...\n"
      "\n"
      "Measures the OBJ importer plugin against tinyobjloader and assimp, in one run, on OBJ files\n"
      "generated in each layout at each size (a height field's grid, written as exporters write it):\n"
      "MB/s (file bytes over the median wall time of a load) and the peak memory a load adds, with pfx\n"
      "at each thread count (the others are single-threaded). Each file is read once into the page\n"
      "cache and written out to disk first; then each load runs in a new process (pfx-bench runs\n"
      "itself with the internal option --import-load), in rounds of one load per row.\n"
      "Writes DIR/import.json and DIR/import.md.\n"
      "\n"
      "  --layouts LIST    any of positions (v only, triangles), triangles (v, vt, vn, v/vt/vn\n"
      "                    triangles), quads (the same as quads), relative-quads (with negative\n"
      "                    indices), objects (quads in 8 objects and groups, 3 materials),\n"
      "                    long-numbers (triangles, 9 decimals and an exponent), short-numbers\n"
      "                    (triangles, 2 decimals); default: all\n"
      "  --sizes LIST      file sizes in MB (default 100,500)\n"
      "  --threads LIST    pfx thread counts (default 1,2)\n"
      "  --loaders LIST    pfx,tinyobjloader,assimp (default: all three)\n"
      "  --runs N          loads per row, taken in rounds of one load per row (default 5)\n"
      "  --dir DIR         where to generate the files (default: a new folder under /tmp, removed\n"
      "                    after the run unless --keep); existing complete files there are reused\n"
      "  --out DIR         output folder (default out/bench)\n"
      "  --plugins DIR     plugin folder (default: the one next to this program's folder)\n"
      "\n"
      "exit codes: 0 ok (failed loads are reported in the tables), 1 internal error, 2 usage\n";
}

bool parse_import_bench_options(const std::vector<std::string>& list, ImportBenchOptions* out, std::string* error) {
  ImportBenchOptions options;
  pfx::app::ArgReader args(list, error);
  while (args.next()) {
    const std::string& arg = args.arg();
    std::string text;
    if (arg == "-h" || arg == "--help") options.help = true;
    else if (arg == "--keep") options.keep_files = true;
    else if (arg == "--dir") { if (!args.value(&text)) return false; options.work_dir = text; }
    else if (arg == "--out") { if (!args.value(&text)) return false; options.out_dir = text; }
    else if (arg == "--plugins") { if (!args.value(&options.plugin_dirs)) return false; }
    else if (arg == "--layouts") {
      if (!args.value(&text)) return false;
      options.layouts.clear();
      for (const auto& item : pfx::app::split_list(text)) {
        ObjLayout layout;
        if (!layout_from_name(item, &layout)) return args.fail("--layouts " + item + ": unknown layout (see --help)");
        options.layouts.push_back(layout);
      }
      if (options.layouts.empty()) return args.fail("--layouts needs at least one layout");
    } else if (arg == "--sizes") {
      if (!args.value(&text)) return false;
      options.sizes_mb.clear();
      for (const auto& item : pfx::app::split_list(text)) {
        char* end = nullptr;
        double mb = std::strtod(item.c_str(), &end);
        if (*end || !(mb >= 0.01 && mb <= 100000)) return args.fail("--sizes " + item + ": expected MB from 0.01 to 100000");
        options.sizes_mb.push_back(mb);
      }
      if (options.sizes_mb.empty()) return args.fail("--sizes needs at least one size");
    } else if (arg == "--threads") {
      if (!args.value(&text)) return false;
      options.threads.clear();
      for (const auto& item : pfx::app::split_list(text)) {
        char* end = nullptr;
        long n = std::strtol(item.c_str(), &end, 10);
        if (*end || n < 1 || n > 1024) return args.fail("--threads " + item + ": expected 1 to 1024");
        options.threads.push_back(static_cast<unsigned>(n));
      }
      if (options.threads.empty()) return args.fail("--threads needs at least one count");
    } else if (arg == "--loaders") {
      if (!args.value(&text)) return false;
      options.loaders = pfx::app::split_list(text);
      for (const auto& name : options.loaders)
        if (name != "pfx" && name != "tinyobjloader" && name != "assimp")
          return args.fail("--loaders " + name + ": expected pfx, tinyobjloader or assimp");
    } else if (arg == "--runs") {
      if (!args.value(&text)) return false;
      char* end = nullptr;
      long n = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end || n < 1 || n > 100) return args.fail("--runs " + text + ": expected 1 to 100");
      options.runs = static_cast<int>(n);
    } else {
      return args.fail("unknown option '" + arg + "' (see pfx-bench --import --help)");
    }
  }
  *out = options;
  return true;
}

int import_bench_main(const std::vector<std::string>& args) {
  ImportBenchOptions options;
  std::string message;
  if (!parse_import_bench_options(args, &options, &message)) {
    std::fprintf(stderr, "pfx-bench: %s\n\n%s", message.c_str(), import_bench_usage().c_str());
    return exit_code::kUsage;
  }
  if (options.help) {
    std::fputs(import_bench_usage().c_str(), stdout);
    return exit_code::kOk;
  }
  pfx::host::PluginRegistry registry([](const char*) { return pfx_gl_proc{nullptr}; },
                                     pfx::host::stderr_log_sink(PFX_LOG_WARNING), "pfx-bench");
  for (const auto& error : pfx::app::load_plugins(registry, options.plugin_dirs))
    std::fprintf(stderr, "pfx-bench: warning: %s\n", error.c_str());
  const std::vector<std::string> built = available_loaders();

  const bool temporary_dir = options.work_dir.empty();
  if (!make_work_dir(&options)) return exit_code::kInternal;
  std::vector<ImportRow> rows;
  int code = exit_code::kOk;
  if (!measure_files(options, built, &rows, &message)) {
    std::fprintf(stderr, "pfx-bench: %s\n", message.c_str());
    code = exit_code::kInternal;
  }
  std::error_code ec;
  if (temporary_dir && !options.keep_files) fs::remove_all(options.work_dir, ec);

  if (!write_reports(rows, options, &message)) {
    std::fprintf(stderr, "pfx-bench: %s\n", message.c_str());
    return exit_code::kInternal;
  }
  return code;
}

}  // namespace pfx::bench
