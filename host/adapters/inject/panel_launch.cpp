#include "panel_launch.hpp"

#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <pfx/host/param_store.hpp>

#include "app_launch.hpp"
#include "chain_recipe.hpp"
#include "plugin_directory.hpp"

extern char** environ;

namespace pfx::inject {

bool prepare_panel(InjectOptions* options, PanelSession* session, std::string* error) {
  InjectSettings& settings = options->settings;
  std::string folder = (std::filesystem::temp_directory_path() / "pfx-inject-panel-XXXXXX").string();
  if (!mkdtemp(folder.data())) {
    *error = "cannot make a folder for the panel's session: " + std::string(std::strerror(errno));
    return false;
  }
  session->folder = folder;
  session->preset = folder + "/session.json";
  session->timings = folder + "/timings.json";
  session->user_preset = settings.preset.empty() ? "pfx-preset.json" : settings.preset;

  // The look the application starts with, as the library would make it, written out whole: the
  // chain (unless nobody chose one: the library then leaves out what the application cannot
  // feed) and every value at the display-referred defaults, the preset's and --set on top.
  auto no_gl = [](const char*) -> pfx_gl_proc { return nullptr; };
  host::PluginRegistry registry(no_gl, [](pfx_log_level, const std::string&, const std::string&) {}, "pfx-inject");
  registry.load_search_path(plugin_folders(settings));
  std::vector<RecipeProblem> problems;
  std::vector<std::string> notes;
  const ChainRecipe recipe = make_recipe(settings, registry, &problems, &notes);
  host::ParamStore store = store_for(recipe.effects, registry);
  if (!recipe.parameters_json.empty() && !store.from_json(recipe.parameters_json, error)) return false;
  for (const auto& assignment : recipe.sets)
    if (!store.set_assignment(assignment, error)) return false;
  app::Preset preset;
  if (recipe.chosen) preset.chain = recipe.effects;
  preset.parameters_json = store.to_json();
  if (!app::write_preset(session->preset, preset, error)) return false;

  settings.preset = session->preset;
  settings.chain.reset();
  settings.sets.clear();
  settings.timings_file = session->timings;
  return true;
}

bool start_panel(const InjectOptions& options, PanelSession* session, std::string* error) {
  const std::string viewer = app::executable_directory() + "/pfx-view";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(viewer, ec)) {
    *error = "--panel needs pfx-view beside pfx-inject: " + viewer + " is missing";
    return false;
  }
  std::vector<std::string> args = {viewer, "--attach", session->preset, "--timings", session->timings, "--preset",
                                   session->user_preset};
  for (const auto& folder : plugin_folders(options.settings)) args.insert(args.end(), {"--plugins", folder});
  args.insert(args.end(), options.panel_options.begin(), options.panel_options.end());
  // The panel is our program, not the application: nothing preloaded into it.
  std::vector<std::string> environment;
  for (char** entry = environ; *entry; ++entry)
    if (std::strncmp(*entry, "LD_PRELOAD=", 11) != 0) environment.push_back(*entry);
  std::vector<char*> argv, envp;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  for (auto& variable : environment) envp.push_back(variable.data());
  envp.push_back(nullptr);
  const pid_t child = fork();
  if (child < 0) {
    *error = std::string("fork: ") + std::strerror(errno);
    return false;
  }
  if (child == 0) {
    execve(argv[0], argv.data(), envp.data());
    _exit(exit_code::kInjectNotStarted);
  }
  session->pid = child;
  return true;
}

void end_panel(PanelSession* session) {
  if (session->pid > 0) {
    kill(session->pid, SIGTERM);
    int status = 0;
    while (waitpid(session->pid, &status, 0) < 0 && errno == EINTR) {
    }
    session->pid = -1;
  }
  std::error_code ec;
  if (!session->folder.empty()) std::filesystem::remove_all(session->folder, ec);
}

}  // namespace pfx::inject
