#include "injector.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "frame_capture.hpp"
#include "plugin_directory.hpp"
#include "real_symbols.hpp"
#include "resource_report.hpp"

extern char** environ;

namespace pfx::inject {
namespace {

namespace fs = std::filesystem;

const char* lookup_environment(const char* name) { return std::getenv(name); }

// The plugin folder beside this library, for a user who preloads it by hand without
// PFX_INJECT_PLUGINS: build/plugins next to build/lib in a build tree, PREFIX/lib/pfx/plugins
// when installed (LIBDIR is PREFIX/lib or PREFIX/lib/<triplet>).
std::vector<std::string> plugin_dirs_beside_library() {
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void*>(&lookup_environment), &info) || !info.dli_fname) return {};
  const fs::path library_dir = fs::path(info.dli_fname).parent_path();
  std::error_code ec;
  for (const fs::path& candidate :
       {library_dir / ".." / "plugins", library_dir / "pfx" / "plugins", library_dir / ".." / "pfx" / "plugins"})
    if (fs::is_directory(candidate, ec)) return {fs::weakly_canonical(candidate, ec).string()};
  return {};
}

const char* variable_of(RecipeProblem::Source source) {
  switch (source) {
    case RecipeProblem::CHAIN: return env::kChain;
    case RecipeProblem::PRESET: return env::kPreset;
    case RecipeProblem::SET: return env::kSet;
  }
  return "";
}

std::string reach_text(const std::string& via) {
  return via == "linked" ? "linked directly" : "looked up with " + via;
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

}  // namespace

Injector& Injector::instance() {
  // Never destroyed: see the header.
  static Injector* const injector = new Injector();
  return *injector;
}

Injector::LoadedSettings Injector::load_settings() {
  LoadedSettings loaded;
  loaded.settings = settings_from_environment(lookup_environment, &loaded.problems);
  std::vector<std::string> names;
  for (char** entry = environ; *entry; ++entry) {
    const std::string variable = *entry;
    names.push_back(variable.substr(0, variable.find('=')));
  }
  for (auto& problem : unknown_variables(names)) loaded.problems.push_back(std::move(problem));
  return loaded;
}

Injector::Injector() : Injector(load_settings()) {}

Injector::Injector(LoadedSettings loaded)
    : settings_(std::move(loaded.settings)),
      log_(settings_.log_file),
      preset_watch_(settings_.preset),
      timings_(settings_.timings_file) {
  for (const auto& problem : loaded.problems) log_.line("ignored " + problem);
}

void Injector::before_present(const PresentCall& call) noexcept {
  try {
    std::lock_guard<std::mutex> lock(mutex_);
    if (++presented_ == 1) first_present_ = std::chrono::steady_clock::now();
    if (settings_.bypass) return;
    if (presented_ < settings_.from_frame) return say_captures_skipped("frames before --from-frame pass through");
    present(call);
  } catch (const std::exception& e) {
    log_.once(std::string("exception ") + e.what(), std::string("internal error: ") + e.what() +
                                                        "; frames pass through untouched from now on");
  } catch (...) {
    log_.once("exception", "internal error; frames pass through untouched from now on");
  }
}

