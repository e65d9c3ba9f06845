#include "viewer_session.hpp"

#include "input_image.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>

#include <pfx/host/hot_reload.hpp>

#include "camera_settings.hpp"
#include "chain_builder.hpp"
#include "default_chain.hpp"
#include "exit_codes.hpp"
#include "exr_io.hpp"
#include "frame_files.hpp"
#include "display_transfer.hpp"
#include "image_texture.hpp"
#include "plugin_directory.hpp"
#include "png_io.hpp"
#include "timing_choice.hpp"

namespace pfx::app {
namespace {

constexpr size_t kMaxMessages = 100;
constexpr double kPollInterval = 0.1;  // seconds between plugin file checks

// Order-dependent mixing of the numbers that make up the state stamp.
void mix(uint64_t* h, uint64_t value) { *h = (*h ^ value) * 1099511628211ull; }
void mix(uint64_t* h, double value) { mix(h, std::hash<double>{}(value)); }

}  // namespace

std::unique_ptr<ViewerSession> ViewerSession::create(const ViewOptions& options, const std::string& renderer,
                                                     pfx::host::GlProcLoader gl_loader, std::string* error,
                                                     int* exit_code) {
  auto fail = [&](int code, const std::string& message) -> std::unique_ptr<ViewerSession> {
    *exit_code = code;
    *error = message;
    return nullptr;
  };
  std::unique_ptr<ViewerSession> self(new ViewerSession);
  ViewerSession* session = self.get();
  self->renderer_ = renderer;
  self->verbose_ = options.verbose;
  // Plugin messages go to stderr as usual; warnings and errors are also shown in the window.
  auto to_stderr = pfx::host::stderr_log_sink(options.verbose ? PFX_LOG_DEBUG : PFX_LOG_INFO);
  auto sink = [session, to_stderr](pfx_log_level level, const std::string& source, const std::string& message) {
    to_stderr(level, source, message);
    if (level >= PFX_LOG_WARNING) session->remember({level >= PFX_LOG_ERROR, "[" + source + "] " + message});
  };
  self->registry_ = std::make_unique<pfx::host::PluginRegistry>(std::move(gl_loader), sink, "pfx-view " PFX_VERSION);
  for (const auto& message : load_plugins(*self->registry_, options.plugin_dirs))
    self->warning(message);
  // Attached to an application's chain, values start where the injected library starts them: at
  // the defaults for its display-referred frames; so do they for an 8-bit picture, as in pfx-render.
  const bool png_input = options.input == ViewInput::Image && is_display_input(options.input_path);
  if (!options.attach.empty() || png_input) self->params_ = pfx::host::ParamStore(pfx::host::DefaultSet::DISPLAY_REFERRED);
  for (const auto& effect : self->registry_->effects()) self->params_.add_effect(effect.desc);

  Preset preset;
  std::string message;
  const std::string& start = options.attach.empty() ? options.preset : options.attach;
  if (!start.empty() && !read_preset(start, &preset, &message)) return fail(exit_code::kBadInput, message);
  // The preset policy every host shares (chain_builder.hpp): what is not loaded or does not fit
  // is named in one warning, and the rest runs.
  const std::vector<std::string> unloaded =
      options.chain_given ? std::vector<std::string>{} : drop_unloaded_effects(preset, *self->registry_);

  self->chain_ = std::make_unique<pfx::host::Chain>(*self->registry_, self->params_);
  self->chain_->set_timing(default_timing(renderer));
  std::vector<PresetEffect> effects;
  if (options.chain_given || !preset.chain)
    for (const auto& id : options.chain_given ? options.chain : default_chain(*self->registry_)) effects.push_back({id, true});
  else
    effects = *preset.chain;
  if (!self->build_chain(effects, &message)) return fail(exit_code::kEffectError, message);
  if (!self->chain_->set_source_definitions(preset.source_definitions, &message))
    return fail(exit_code::kBadInput, start + ": PreprocessorDefinitions: " + message);

  // Values after the chain: "bloom#2" exists once the chain holds a second bloom.
  const std::string warning = preset_left_out_warning(start, unloaded, apply_preset_values(self->params_, preset));
  if (!warning.empty()) self->warning(warning);
  for (const auto& note : preset.notes) self->info(start + ": " + note);
  for (const auto& assignment : options.sets) {
    std::string note;
    if (!self->params_.set_assignment(assignment, &message, &note)) return fail(exit_code::kUsage, "--set " + message);
    if (!note.empty()) self->info("--set " + assignment + ": " + note);
  }

  self->preset_path_ = !options.save_preset.empty() ? options.save_preset
                       : preset.from_reshade         ? options.preset + ".pfx.json"  // never written over a ReShade preset
                       : !options.preset.empty()     ? options.preset
                                                     : "pfx-preset.json";
  if (options.attach.empty()) {
    self->watched_preset_ = options.preset;
    self->preset_watch_.changed({options.preset});  // its stamp as read now
  }
  self->shots_dir_ = options.shots_dir;
  self->set_watching(options.watch);
  if (!options.attach.empty()) return self;  // no picture of its own

  bool bad_input = false;
  self->source_ = FrameSource::create(options, *self->registry_, &message, &bad_input);
  if (!self->source_) return fail(bad_input ? exit_code::kBadInput : exit_code::kInternal, message);
  for (const auto& warning : self->source_->warnings()) self->warning(warning);
  Camera& camera = self->source_->camera();
  const Camera place = camera;
  apply_preset_camera(preset.camera, &camera);
  apply_camera_keys(options.camera, options.camera_keys, &camera);
  if (!self->source_->has_scene()) camera.position = place.position, camera.target = place.target, camera.up = place.up;
  if (!(camera.far_plane > camera.near_plane)) return fail(exit_code::kUsage, "camera: far must be greater than near");

  self->tone_ = options.tone;
  if (preset.exposure_ev && !options.exposure_given) self->tone_.exposure_ev = *preset.exposure_ev;
  if (preset.tone && !options.tone_given) self->tone_.curve = *preset.tone;
  return self;
}

ViewerSession::~ViewerSession() {
  // GL objects before the chain and the registry (the context is still current).
  output_.reset();
  source_.reset();
  chain_.reset();
}

bool ViewerSession::build_chain(const std::vector<PresetEffect>& effects, std::string* error) {
  while (chain_->size() > 0) chain_->remove(chain_->size() - 1);
  for (const auto& effect : effects) {
    if (!chain_->add(effect.id, error)) return false;
    chain_->set_enabled(chain_->size() - 1, effect.enabled);
  }
  return true;
}

uint64_t ViewerSession::state_stamp(int width, int height) const {
  uint64_t h = 1469598103934665603ull;
  mix(&h, uint64_t(width));
  mix(&h, uint64_t(height));
  mix(&h, reload_count_);
  mix(&h, source_frames_);
  mix(&h, uint64_t(chain_->size()));
  for (size_t i = 0; i < chain_->size(); ++i) {
    mix(&h, std::hash<std::string>{}(chain_->effect_id(i)));
    mix(&h, uint64_t(chain_->enabled(i)));
    mix(&h, params_.revision(chain_->instance_name(i)));
  }
  if (!source_) return h;
  const Camera& c = source_->camera();
  for (double v : {c.position.x, c.position.y, c.position.z, c.target.x, c.target.y, c.target.z, c.up.x, c.up.y,
                   c.up.z, c.fovy_radians, c.near_plane, c.far_plane})
    mix(&h, v);
  return h;
}

bool ViewerSession::render(int width, int height, double time_seconds, bool force_scene) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  source_->prepare(width, height, force_scene);
  const int w = source_->width(), h = source_->height();
  output_->resize(w, h, source_->display_referred());
  // Into the target, shown on success: a failing frame leaves the last good one shown.
  std::string message;
  bool ok = chain_->render(source_->frame(time_seconds, frame_index_++), source_->textures(), output_->target(), &message);
  last_render_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  if (!ok) {
    if (message != render_error_) error("frame failed: " + message);
    render_error_ = message;
    return false;
  }
  output_->swap();
  log_plan_and_reports();
  render_error_.clear();
  return true;
}

