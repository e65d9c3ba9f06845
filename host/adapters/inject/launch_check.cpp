#include "launch_check.hpp"

#include <cstdio>
#include <filesystem>

#include <pfx/host/plugin_registry.hpp>

#include "app_launch.hpp"
#include "chain_recipe.hpp"
#include "plugin_directory.hpp"

namespace pfx::inject {
namespace {

const char* option_of(RecipeProblem::Source source) {
  switch (source) {
    case RecipeProblem::CHAIN: return "--chain";
    case RecipeProblem::PRESET: return "--preset";
    case RecipeProblem::SET: return "--set";
  }
  return "";
}

// A capture that could never be written: its folder is missing, or its frame is one the chain
// does not run on.
void check_capture(const Capture& capture, const InjectSettings& settings, std::vector<std::string>* errors) {
  const std::string name = "--capture " + (capture.every_frame ? "all" : std::to_string(capture.frame)) + ":" + capture.prefix;
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(capture.prefix).parent_path();
  std::error_code ec;
  if (!folder.empty() && !fs::is_directory(folder, ec))
    errors->push_back(name + ": the folder " + folder.string() + " does not exist");
  if (capture.every_frame) return;
  if (capture.frame < settings.from_frame)
    errors->push_back(name + ": frame " + std::to_string(capture.frame) + " comes before --from-frame " +
                      std::to_string(settings.from_frame) + ", which the chain leaves alone");
  if (settings.quit_after && capture.frame > settings.quit_after)
    errors->push_back(name + ": the application ends after frame " + std::to_string(settings.quit_after) +
                      " (--quit-after)");
}

}  // namespace

LaunchCheck check_launch(const InjectOptions& options) {
  LaunchCheck check;
  const InjectSettings& settings = options.settings;
  for (const auto& capture : settings.captures) check_capture(capture, settings, &check.errors);

  // Plugins' init is free of GL by contract: loading them here needs no context.
  auto no_gl = [](const char*) -> pfx_gl_proc { return nullptr; };
  auto sink = [&check](pfx_log_level level, const std::string& source, const std::string& message) {
    if (level >= PFX_LOG_WARNING) check.notes.push_back("[" + source + "] " + message);
  };
  host::PluginRegistry registry(no_gl, sink, "pfx-inject");
  const std::vector<std::string> folders = plugin_folders(settings);
  for (const auto& message : app::load_messages(registry, registry.load_search_path(folders))) check.notes.push_back(message);
  if (registry.effects().empty()) {
    std::string searched;
    for (const auto& folder : host::PluginRegistry::search_path(folders)) searched += (searched.empty() ? "" : ", ") + folder;
    check.errors.push_back("no effect plugins found (searched: " + (searched.empty() ? "no folder" : searched) +
                           "): give --plugins DIR");
    check.exit_code = exit_code::kInjectSetup;
    return check;
  }
  std::vector<RecipeProblem> problems;
  std::vector<std::string> notes;
  // A preset that does not read, and a --chain or --set that does not apply, are refused. What a
  // preset that reads holds that does not apply is left out by the library, which says so once
  // when it loads the preset in the application, as every host does.
  make_recipe(settings, registry, &problems, &notes);
  for (const auto& problem : problems) check.errors.push_back(std::string(option_of(problem.source)) + ": " + problem.message);
  for (const auto& note : notes) check.notes.push_back("--set " + note);
  if (!check.errors.empty()) check.exit_code = exit_code::kInjectUsage;
  return check;
}

}  // namespace pfx::inject
