// Chain::execute: running a frame's plan. Each pass is bound (output, viewport, blend, inputs),
// run between the pass hooks and the timer, and checked; then the timer and the effects report.
#include "chain_internal.hpp"
#include "frame_ends.hpp"
#include "frame_timer.hpp"
#include "pfx/host/gl_error.hpp"

namespace pfx::host {
namespace {

const char* timing_name(Timing timing) {
  switch (timing) {
    case Timing::GPU_QUERIES: return "gpu-timestamps";
    case Timing::FINISH_AND_CLOCK: return "finish+clock";
    case Timing::OFF: break;
  }
  return "off";
}

GLuint frame_input_texture(const FrameTextures& textures, const std::string& name) {
  if (name == PFX_INPUT_NAME_COLOR) return textures.color;
  if (name == PFX_INPUT_NAME_DEPTH) return textures.depth;
  if (name == PFX_INPUT_NAME_NORMAL) return textures.normal;
  if (name == PFX_INPUT_NAME_ALBEDO) return textures.albedo;
  if (name == PFX_INPUT_NAME_EMISSIVE) return textures.emissive;
  return 0;
}

// Every effect is off or a no-op: the output is the input, at the cost of one copy (a draw where
// one is 8-bit and the other not, so the values stay linear light, or where the host set a
// swizzle on its colour, which only sampling applies).
bool copy_color_to_output(const FrameResources& resources, const GlLimits& limits, GlPool& pool,
                          FrameConversion& conversion, std::string* error) {
  const GLuint color = resources.textures.color;
  const auto width = static_cast<GLsizei>(resources.frame.width), height = static_cast<GLsizei>(resources.frame.height);
  const HostOutput& output = resources.output;
  GlStateScope state_scope(limits, GlStateScope::SAVE);
  if (output.to_framebuffer) {
    // Codes that mean what the framebuffer's do move as bits (a blit converts nothing with
    // GL_FRAMEBUFFER_SRGB off); other colour is drawn, encoded as the framebuffer wants.
    GLint format = 0;
    glGetTextureLevelParameteriv(color, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    if (format == (output.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8) && samples_as_stored(color)) {
      glBindFramebuffer(GL_READ_FRAMEBUFFER, pool.framebuffer_for(color));
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, output.framebuffer);
      glDisable(GL_FRAMEBUFFER_SRGB);
      glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    } else if (!conversion.draw_into(color, output.framebuffer, output.srgb, resources.frame.width,
                                     resources.frame.height, error)) {
      return false;
    }
  } else if (is_eight_bit_texture(color) == resources.output_eight_bit && samples_as_stored(color)) {
    glCopyImageSubData(color, GL_TEXTURE_2D, 0, 0, 0, 0, output.texture, GL_TEXTURE_2D, 0, 0, 0, 0, width, height, 1);
  } else if (!conversion.draw_copy(color, output.texture, resources.frame.width, resources.frame.height, error)) {
    return false;
  }
  const GLenum gl_error = glGetError();
  if (gl_error == GL_NO_ERROR) return true;
  if (error)
    *error = "copying colour to the output failed (GL error " + gl_error_text(gl_error) +
             "): both must be of the frame size, RGBA16F or 8-bit";
  return false;
}

// Whether a pass of the plan samples the chain's output (the last effect reading back what it drew).
bool plan_reads_chain_output(const FramePlan& plan) {
  for (const PlannedPass& pass : plan.passes)
    for (const ResourceRef& input : pass.inputs)
      if (input.kind == ResourceRef::CHAIN_OUTPUT) return true;
  return false;
}

bool transform_feedback_running() {
  GLboolean active = GL_FALSE, paused = GL_FALSE;
  glGetBooleanv(GL_TRANSFORM_FEEDBACK_ACTIVE, &active);
  glGetBooleanv(GL_TRANSFORM_FEEDBACK_PAUSED, &paused);
  return active && !paused;
}

// Binds what one planned pass reads and writes, and describes it to the plugin.
class PassBinding {
 public:
  PassBinding(const FrameResources& resources, const PlannedPass& planned, const DeclaredPass& pass);
  PassBinding(const PassBinding&) = delete;
  PassBinding& operator=(const PassBinding&) = delete;
  // The pass's samplers are the chain's, not the next pass's nor the engine's.
  ~PassBinding();
  // The fields of the pass context that name the output and the inputs.
  void describe(pfx_pass_context* context) const;

 private:
  GLuint resolve(const ResourceRef& ref, uint32_t* width, uint32_t* height, pfx_format* format) const;
  void bind_output(const PlannedPass& planned, const DeclaredPass& pass);
  void bind_inputs(const PlannedPass& planned, const DeclaredPass& pass);