void ViewerSession::set_watching(bool on) {
  watching_ = on;
  if (!on) return;
  // Start from the files as they are now: a change made while not watching is not a rebuild.
  for (const auto& plugin : registry_->plugins()) watcher_.watch(plugin->id, plugin->path);
}

std::vector<std::string> ViewerSession::chain_source_files() const {
  std::vector<std::string> files;
  for (size_t i = 0; i < chain_->size(); ++i) {
    const pfx::host::EffectInfo* info = registry_->find_effect(chain_->effect_id(i));
    if (!info) continue;
    const auto source = info->plugin->effect_sources.find(chain_->effect_id(i));
    if (source != info->plugin->effect_sources.end()) files.push_back(source->second.file);
  }
  return files;
}

void ViewerSession::poll_plugins(double now_seconds) {
  if (now_seconds - last_source_look_ >= kPollInterval) {
    last_source_look_ = now_seconds;
    // Two frames: the effect may have looked at its files just before the edit, and looks again
    // only after its own short interval.
    if (sources_.changed(chain_source_files())) source_frames_owed_ = 2;
    if (source_frames_owed_ > 0) --source_frames_owed_, ++source_frames_;
    if (!watched_preset_.empty() && preset_watch_.changed({watched_preset_})) load_preset(watched_preset_);
  }
  if (!watching_ || now_seconds - last_poll_ < kPollInterval) return;
  last_poll_ = now_seconds;
  for (const auto& id : watcher_.poll(now_seconds)) {
    pfx::host::ReloadResult result;
    std::string message;
    const std::string path = registry_->find_plugin(id)->path;
    const auto started = std::chrono::steady_clock::now();
    if (!pfx::host::reload_plugin(*registry_, params_, *chain_, id, &result, &message)) {
      error("reload failed: " + message + "; the previous version keeps running");
      continue;
    }
    ++reload_count_;
    // The time the reload itself took (loading, creating the effects, compiling their shaders),
    // apart from the wait for the file to settle: a slow plugin shows which of the two it is.
    char took[32];
    std::snprintf(took, sizeof took, " in %.2f s",
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    std::string text = "reloaded " + id + " " + result.old_version + " -> " + result.new_version + " from " + path +
                       took + " (parameter values kept)";
    for (const auto& dropped : result.effects_dropped) text += "; effect '" + dropped + "' is gone and left the chain";
    info(text);
  }
}

Preset ViewerSession::current_preset() const {
  Preset preset;
  preset.chain.emplace();
  for (size_t i = 0; i < chain_->size(); ++i) preset.chain->push_back({chain_->effect_id(i), chain_->enabled(i)});
  preset.parameters_json = params_.to_json();
  preset.source_definitions = chain_->source_definitions();
  if (!source_) return preset;  // attached: the chain and its values are the whole look
  const Camera& camera = source_->camera();
  preset.camera = preset_camera_of(camera);
  if (!source_->has_scene()) preset.camera.position.reset(), preset.camera.target.reset(), preset.camera.up.reset();
  preset.exposure_ev = tone_.exposure_ev;
  preset.tone = tone_.curve;
  return preset;
}

bool ViewerSession::apply_preset(const Preset& given, const std::string& path, std::string* error, std::string* left_out) {
  Preset preset = given;
  const std::vector<std::string> unloaded = drop_unloaded_effects(preset, *registry_);
  // The values are checked against a store shaped like the preset's chain ("bloom#2" needs a
  // second bloom) before anything changes.
  pfx::host::ParamStore values = params_;
  std::map<std::string, size_t> counts;
  if (preset.chain)
    for (const auto& effect : *preset.chain) ++counts[effect.id];
  for (const auto& effect : registry_->effects()) {
    // An effect that came with a reloaded plugin is not in the store until the chain adds it.
    if (!values.has_effect(effect.desc->id)) values.add_effect(effect.desc);
    if (preset.chain) values.set_instance_count(effect.desc->id, std::max<size_t>(1, counts[effect.desc->id]));
  }
  *left_out = preset_left_out_warning(path, unloaded, apply_preset_values(values, preset));
  Camera camera;
  if (source_) {
    camera = source_->camera();
    apply_preset_camera(preset.camera, &camera);
    if (!source_->has_scene()) camera.position = source_->camera().position, camera.target = source_->camera().target, camera.up = source_->camera().up;
    if (!(camera.far_plane > camera.near_plane)) {
      *error = "camera: far must be greater than near";
      return false;
    }
  }
  // The definitions are checked by the instances there are (a refused list changes nothing), and
  // those the chain adds next get them.
  if (!chain_->set_source_definitions(preset.source_definitions, error)) {
    *error = "PreprocessorDefinitions: " + *error;
    return false;
  }
  // The chain first: rebuilding it drops the values of instances it removes, which the new ones
  // then get from `values` (shaped alike, so the chain and the store agree).
  if (preset.chain && !build_chain(*preset.chain, error)) return false;
  params_ = values;
  if (source_) source_->camera() = camera;
  if (preset.exposure_ev) tone_.exposure_ev = *preset.exposure_ev;
  if (preset.tone) tone_.curve = *preset.tone;
  return true;
}

void ViewerSession::save_preset() {
  std::string message;
  if (write_preset(preset_path_, current_preset(), &message)) info("saved preset " + preset_path_);
  else error(message);
  // The viewer's own save is no edit to apply again.
  if (preset_path_ == watched_preset_) preset_watch_.changed({watched_preset_});
}

void ViewerSession::load_preset(const std::string& path) {
  Preset preset;
  std::string message;
  if (!read_preset(path, &preset, &message)) return error(message + "; the look shown stays");
  std::string left_out;
  if (!apply_preset(preset, path, &message, &left_out)) return error(path + ": " + message + "; the look shown stays");
  info("loaded preset " + path);
  if (!left_out.empty()) warning(left_out);
}

bool ViewerSession::write_frame(const std::string& png_path, std::string* error) {
  if (!output_->has_frame()) {
    *error = "no frame has been rendered yet";
    return false;
  }
  // An 8-bit picture's result is written as pfx-render writes it from the same PNG: its codes,
  // with the file's channels, not tone-mapped; the EXR beside it holds them decoded.
  if (output_->codes())
    return write_png(png_path, output_->encoded(source_->channels()), error) &&
           write_exr(exr_beside(png_path), output_->linear(), ExrPixelType::Half, error);
  return write_frame_pair(output_->linear(), png_path, tone_, error);
}

void ViewerSession::log_plan_and_reports() {
  // With -v, the passes of each new plan and each effect's report when it changes, so where a
  // frame's work goes (that an all-FX chain over an 8-bit picture converts nothing, when FX
  // programs hold values as constants) can be read without the window.
  if (!verbose_) return;
  const pfx::host::FrameReport& report = chain_->report();
  std::string passes;
  for (const auto& pass : report.passes) passes += (passes.empty() ? "" : ", ") + pass.effect + "/" + pass.pass;
  if (passes != logged_passes_) info("passes: " + passes);
  logged_passes_ = passes;
  for (const auto& [instance, figures] : report.effect_reports) {
    std::string& logged = logged_reports_[instance];
    if (figures != logged) info("report of " + instance + ": " + figures);
    logged = figures;
  }
}

void ViewerSession::apply_edits(const std::vector<ViewOptions::Edit>& edits, long long frame) {
  for (const auto& edit : edits) {
    if (edit.frame != frame) continue;
    std::string message;
    if (params_.set_assignment(edit.assignment, &message)) info("edited " + edit.assignment);
    else error("--edit " + message);
  }
}

void ViewerSession::take_screenshot() {
  const std::string base = next_screenshot_base(shots_dir_);
  std::string message;
  if (!write_frame(base + ".png", &message) || !write_preset(base + ".json", current_preset(), &message))
    return error("screenshot failed: " + message);
  info("screenshot " + base + ".png, .exr and .json (the preset)");
}

void ViewerSession::info(const std::string& text) {
  std::printf("pfx-view: %s\n", text.c_str());
  std::fflush(stdout);
  remember({false, text});
}

void ViewerSession::warning(const std::string& text) {
  std::fprintf(stderr, "pfx-view: warning: %s\n", text.c_str());
  remember({true, text});
}

void ViewerSession::error(const std::string& text) {
  std::fprintf(stderr, "pfx-view: error: %s\n", text.c_str());
  remember({true, text});
}

void ViewerSession::remember(Message message) {
  messages_.push_back(std::move(message));
  if (messages_.size() > kMaxMessages) messages_.pop_front();
}

}  // namespace pfx::app
