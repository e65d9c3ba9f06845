// pfx-frei0r-effects: a build tool beside the frei0r plugins. It loads the pfx plugins, makes a
// headless GL context, and finds the effects that need nothing but colour (colour_only.hpp):
//   --list                 each effect and what it needs
//   --markdown             their parameter tables, as docs/hosts.md has them
//   --copies LIBRARY DIR   DIR/pfx_<effect>.so, a copy of LIBRARY (pfx_chain.so), for each of them;
//                          copies left from effects no longer there are removed
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "colour_only.hpp"
#include "exit_codes.hpp"
#include "frei0r_tables.hpp"
#include "headless_context.hpp"
#include "plugin_directory.hpp"

namespace fs = std::filesystem;

namespace {

int usage() {
  std::fputs("usage: pfx-frei0r-effects [--plugins DIR]... (--list | --markdown | --copies LIBRARY DIR)\n", stderr);
  return pfx::exit_code::kUsage;
}

// Each copy is written under a temporary name and renamed: a host scanning the folder meanwhile
// never opens half a library.
bool make_copies(const std::vector<std::string>& ids, const fs::path& library, const fs::path& folder) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("pfx_", 0) != 0 || entry.path().extension() != ".so" || name == library.filename().string()) continue;
    bool wanted = false;
    for (const auto& id : ids) wanted |= name == "pfx_" + id + ".so";
    if (!wanted) fs::remove(entry.path(), ec);
  }
  for (const auto& id : ids) {
    const fs::path target = folder / ("pfx_" + id + ".so"), temporary = folder / (".pfx_" + id + ".so.tmp");
    if (!fs::copy_file(library, temporary, fs::copy_options::overwrite_existing, ec)) {
      std::fprintf(stderr, "pfx-frei0r-effects: cannot copy %s to %s: %s\n", library.c_str(), temporary.c_str(),
                   ec.message().c_str());
      return false;
    }
    fs::rename(temporary, target, ec);
    if (ec) {
      std::fprintf(stderr, "pfx-frei0r-effects: cannot write %s: %s\n", target.c_str(), ec.message().c_str());
      return false;
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> folders;
  std::string mode, library, destination;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--plugins" && i + 1 < argc) folders.push_back(argv[++i]);
    else if (arg == "--list" || arg == "--markdown") mode = arg;
    else if (arg == "--copies" && i + 2 < argc) {
      mode = arg;
      library = argv[++i];
      destination = argv[++i];
    } else return usage();
  }
  if (mode.empty()) return usage();
  std::string error;
  auto context = pfx::app::HeadlessContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "pfx-frei0r-effects: %s (the effects are told apart by running them)\n", error.c_str());
    return pfx::exit_code::kInternal;
  }
  pfx::host::PluginRegistry registry(
      [](const char* name) { return pfx::app::HeadlessContext::get_proc_address(nullptr, name); },
      pfx::host::stderr_log_sink(PFX_LOG_WARNING), "pfx-frei0r-effects");
  for (const auto& message : pfx::app::load_plugins(registry, folders))
    std::fprintf(stderr, "pfx-frei0r-effects: warning: %s\n", message.c_str());
  std::vector<std::string> colour_only;
  std::string tables;
  for (const auto& effect : pfx::adapters::classify_effects(registry)) {
    if (mode == "--list") {
      std::string needs;
      for (const auto& need : effect.needs) needs += (needs.empty() ? "" : ", ") + need;
      std::printf("%s: %s\n", effect.id.c_str(),
                  !effect.error.empty() ? ("not told: " + effect.error).c_str()
                  : effect.colour_only  ? "colour only (a frei0r plugin of its own)"
                                        : ("needs " + needs).c_str());
    }
    if (!effect.colour_only) continue;
    colour_only.push_back(effect.id);
    if (!tables.empty()) tables += "\n";
    tables += pfx::frei0r::markdown_table(*registry.find_effect(effect.id)->desc);
  }
  if (mode == "--markdown") std::fputs(tables.c_str(), stdout);
  if (mode == "--copies" && !make_copies(colour_only, library, destination)) return pfx::exit_code::kInternal;
  return pfx::exit_code::kOk;
}