  const FrameResources& resources_;
  const bool display_referred_;  // the effect reads and writes sRGB codes
  GLuint output_texture_ = 0, output_framebuffer_ = 0;
  uint32_t output_width_ = 0, output_height_ = 0;
  pfx_format output_format_ = PFX_FORMAT_RGBA16F;
  bool srgb_writes_ = false;
  std::vector<pfx_bound_texture> inputs_;
};

PassBinding::PassBinding(const FrameResources& resources, const PlannedPass& planned,
                         const DeclaredPass& pass)
    : resources_(resources), display_referred_(planned.display_referred) {
  bind_output(planned, pass);
  if (pass.blend == PFX_BLEND_ADD) glEnable(GL_BLEND);
  else glDisable(GL_BLEND);
  bind_inputs(planned, pass);
  glBindVertexArray(resources_.pool.empty_vertex_array());
  glActiveTexture(GL_TEXTURE0);
}

PassBinding::~PassBinding() {
  for (size_t i = 0; i < inputs_.size(); ++i) glBindSampler(static_cast<GLuint>(i), 0);
  if (srgb_writes_) glDisable(GL_FRAMEBUFFER_SRGB);
}

GLuint PassBinding::resolve(const ResourceRef& ref, uint32_t* width, uint32_t* height, pfx_format* format) const {
  *format = PFX_FORMAT_RGBA16F;
  if (ref.kind == ResourceRef::POOLED) {
    const PlannedResource& r = resources_.plan.resources[ref.resource];
    *width = r.width;
    *height = r.height;
    *format = r.format;
    // sRGB codes between effects: a linear effect samples them decoded.
    return r.display_codes && !display_referred_ ? resources_.pool.srgb_view(r.slot) : resources_.pool.texture(r.slot);
  }
  *width = resources_.frame.width;
  *height = resources_.frame.height;
  if (ref.kind == ResourceRef::CHAIN_OUTPUT) {
    if (resources_.output_eight_bit) *format = PFX_FORMAT_RGBA8;
    return resources_.output_to_framebuffer ? 0 : resources_.output_bound;
  }
  if (ref.kind == ResourceRef::FRAME_INPUT)
    return ref.frame_input == PFX_INPUT_NAME_COLOR ? resources_.color_bound
                                                  : frame_input_texture(resources_.textures, ref.frame_input);
  return 0;
}

void PassBinding::bind_output(const PlannedPass& planned, const DeclaredPass& pass) {
  if (planned.output.kind == ResourceRef::NONE) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return;
  }
  output_texture_ = resolve(planned.output, &output_width_, &output_height_, &output_format_);
  const bool chain_output = planned.output.kind == ResourceRef::CHAIN_OUTPUT;
  if (chain_output && resources_.output_to_framebuffer) output_framebuffer_ = resources_.output.framebuffer;
  else if (chain_output) output_framebuffer_ = resources_.pool.framebuffer_for(output_texture_);
  const PlannedResource* pooled = chain_output ? nullptr : &resources_.plan.resources[planned.output.resource];
  // sRGB codes between effects: a linear effect draws them encoded.
  const bool encodes_codes = pooled && pooled->display_codes && !display_referred_;
  if (encodes_codes) output_framebuffer_ = resources_.pool.srgb_framebuffer(pooled->slot);
  else if (pooled) output_framebuffer_ = resources_.pool.framebuffer(pooled->slot);
  glBindFramebuffer(GL_FRAMEBUFFER, output_framebuffer_);
  // Drawing into an sRGB output encodes; every other target is linear.
  if ((chain_output && resources_.output_srgb_writes) || encodes_codes) {
    glEnable(GL_FRAMEBUFFER_SRGB);
    srgb_writes_ = true;
  }
  glViewport(0, 0, static_cast<GLsizei>(output_width_), static_cast<GLsizei>(output_height_));
  if (pass.load == PFX_LOAD_CLEAR) {
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
  }
}

void PassBinding::bind_inputs(const PlannedPass& planned, const DeclaredPass& pass) {
  inputs_.assign(planned.inputs.size(), pfx_bound_texture{});
  for (size_t i = 0; i < planned.inputs.size(); ++i) {
    pfx_format format;
    inputs_[i].texture = resolve(planned.inputs[i], &inputs_[i].width, &inputs_[i].height, &format);
    inputs_[i].unit = static_cast<uint32_t>(i);
    glBindTextureUnit(static_cast<GLuint>(i), inputs_[i].texture);
    glBindSampler(static_cast<GLuint>(i), resources_.pool.sampler(pass.inputs[i].filter, pass.inputs[i].wrap));
  }
}

void PassBinding::describe(pfx_pass_context* context) const {
  context->output_texture = output_texture_;
  context->output_framebuffer = output_framebuffer_;
  context->output_width = output_width_;
  context->output_height = output_height_;
  context->output_format = output_format_;
  context->inputs = inputs_.data();
  context->input_count = static_cast<uint32_t>(inputs_.size());
}

}  // namespace