void Injector::present(const PresentCall& call) {
  const std::string system = window_system_name(call.system);
  void* context = current_context(call.system);
  if (!context) {
    log_.once("no context " + system, "a present with no current " + system + " context: passed through");
    return say_captures_skipped("there was no current context");
  }
  if (!presents_current_surface(call)) {
    log_.once("other surface " + system,
              "a present of a surface the current context does not draw to: passed through");
    return say_captures_skipped("it presented a surface the current context does not draw to");
  }
  ContextEntry& entry = prepare_context_chain(call, context);
  if (!entry.pipeline) return say_captures_skipped("its context's frames pass through (" + entry.aside + ")");
  if (entry.recipe_generation != recipe_generation_) {
    std::vector<std::string> notes;
    std::string reason;
    const std::string frame = "frame " + std::to_string(presented_) + ": ";
    if (entry.pipeline->rebuild(recipe_, &notes, &reason)) log_.line(frame + "preset applied: chain " + entry.pipeline->chain_text());
    else log_.line(frame + "the changed preset could not be applied (" + reason + "); the previous chain keeps running");
    for (const auto& note : notes) log_.line(note);
    entry.recipe_generation = recipe_generation_;
  }
  FrameWork work;
  if (!surface_size(call, &work.width, &work.height)) {
    log_.once("no size " + system, "the size of a presented " + system + " surface is unknown: passed through");
    return say_captures_skipped("the size of its surface is unknown");
  }
  work.frame = presented_;
  work.time_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - first_present_).count();
  work.captures = capture_prefixes(settings_.captures, presented_);
  // The unit for --bench, once the JIT and caches are warm.
  work.measure_copy_pass = !settings_.stats_file.empty() && presented_ == 5;
  std::vector<std::string> messages;
  std::string reason;
  const bool ok = entry.pipeline->process(work, &messages, &reason);
  for (const auto& message : messages) log_.line(message);
  if (work.measure_copy_pass) copy_pass_ms_ = entry.pipeline->copy_pass_ms();
  if (ok && entry.pipeline->ran_passes() && !settings_.stats_file.empty()) stats_.ran_chain();
  if (!ok) {
    log_.line("frame " + std::to_string(presented_) + ": " + reason + "; this context's frames pass through untouched from now on");
    say_captures_skipped("the chain failed");
    entry.pipeline.reset();
    entry.aside = reason;
    return;
  }
  std::string error;
  if (!timings_.offer(presented_, entry.pipeline->chain_text(), entry.pipeline->report(), &error))
    log_.once("timings", "the pass times for the panel could not be written: " + error);
  for (uint64_t frame : settings_.resources_at)
    if (frame == presented_) log_.line("frame " + std::to_string(presented_) + ": " + resource_text(count_resources()));
}

void Injector::say_captures_skipped(const std::string& why) {
  for (const auto& skipped : skipped_captures(settings_.captures, presented_, why)) {
    if (skipped.once_key.empty()) log_.line(skipped.line);
    else log_.once(skipped.once_key, skipped.line);
  }
}

void Injector::reread_preset_if_changed() {
  if (!preset_watch_.changed()) return;
  // An edit that does not read (saved half-way, a typo in the JSON) keeps the chain that runs; in
  // one that reads, what does not apply is left out with one warning, as at the start. (What the
  // variables left out was said at the start.)
  std::vector<RecipeProblem> problems;
  std::vector<std::string> notes;
  ChainRecipe recipe = make_recipe(settings_, *registry_, &problems, &notes);
  std::string why;
  for (const auto& problem : problems)
    if (problem.source == RecipeProblem::PRESET) why += (why.empty() ? "" : "; ") + problem.message;
  if (!why.empty()) {
    log_.line("the changed preset could not be applied (" + why + "); the previous chain keeps running");
    return;
  }
  if (!recipe.left_out.empty()) log_.line("warning: " + recipe.left_out);
  for (const auto& note : notes) log_.line(note);
  recipe_ = std::move(recipe);
  ++recipe_generation_;
}

bool Injector::load_plugins(WindowSystem system) {
  if (registry_) return true;
  if (plugins_refused_) return false;
  plugins_refused_ = true;  // until it succeeds: one attempt, one message
  auto loader = [system](const char* name) { return reinterpret_cast<pfx_gl_proc>(gl_proc(system, name)); };
  auto sink = [this](pfx_log_level level, const std::string& source, const std::string& message) {
    if (level >= PFX_LOG_INFO) log_.line(std::string(host::log_level_name(level)) + ": [" + source + "] " + message);
  };
  auto registry = std::make_unique<host::PluginRegistry>(loader, sink, "pfx-inject");
  const std::vector<std::string> dirs = settings_.plugin_dirs.empty() ? plugin_dirs_beside_library() : settings_.plugin_dirs;
  for (const auto& message : app::load_messages(*registry, registry->load_search_path(dirs))) log_.line(message);
  if (registry->effects().empty()) {
    log_.line("no effect plugins found (searched: " + (dirs.empty() ? std::string("no folder") : join(dirs)) +
              ", and PFX_PLUGIN_PATH); frames pass through untouched");
    return false;
  }
  // Settings a user set by hand: what does not apply is named and left out, the rest runs.
  std::vector<RecipeProblem> problems;
  std::vector<std::string> notes;
  recipe_ = make_recipe(settings_, *registry, &problems, &notes);
  for (const auto& problem : problems) log_.line("ignored " + std::string(variable_of(problem.source)) + ": " + problem.message);
  if (!recipe_.left_out.empty()) log_.line("warning: " + recipe_.left_out);
  for (const auto& note : notes) log_.line(note);
  recipe_generation_ = 1;
  registry_ = std::move(registry);
  plugins_refused_ = false;
  return true;
}

