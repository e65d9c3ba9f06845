// pfx-import: loads a model file through the importer plugins and says what it got.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <pfx/host/import_result.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "exit_codes.hpp"
#include "import_options.hpp"
#include "import_report.hpp"
#include "plugin_directory.hpp"

using namespace pfx::exit_code;

namespace {

int error_exit(int code, const std::string& message) {
  std::fprintf(stderr, "pfx-import: %s\n", message.c_str());
  return code;
}

std::string importer_list(const pfx::host::PluginRegistry& registry) {
  std::string list;
  for (const auto& info : registry.importers())
    for (uint32_t i = 0; i < info.desc->extension_count; ++i)
      list += (list.empty() ? "" : ", ") + std::string(".") + info.desc->extensions[i];
  return list.empty() ? "none" : list;
}

// Rewrites one stderr line in place; whole percents only, so it prints at most 101 times.
void show_progress(void* user, float fraction) {
  int* last = static_cast<int*>(user);
  const int percent = static_cast<int>(fraction * 100.0f);
  if (percent == *last) return;
  *last = percent;
  std::fprintf(stderr, "\rpfx-import: %3d%%", percent);
  if (percent >= 100) std::fputc('\n', stderr);
  std::fflush(stderr);
}

}  // namespace

int main(int argc, char** argv) {
  pfx::import::ImportOptions options;
  std::string message;
  if (!pfx::import::parse_import_options(std::vector<std::string>(argv + 1, argv + argc), &options, &message)) {
    std::fprintf(stderr, "pfx-import: %s\n\n%s", message.c_str(), pfx::import::import_usage().c_str());
    return kUsage;
  }
  if (options.help) {
    std::fputs(pfx::import::import_usage().c_str(), stdout);
    return kOk;
  }
  std::error_code ec;
  if (!std::filesystem::exists(options.file, ec)) return error_exit(kBadInput, options.file + ": no such file");

  // Importers make no GL calls: the registry gets no GL loader.
  pfx::host::PluginRegistry registry([](const char*) { return pfx_gl_proc{nullptr}; },
                                     pfx::host::stderr_log_sink(PFX_LOG_WARNING), "pfx-import");
  for (const auto& error : pfx::app::load_plugins(registry, options.plugin_dirs))
    std::fprintf(stderr, "pfx-import: warning: %s\n", error.c_str());
  const pfx::host::ImporterInfo* importer = registry.find_importer_for_path(options.file);
  if (!importer)
    return error_exit(kEffectError, options.file + ": no importer for this file's extension (importers loaded for: " +
                                        importer_list(registry) + ")");

  pfx_import_request request{};
  request.struct_size = sizeof request;
  request.path = options.file.c_str();
  request.threads = options.threads;
  int last_percent = -1;
  if (options.progress == "on" || (options.progress == "auto" && ::isatty(STDERR_FILENO))) {
    request.progress = show_progress;
    request.progress_user = &last_percent;
  }
  const auto start = std::chrono::steady_clock::now();  // the call timed here, whatever the importer says
  const pfx::host::ImportResult result(*importer->desc, request);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result) return error_exit(kInternal, options.file + ": out of memory");
  int code = kOk;
  if (result->status == PFX_OK) {
    const std::string text = options.json ? pfx::import::summary_json(options.file, *result, seconds)
                                          : pfx::import::summary_text(options.file, *result, seconds);
    std::fputs(text.c_str(), stdout);
  } else {
    if (last_percent >= 0 && last_percent < 100) std::fputc('\n', stderr);
    code = result->status == PFX_ERROR ? kBadInput : result->status == PFX_OUT_OF_MEMORY ? kInternal : kEffectError;
    error_exit(code, result->error ? result->error : "import failed (status " + std::to_string(result->status) + ")");
  }
  return code;
}
