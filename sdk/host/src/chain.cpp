#include "pfx/host/chain.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

#include <pfx/cpp/identifier.hpp>

#include "chain_internal.hpp"

namespace pfx::host {
namespace {

const char* const kNoContext = "no OpenGL 4.5 context was current when the chain was made";

GLADapiproc load_through_registry(void* user, const char* name) {
  auto* registry = static_cast<const PluginRegistry*>(user);
  return reinterpret_cast<GLADapiproc>(registry->gl_loader()(name));
}

}  // namespace

Chain::Chain(const PluginRegistry& registry, ParamStore& params) : registry_(registry), params_(params) {
  // libpfxhost keeps a private GL function table, loaded through the embedding program's loader.
  // Without a current 4.5 context this fails; render() then refuses instead of crashing.
  gl_loaded_ = gladLoadGLUserPtr(load_through_registry, const_cast<PluginRegistry*>(&registry_)) != 0 &&
               GLAD_GL_VERSION_4_5;
  if (!gl_loaded_) return;
  gl_ = std::make_unique<GlResources>();
}

const GlLimits* Chain::gl_limits() const { return gl_ ? &gl_->limits : nullptr; }

void Chain::set_timing(Timing timing) {
  if (timing == timing_) return;
  timing_ = timing;
  if (gl_) gl_->timer.clear();
  times_ = FrameTimes{};
  last_timed_frame_ = 0;
  report_.times = times_;
}

bool Chain::wait_for_timings() {
  if (!gl_loaded_ || timing_ == Timing::OFF || last_timed_frame_ == 0) return false;
  if (timing_ == Timing::GPU_QUERIES && times_.frame != last_timed_frame_) {
    // A query buffer the engine left bound would receive the results instead of us.
    GLint query_buffer = 0;
    glGetIntegerv(GL_QUERY_BUFFER_BINDING, &query_buffer);
    glBindBuffer(GL_QUERY_BUFFER, 0);
    FrameTimes times;
    const bool waited = gl_->timer.wait_newest(&times);
    glBindBuffer(GL_QUERY_BUFFER, static_cast<GLuint>(query_buffer));
    if (waited) times_ = std::move(times);
  }
  report_.times = times_;
  if (times_.frame == report_.frame) report_.passes = times_.passes;
  return times_.frame == last_timed_frame_;
}

Chain::~Chain() {
  for (auto& instance : instances_) {
    instance->info.desc->destroy(instance->handle);
    params_.release_instance(instance->info.desc->id);
  }
  instances_.clear();
  gl_.reset();
}

namespace {

// Why `effect_id` names no effect when a plugin could not make effects of some of its source files
// (an FX file that does not compile): the files whose name the id holds (fx_brokentech from
// BrokenTech.fx), each with its first error; otherwise how many such files there are.
std::string failed_sources_hint(const PluginRegistry& registry, const std::string& effect_id) {
  std::string named;
  size_t failed = 0;
  for (const auto& plugin : registry.plugins())
    for (const std::string& message : plugin->source_errors) {
      ++failed;
      const std::string first_line = message.substr(0, message.find('\n'));
      size_t colon = 0;
      while ((colon = first_line.find(':', colon)) != std::string::npos &&
             !(colon + 1 < first_line.size() && std::isdigit(static_cast<unsigned char>(first_line[colon + 1]))))
        ++colon;
      std::string stem = first_line.substr(0, colon);
      stem = stem.substr(stem.find_last_of('/') == std::string::npos ? 0 : stem.find_last_of('/') + 1);
      stem = stem.substr(0, stem.rfind('.'));
      if (!stem.empty() && effect_id.find(pfx::identifier_from(stem)) != std::string::npos)
        named += (named.empty() ? "" : "; ") + first_line;
    }
  if (!named.empty()) return "; a file it may come from did not compile: " + named;
  if (failed) return "; " + std::to_string(failed) + " source file(s) gave no effect (--list names them)";
  return "";
}

}  // namespace

bool Chain::add(const std::string& effect_id, std::string* error) {
  if (!gl_loaded_) {
    if (error) *error = kNoContext;
    return false;
  }
  const EffectInfo* info = registry_.find_effect(effect_id);
  if (!info) {
    std::string known;
    for (const auto& effect : registry_.effects()) known += (known.empty() ? "" : ", ") + std::string(effect.desc->id);
    if (error)
      *error = "unknown effect '" + effect_id + "' (loaded: " + (known.empty() ? "none" : known) + ")" +
               failed_sources_hint(registry_, effect_id);
    return false;
  }
  void* handle = nullptr;
  pfx_status status = info->desc->create(info->plugin->host, &handle);
  if (status != PFX_OK || !handle) {
    if (error) *error = "effect '" + effect_id + "' could not be created (status " + std::to_string(status) + ")";
    return false;
  }
  if (!define_sources(*info, handle, source_definitions_, error)) {
    info->desc->destroy(handle);
    return false;
  }
  params_.hold_instance(info->desc);
  auto instance = std::make_unique<Instance>();
  instance->info = *info;
  instance->handle = handle;
  instances_.push_back(std::move(instance));
  renumber();
  plan_valid_ = false;
  return true;
}

bool Chain::define_sources(const EffectInfo& info, void* handle, const std::string& definitions,
                           std::string* error) const {
  const Plugin& plugin = *info.plugin;
  if (!plugin.set_definitions || !plugin.effect_sources.count(info.desc->id)) return true;
  const pfx_status status = plugin.set_definitions(handle, definitions.c_str());
  if (status == PFX_OK) return true;
  if (error)
    *error = "effect '" + std::string(info.desc->id) + "' refused the preprocessor definitions \"" + definitions +
             "\" (status " + std::to_string(status) + "; its plugin's log says why)";
  return false;
}

bool Chain::set_source_definitions(const std::string& definitions, std::string* error) {
  for (size_t i = 0; i < instances_.size(); ++i) {
    if (define_sources(instances_[i]->info, instances_[i]->handle, definitions, error)) continue;
    // Those before it took the list: they get the chain's own back (they took it before).
    for (size_t j = 0; j < i; ++j)
      define_sources(instances_[j]->info, instances_[j]->handle, source_definitions_, nullptr);
    return false;
  }
  source_definitions_ = definitions;
  return true;
}

void Chain::renumber() {
  for (size_t i = 0; i < instances_.size(); ++i) {
    Instance& instance = *instances_[i];
    instance.number = 1;
    for (size_t j = 0; j < i; ++j)
      if (std::strcmp(instances_[j]->info.desc->id, instance.info.desc->id) == 0) ++instance.number;
    instance.name = ParamStore::instance_name(instance.info.desc->id, instance.number);
  }
}

size_t Chain::size() const { return instances_.size(); }
std::string Chain::effect_id(size_t index) const { return instances_.at(index)->info.desc->id; }
size_t Chain::instance_number(size_t index) const { return instances_.at(index)->number; }
std::string Chain::instance_name(size_t index) const { return instances_.at(index)->name; }
void Chain::set_enabled(size_t index, bool enabled) {
  instances_.at(index)->enabled = enabled;
  plan_valid_ = false;
}
bool Chain::enabled(size_t index) const { return instances_.at(index)->enabled; }
void Chain::remove(size_t index) {
  const std::string id = instances_.at(index)->info.desc->id;
  const size_t number = instances_[index]->number;
  instances_[index]->info.desc->destroy(instances_[index]->handle);
  instances_.erase(instances_.begin() + static_cast<long>(index));
  renumber();
  params_.drop_instance(id, number);
  plan_valid_ = false;
}
void Chain::move(size_t from, size_t to) {
  auto instance = std::move(instances_.at(from));
  const size_t old_number = instance->number;
  Instance& moved = *instance;
  instances_.erase(instances_.begin() + static_cast<long>(from));
  instances_.insert(instances_.begin() + static_cast<long>(std::min(to, instances_.size())), std::move(instance));
  renumber();
  // Passing another instance of the same effect changes its number: its values go with it.
  if (moved.number != old_number) params_.move_instance(moved.info.desc->id, old_number, moved.number);
  plan_valid_ = false;
}

bool Chain::refresh(std::vector<std::string>* dropped, std::string* error) {
  struct Replacement {
    size_t index;
    EffectInfo info;
    void* handle;
  };
  std::vector<Replacement> replacements;
  std::vector<size_t> gone;
  for (size_t i = 0; i < instances_.size(); ++i) {
    const EffectInfo* now = registry_.find_effect(instances_[i]->info.desc->id);
    if (!now) {
      gone.push_back(i);
      continue;
    }
    if (now->desc == instances_[i]->info.desc && now->plugin == instances_[i]->info.plugin) continue;
    void* handle = nullptr;
    pfx_status status = now->desc->create(now->plugin->host, &handle);
    std::string refused;
    if (status == PFX_OK && handle && !define_sources(*now, handle, source_definitions_, &refused)) {
      now->desc->destroy(handle);
      handle = nullptr;
    }
    if (status != PFX_OK || !handle) {
      for (auto& made : replacements) made.info.desc->destroy(made.handle);
      if (error)
        *error = !refused.empty()
                     ? refused + " in the new version"
                     : "effect '" + std::string(now->desc->id) + "' of the new version could not be created (status " +
                           std::to_string(status) + ")";
      return false;
    }
    replacements.push_back({i, *now, handle});
  }
  for (auto& made : replacements) {
    Instance& instance = *instances_[made.index];
    instance.info.desc->destroy(instance.handle);
    instance.info = made.info;
    instance.handle = made.handle;
    instance.has_declaration = false;
  }
  for (auto it = gone.rbegin(); it != gone.rend(); ++it) {
    if (dropped) dropped->insert(dropped->begin(), instances_[*it]->info.desc->id);
    remove(*it);
  }
  if (!replacements.empty() || !gone.empty()) plan_valid_ = false;
  return true;
}

bool Chain::declare(const Instance& instance, const pfx_frame& frame, Declaration* out, std::string* error) const {
  const std::string& id = instance.name;
  pfx_declaration raw{};
  raw.struct_size = sizeof raw;
  pfx_status status = instance.info.desc->declare(instance.handle, &frame, instance.values(params_), &raw);
  if (status != PFX_OK) {
    *error = "effect '" + id + "': declare failed (status " + std::to_string(status) + ")";
    return false;
  }
  std::string message;
  if (!copy_declaration(raw, frame.width, frame.height, out, &message)) {
    *error = "effect '" + id + "': " + message;
    return false;
  }
  return true;
}

bool Chain::inputs_needed(size_t index, const pfx_frame& frame, uint32_t* inputs, std::string* error) const {
  Declaration declaration;
  if (!declare(*instances_.at(index), frame, &declaration, error)) return false;
  *inputs = declared_frame_inputs(declaration);
  return true;
}

bool Chain::plans_passes(const pfx_frame& frame, bool* passes, std::string* error) const {
  *passes = false;
  for (const auto& instance : instances_) {
    if (!instance->enabled) continue;
    Declaration declaration;
    if (!declare(*instance, frame, &declaration, error)) return false;
    if (!declaration.passes.empty()) {
      *passes = true;
      return true;
    }
  }
  return true;
}

bool Chain::declare_all(const pfx_frame& frame, std::vector<int>* active, std::string* error) {
  report_.effects_skipped.clear();
  report_.effects_run.clear();
  for (size_t i = 0; i < instances_.size(); ++i) {
    Instance& instance = *instances_[i];
    const std::string& id = instance.name;
    if (!instance.enabled) {
      report_.effects_skipped.push_back(id);
      continue;
    }
    // declare is cheap by contract, so it runs every frame; only a changed answer re-plans.
    Declaration declaration;
    if (!declare(instance, frame, &declaration, error)) return false;
    if (!instance.has_declaration || !(declaration == instance.declaration)) {
      instance.declaration = std::move(declaration);
      instance.has_declaration = true;
      plan_valid_ = false;
    }
    if (instance.declaration.passes.empty()) {
      report_.effects_skipped.push_back(id);
      continue;
    }
    active->push_back(static_cast<int>(i));
    report_.effects_run.push_back(id);
  }
  return true;
}

bool Chain::check_frame(const pfx_frame& frame, const FrameTextures& textures, const HostOutput& output,
                        std::string* error) const {
  const char* problem = nullptr;
  if (!gl_loaded_) problem = kNoContext;
  else if (frame.struct_size < PFX_FRAME_MIN_SIZE) problem = "pfx_frame struct too small";
  else if (frame.width < 1 || frame.height < 1) problem = "frame size must be at least 1x1";
  else if (!textures.color || !(frame.inputs & PFX_INPUT_COLOR)) problem = "the frame has no colour input";
  else if (!output.to_framebuffer && (!output.texture || output.texture == textures.color))
    problem = "the output must be its own texture";
  else if (output.to_framebuffer && glCheckNamedFramebufferStatus(output.framebuffer, GL_DRAW_FRAMEBUFFER) !=
                                        GL_FRAMEBUFFER_COMPLETE)
    problem = "the output framebuffer is not complete";
  else if (output.to_framebuffer && output.srgb && !framebuffer_draws_srgb(output.framebuffer))
    problem = "the output framebuffer holds sRGB codes but its draw buffer is not sRGB-capable";
  if (problem) *error = problem;
  return !problem;
}

bool Chain::update_plan(const pfx_frame& frame, const std::vector<int>& active, std::string* error) {
  if (plan_valid_ && active == planned_active_) return true;
  std::vector<PlanInput> inputs;
  for (int index : active) inputs.push_back({instances_[index]->name, &instances_[index]->declaration});
  FramePlan plan;
  if (!plan_frame(inputs, frame.width, frame.height, frame.inputs, &plan, error)) return false;
  plan_ = std::move(plan);
  planned_active_ = active;
  plan_valid_ = true;
  gl_->pool.match(plan_.slots);
  return true;
}

bool Chain::render(const pfx_frame& frame, const FrameTextures& textures, uint32_t output_texture,
                   std::string* error) {
  HostOutput output;
  output.texture = output_texture;
  return render_into(frame, textures, output, error);
}

bool Chain::render(const pfx_frame& frame, const FrameTextures& textures, const FramebufferOutput& framebuffer,
                   std::string* error) {
  HostOutput output;
  output.to_framebuffer = true;
  output.framebuffer = framebuffer.framebuffer;
  output.srgb = framebuffer.srgb;
  return render_into(frame, textures, output, error);
}

bool Chain::render_into(const pfx_frame& frame, const FrameTextures& textures, const HostOutput& output,
                        std::string* error) {
  report_.frame = ++frames_;
  std::string message;
  std::vector<int> active;
  if (!check_frame(frame, textures, output, &message) || !declare_all(frame, &active, &message) ||
      !update_plan(frame, active, &message)) {
    if (error) *error = message;
    return false;
  }
  FrameResources resources{frame, textures, output, plan_, gl_->pool};
  const bool ran = execute(resources, active, error);
  report_.peak_target_bytes = plan_.peak_target_bytes + gl_->conversion.bytes();
  report_.unpooled_target_bytes = plan_.unpooled_target_bytes + gl_->conversion.bytes();
  return ran;
}

}  // namespace pfx::host