Injector::ContextEntry& Injector::prepare_context_chain(const PresentCall& call, void* context) {
  const ContextKey key{call.system, context};
  auto found = contexts_.find(key);
  if (found != contexts_.end()) {
    if (found->second.pipeline) reread_preset_if_changed();
    return found->second;
  }
  ContextEntry& entry = contexts_[key];
  entry.number = ++contexts_seen_;
  const std::string system = window_system_name(call.system);
  const std::string name = system + " context " + std::to_string(entry.number);
  const std::string present_name = call.system == WindowSystem::GLX ? "glXSwapBuffers" : "eglSwapBuffers";
  const std::string hooked = "hooked " + present_name + " (" + reach_text(reached_through(present_name.c_str())) + ")";
  if (!load_plugins(call.system)) {
    entry.aside = "no effect plugins";
    return entry;
  }
  std::string reason;
  std::vector<std::string> notes;
  const std::string other_api = other_client_api(call.system);
  if (!other_api.empty()) reason = "an " + other_api + " context: pfx needs desktop OpenGL 4.5";
  else entry.pipeline = ContextPipeline::create(*registry_, settings_, recipe_, &notes, &reason);
  for (const auto& note : notes) log_.line(note);
  if (!entry.pipeline) {
    log_.line(hooked + " in " + name + ": " + reason + "; its frames pass through untouched");
    entry.aside = reason;
    return entry;
  }
  entry.recipe_generation = recipe_generation_;
  chain_text_ = entry.pipeline->chain_text();
  log_.line(hooked + " in " + name + "; chain: " + chain_text_ +
            (settings_.dry_run ? " (dry run: the application's own frames are presented)" : ""));
  return entry;
}

void Injector::after_present() noexcept {
  bool quitting = false;
  try {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!settings_.stats_file.empty()) stats_.presented();
    quitting = settings_.quit_after && presented_ >= settings_.quit_after;
    if (quitting) prepare_to_quit();
  } catch (...) {
    log_.once("exception after", "internal error after a present");
  }
  // Outside the lock: exit runs the application's atexit handlers, which may present or destroy
  // a context and so come back through our hooks.
  if (quitting) {
    std::fflush(nullptr);
    std::exit(0);
  }
}

void Injector::prepare_to_quit() {
  log_.line("quitting after " + std::to_string(presented_) + " presented frames, as asked");
  if (!settings_.stats_file.empty()) {
    std::string error;
    const std::string mode = settings_.bypass ? "application alone" : chain_text_;
    if (!stats_.write(settings_.stats_file, copy_pass_ms_, settings_.bypass ? "bypass" : "chain", mode, &error))
      log_.line("frame times not written: " + error);
  }
  // Free what the current context holds while it is current; other contexts' objects go with
  // the process.
  for (auto& [key, entry] : contexts_)
    if (entry.pipeline && current_context(key.first) == key.second) entry.pipeline.reset();
}

void Injector::context_destroyed(WindowSystem system, void* context) noexcept {
  try {
    std::lock_guard<std::mutex> lock(mutex_);
    auto found = contexts_.find({system, context});
    if (found == contexts_.end()) return;
    const std::string name = std::string(window_system_name(system)) + " context " + std::to_string(found->second.number);
    if (found->second.pipeline && current_context(system) != context) {
      orphans_.push_back(std::move(found->second.pipeline));
      log_.line(name + " destroyed while not current: its chain's GL objects went with it");
    } else if (found->second.pipeline) {
      log_.line(name + " destroyed: its chain freed");
    }
    contexts_.erase(found);  // a current context's pipeline frees its objects here
  } catch (...) {
    log_.once("exception destroy", "internal error while a context was destroyed");
  }
}

}  // namespace pfx::inject
