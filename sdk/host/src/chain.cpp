#include "pfx/host/chain.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

#include <glad/gl.h>

#include "gl_pool.hpp"
#include "gl_state_scope.hpp"
#include "gpu_timer.hpp"

namespace pfx::host {

struct Chain::Instance {
  // Copied, not a pointer into the registry's index, which a load or reload rebuilds.
  EffectInfo info;
  void* handle = nullptr;
  bool enabled = true;
  Declaration declaration;
  bool has_declaration = false;
  // Which instance of its effect this is (from 1, in chain order) and its name, "bloom#2".
  size_t number = 1;
  std::string name;
};

struct Chain::GlResources {
  GlPool pool;
  GlLimits limits = GlLimits::query();
  GpuTimer timer;
};

namespace {

GLADapiproc load_through_registry(void* user, const char* name) {
  auto* registry = static_cast<const PluginRegistry*>(user);
  return reinterpret_cast<GLADapiproc>(registry->gl_loader()(name));
}

std::string gl_error_text(GLenum error) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "0x%04x", error);
  return buffer;
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
  for (auto& instance : instances_) instance->info.desc->destroy(instance->handle);
  instances_.clear();
  gl_.reset();
}

bool Chain::add(const std::string& effect_id, std::string* error) {
  if (!gl_loaded_) {
    if (error) *error = "no OpenGL 4.5 context was current when the chain was made";
    return false;
  }
  const EffectInfo* info = registry_.find_effect(effect_id);
  if (!info) {
    std::string known;
    for (const auto& effect : registry_.effects()) known += (known.empty() ? "" : ", ") + std::string(effect.desc->id);
    if (error) *error = "unknown effect '" + effect_id + "' (loaded: " + (known.empty() ? "none" : known) + ")";
    return false;
  }
  void* handle = nullptr;
  pfx_status status = info->desc->create(info->plugin->host, &handle);
  if (status != PFX_OK || !handle) {
    if (error) *error = "effect '" + effect_id + "' could not be created (status " + std::to_string(status) + ")";
    return false;
  }
  if (!params_.has_effect(effect_id)) params_.add_effect(info->desc);
  auto instance = std::make_unique<Instance>();
  instance->info = *info;
  instance->handle = handle;
  instances_.push_back(std::move(instance));
  renumber();
  const size_t number = instances_.back()->number;
  if (params_.instance_count(effect_id) < number) params_.set_instance_count(effect_id, number);
  plan_valid_ = false;
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
  params_.remove_instance(id, number);
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
    if (status != PFX_OK || !handle) {
      for (auto& made : replacements) made.info.desc->destroy(made.handle);
      if (error)
        *error = "effect '" + std::string(now->desc->id) + "' of the new version could not be created (status " +
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
  const pfx_value* values = params_.values(instance.info.desc->id, instance.number);
  if (!values) {
    // The store was changed behind the chain (set_instance_count, remove_effect, assignment).
    *error = "effect '" + id + "': the parameter store has no values for it";
    return false;
  }
  pfx_status status = instance.info.desc->declare(instance.handle, &frame, values, &raw);
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

bool Chain::render(const pfx_frame& frame, const FrameTextures& textures, uint32_t output_texture,
                   std::string* error) {
  std::string message;
  auto fail = [&](const std::string& text) {
    if (error) *error = text;
    return false;
  };
  report_.frame = ++frames_;
  if (!gl_loaded_) return fail("no OpenGL 4.5 context was current when the chain was made");
  if (frame.struct_size < PFX_FRAME_MIN_SIZE) return fail("pfx_frame struct too small");
  if (frame.width < 1 || frame.height < 1) return fail("frame size must be at least 1x1");
  if (!textures.color || !(frame.inputs & PFX_INPUT_COLOR)) return fail("the frame has no colour input");
  if (!output_texture || output_texture == textures.color) return fail("the output must be its own texture");

  std::vector<int> active;
  if (!declare_all(frame, &active, &message)) return fail(message);
  if (!plan_valid_ || active != planned_active_) {
    std::vector<PlanInput> inputs;
    for (int index : active) inputs.push_back({instances_[index]->name, &instances_[index]->declaration});
    FramePlan plan;
    if (!plan_frame(inputs, frame.width, frame.height, frame.inputs, &plan, &message)) return fail(message);
    plan_ = std::move(plan);
    planned_active_ = active;
    plan_valid_ = true;
    gl_->pool.match(plan_.slots);
  }
  report_.peak_target_bytes = plan_.peak_target_bytes;
  report_.unpooled_target_bytes = plan_.unpooled_target_bytes;
  return execute(frame, textures, output_texture, active, error);
}

bool Chain::execute(const pfx_frame& frame, const FrameTextures& textures, uint32_t output_texture,
                    const std::vector<int>& active, std::string* error) {
  report_.passes.clear();
  report_.effect_reports.clear();
  report_.timing = timing_ == Timing::GPU_QUERIES ? "gpu-timestamps" : timing_ == Timing::FINISH_AND_CLOCK ? "finish+clock" : "off";
  report_.times = times_;
  GlPool& pool = gl_->pool;

  while (glGetError() != GL_NO_ERROR) {
  }  // errors of the embedding program are not ours to report
  if (active.empty()) {
    // Every effect is off or a no-op: the output is the input, at the cost of one copy.
    glCopyImageSubData(textures.color, GL_TEXTURE_2D, 0, 0, 0, 0, output_texture, GL_TEXTURE_2D, 0, 0, 0, 0,
                       static_cast<GLsizei>(frame.width), static_cast<GLsizei>(frame.height), 1);
    GLenum gl_error = glGetError();
    if (gl_error != GL_NO_ERROR) {
      if (error) *error = "copying colour to the output failed (GL error " + gl_error_text(gl_error) +
                          "): both must be RGBA16F textures of the frame size";
      return false;
    }
    return true;
  }
  GLboolean feedback_active = GL_FALSE, feedback_paused = GL_FALSE;
  glGetBooleanv(GL_TRANSFORM_FEEDBACK_ACTIVE, &feedback_active);
  glGetBooleanv(GL_TRANSFORM_FEEDBACK_PAUSED, &feedback_paused);
  if (feedback_active && !feedback_paused) {
    if (error) *error = "transform feedback is active: end or pause it before render()";
    return false;
  }

  // The state every pass starts from (docs/sdk.md §1.5), and the engine's back on every return,
  // unless a GlStateGuard of the host saved it already and will put it back.
  GlStateScope state_scope(gl_->limits, guards_ > 0 ? GlStateScope::SET_ONLY : GlStateScope::SAVE);

  auto frame_input_texture = [&](const std::string& name) -> GLuint {
    if (name == PFX_INPUT_NAME_COLOR) return textures.color;
    if (name == PFX_INPUT_NAME_DEPTH) return textures.depth;
    if (name == PFX_INPUT_NAME_NORMAL) return textures.normal;
    if (name == PFX_INPUT_NAME_ALBEDO) return textures.albedo;
    if (name == PFX_INPUT_NAME_EMISSIVE) return textures.emissive;
    return 0;
  };
  auto resolve = [&](const ResourceRef& ref, uint32_t* width, uint32_t* height, pfx_format* format) -> GLuint {
    *format = PFX_FORMAT_RGBA16F;
    if (ref.kind == ResourceRef::POOLED) {
      const PlannedResource& r = plan_.resources[ref.resource];
      *width = r.width;
      *height = r.height;
      *format = r.format;
      return pool.texture(r.slot);
    }
    *width = frame.width;
    *height = frame.height;
    if (ref.kind == ResourceRef::CHAIN_OUTPUT) return output_texture;
    if (ref.kind == ResourceRef::FRAME_INPUT) return frame_input_texture(ref.frame_input);
    return 0;
  };

  using Clock = std::chrono::steady_clock;
  std::vector<double> cpu_ms;
  GpuTimer& timer = gl_->timer;
  if (timing_ == Timing::GPU_QUERIES) timer.begin_frame(report_.frame);
  if (timing_ == Timing::FINISH_AND_CLOCK) glFinish();
  // A frame that fails part way leaves no half-stamped query set in flight.
  struct AbandonOnFailure {
    GpuTimer& timer;
    bool done = false;
    ~AbandonOnFailure() {
      if (!done) timer.abandon_frame();
    }
  } abandon_on_failure{timer};

  std::vector<pfx_bound_texture> bound;
  for (size_t p = 0; p < plan_.passes.size(); ++p) {
    const PlannedPass& planned = plan_.passes[p];
    Instance& instance = *instances_[active[planned.effect]];
    const DeclaredPass& pass = instance.declaration.passes[planned.pass];
    const char* effect_id = instance.info.desc->id;

    pfx_pass_context context{};
    context.struct_size = sizeof context;
    context.pass_index = static_cast<uint32_t>(planned.pass);
    context.user_tag = pass.user_tag;
    context.frame = &frame;
    context.params = params_.values(effect_id, instance.number);

    if (planned.output.kind != ResourceRef::NONE) {
      context.output_texture =
          resolve(planned.output, &context.output_width, &context.output_height, &context.output_format);
      context.output_framebuffer = planned.output.kind == ResourceRef::POOLED
                                       ? pool.framebuffer(plan_.resources[planned.output.resource].slot)
                                       : pool.framebuffer_for(output_texture);
      glBindFramebuffer(GL_FRAMEBUFFER, context.output_framebuffer);
      glViewport(0, 0, static_cast<GLsizei>(context.output_width), static_cast<GLsizei>(context.output_height));
      if (pass.load == PFX_LOAD_CLEAR) {
        const GLfloat zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_COLOR, 0, zero);
      }
    } else {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    if (pass.blend == PFX_BLEND_ADD) glEnable(GL_BLEND);
    else glDisable(GL_BLEND);

    bound.assign(planned.inputs.size(), pfx_bound_texture{});
    for (size_t i = 0; i < planned.inputs.size(); ++i) {
      pfx_format format;
      bound[i].texture = resolve(planned.inputs[i], &bound[i].width, &bound[i].height, &format);
      bound[i].unit = static_cast<uint32_t>(i);
      glBindTextureUnit(static_cast<GLuint>(i), bound[i].texture);
      glBindSampler(static_cast<GLuint>(i), pool.sampler(pass.inputs[i].filter, pass.inputs[i].wrap));
    }
    context.inputs = bound.data();
    context.input_count = static_cast<uint32_t>(bound.size());
    glBindVertexArray(pool.empty_vertex_array());
    glActiveTexture(GL_TEXTURE0);

    if (pass_hook_) pass_hook_(effect_id, pass.name, false);
    Clock::time_point start = Clock::now();
    pfx_status status = instance.info.desc->run_pass(instance.handle, &context);
    if (pass_hook_) pass_hook_(effect_id, pass.name, true);
    // Passes are reported by instance: "bloom#2" tells the second bloom's passes from the first's.
    if (timing_ == Timing::GPU_QUERIES) timer.end_pass(instance.name, pass.name);
    if (timing_ == Timing::FINISH_AND_CLOCK) {
      glFinish();
      cpu_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    for (size_t i = 0; i < bound.size(); ++i) glBindSampler(static_cast<GLuint>(i), 0);

    const std::string label = std::string("effect '") + effect_id + "' pass '" + pass.name + "'";
    if (status != PFX_OK) {
      if (error) *error = label + " failed (status " + std::to_string(status) + ")";
      return false;
    }
    GLenum gl_error = glGetError();
    if (gl_error != GL_NO_ERROR) {
      if (error) *error = label + " raised GL error " + gl_error_text(gl_error);
      return false;
    }
    report_.passes.push_back({instance.name, pass.name, 0.0});
  }

  abandon_on_failure.done = true;
  if (timing_ != Timing::OFF) last_timed_frame_ = report_.frame;
  if (timing_ == Timing::GPU_QUERIES) {
    timer.end_frame();
    // Earlier frames only, and only those whose queries have landed: never a wait.
    if (timer.poll(report_.frame, &times_)) report_.times = times_;
  } else if (timing_ == Timing::FINISH_AND_CLOCK) {
    FrameTimes times;
    times.frame = report_.frame;
    for (size_t i = 0; i < report_.passes.size(); ++i) {
      report_.passes[i].ms = cpu_ms[i];
      times.total_ms += cpu_ms[i];
    }
    times.passes = report_.passes;
    times_ = std::move(times);
    report_.times = times_;
  }

  for (int index : active) {
    Instance& instance = *instances_[index];
    if (!instance.info.desc->report_json) continue;
    const char* figures = instance.info.desc->report_json(instance.handle);
    if (figures && *figures) report_.effect_reports.emplace_back(instance.name, figures);
  }
  return true;
}

}  // namespace pfx::host