bool Chain::execute(FrameResources& resources, const std::vector<int>& active, std::string* error) {
  report_.passes.clear();
  report_.effect_reports.clear();
  report_.timing = timing_name(timing_);
  report_.times = times_;
  while (glGetError() != GL_NO_ERROR) {
  }  // errors of the embedding program are not ours to report
  if (active.empty()) return copy_color_to_output(resources, gl_->limits, gl_->pool, gl_->conversion, error);
  if (transform_feedback_running()) {
    if (error) *error = "transform feedback is active: end or pause it before render()";
    return false;
  }
  // The state every pass starts from (docs/sdk.md §1.5), and the engine's back on every return,
  // unless a GlStateGuard of the host saved it already and will put it back.
  GlStateScope state_scope(gl_->limits, guards_ > 0 ? GlStateScope::SET_ONLY : GlStateScope::SAVE);
  FrameTimer timer(timing_, gl_->timer, report_.frame);
  const Declaration& first = instances_[active.front()]->declaration;
  const Declaration& last = instances_[active.back()]->declaration;
  choose_frame_ends(first, last, plan_reads_chain_output(plan_), gl_->conversion, &resources);
  const bool ran = run_frame(resources, active, timer, error);
  release_frame_views(&resources);
  if (!ran) return false;
  if (timing_ != Timing::OFF) last_timed_frame_ = report_.frame;
  if (timer.finish(&report_.passes, &times_)) report_.times = times_;
  collect_effect_reports(active);
  return true;
}

bool Chain::run_frame(FrameResources& resources, const std::vector<int>& active, FrameTimer& timer,
                      std::string* error) {
  // The chain's own steps are timed and listed as passes of "chain", so a report shows them.
  std::string name;
  if (resources.color_step != ColorStep::AS_IS) {
    timer.start_pass();
    if (!run_color_step(resources, gl_->conversion, &name, error)) return false;
    chain_pass(timer, name);
  }
  for (const PlannedPass& planned : plan_.passes) {
    if (planned.conversion == Conversion::NONE) {
      if (!run_pass(resources, planned, *instances_[active[planned.effect]], timer, error)) return false;
      continue;
    }
    timer.start_pass();
    if (!run_conversion(resources, planned, error)) return false;
    chain_pass(timer, planned.conversion == Conversion::TO_DISPLAY ? "linear to sRGB codes" : "sRGB codes to linear");
  }
  if (resources.output_step != OutputStep::AS_IS) {
    timer.start_pass();
    if (!run_output_step(resources, gl_->pool, gl_->conversion, &name, error)) return false;
    chain_pass(timer, name);
  }
  return true;
}

void Chain::chain_pass(FrameTimer& timer, const std::string& name) {
  timer.end_pass("chain", name);
  report_.passes.push_back({"chain", name, 0.0});
}

bool Chain::run_conversion(const FrameResources& resources, const PlannedPass& planned, std::string* error) {
  const PlannedResource& from = plan_.resources[planned.inputs[0].resource];
  const PlannedResource& to = plan_.resources[planned.output.resource];
  const Transfer transfer = planned.conversion == Conversion::TO_DISPLAY ? Transfer::ENCODE : Transfer::DECODE;
  // Both raw: ENCODE writes codes itself, DECODE reads them.
  return gl_->conversion.draw_into(resources.pool.texture(from.slot), resources.pool.framebuffer(to.slot), false,
                                   to.width, to.height, error, transfer);
}

bool Chain::run_pass(const FrameResources& resources, const PlannedPass& planned, Instance& instance,
                     FrameTimer& timer, std::string* error) {
  const DeclaredPass& pass = instance.declaration.passes[planned.pass];
  const char* effect_id = instance.info.desc->id;
  pfx_status status = PFX_OK;
  {
    const PassBinding binding(resources, planned, pass);
    pfx_pass_context context{};
    context.struct_size = sizeof context;
    context.pass_index = static_cast<uint32_t>(planned.pass);
    context.user_tag = pass.user_tag;
    context.frame = &resources.frame;
    context.params = instance.values(params_);
    binding.describe(&context);

    if (pass_hook_) pass_hook_(effect_id, pass.name, false);
    timer.start_pass();
    status = instance.info.desc->run_pass(instance.handle, &context);
    if (pass_hook_) pass_hook_(effect_id, pass.name, true);
    // Passes are reported by instance: "bloom#2" tells the second bloom's passes from the first's.
    timer.end_pass(instance.name, pass.name);
  }
  auto fail = [&](const std::string& what) {
    if (error) *error = "effect '" + std::string(effect_id) + "' pass '" + pass.name + "' " + what;
    return false;
  };
  if (status != PFX_OK) return fail("failed (status " + std::to_string(status) + ")");
  const GLenum gl_error = glGetError();
  if (gl_error != GL_NO_ERROR) return fail("raised GL error " + gl_error_text(gl_error));
  report_.passes.push_back({instance.name, pass.name, 0.0});
  return true;
}

void Chain::collect_effect_reports(const std::vector<int>& active) {
  for (int index : active) {
    const Instance& instance = *instances_[index];
    if (!instance.info.desc->report_json) continue;
    const char* figures = instance.info.desc->report_json(instance.handle);
    if (figures && *figures) report_.effect_reports.emplace_back(instance.name, figures);
  }
}

}  // namespace pfx::host
