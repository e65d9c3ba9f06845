// Embeds libpfxhost the smallest way: a registry loads a plugin folder (the installed one unless
// told otherwise) and any plugin files named, then lists what it found. Loading needs no GL: a
// plugin's init may not touch it, so there is no context here and the loader returns nothing.
//
// usage: list_plugins [--dir DIR] [PLUGIN.so]...
// Exit 0 when every plugin loaded (zero plugins is fine: the folder may be empty), 1 otherwise.
#include <cstdio>
#include <string>
#include <vector>

#include <pfx/pfx.h>
#include <pfx/host/plugin_registry.hpp>

int main(int argc, char** argv) {
  std::string directory = PFX_INSTALLED_PLUGIN_DIR;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--dir" && i + 1 < argc) directory = argv[++i];
    else files.push_back(arg);
  }

  std::printf("pfx ABI %u.%u\n", PFX_ABI_MAJOR, PFX_ABI_MINOR);
  pfx::host::PluginRegistry registry([](const char*) -> pfx_gl_proc { return nullptr; },
                                     pfx::host::stderr_log_sink(PFX_LOG_WARNING), "list_plugins");
  std::vector<std::string> errors = registry.load_directory(directory);
  for (const auto& file : files) {
    std::string error;
    if (!registry.load(file, &error)) errors.push_back(error);
  }
  for (const auto& error : errors) std::fprintf(stderr, "list_plugins: %s\n", error.c_str());

  std::printf("%zu plugin(s) from %s%s\n", registry.plugins().size(), directory.c_str(),
              files.empty() ? "" : " and the files named");
  for (const auto& plugin : registry.plugins()) std::printf("plugin %s %s\n", plugin->id.c_str(), plugin->version.c_str());
  for (const auto& effect : registry.effects())
    std::printf("effect %s (%u parameters)\n", effect.desc->id, effect.desc->param_count);
  return errors.empty() ? 0 : 1;
}
