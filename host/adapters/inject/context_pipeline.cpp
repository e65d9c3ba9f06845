#include "context_pipeline.hpp"

#include <cstdio>
#include <optional>

#include <glad/gl.h>
#include <pfx/host/gl_error.hpp>
#include <pfx/host/gl_state_guard.hpp>

#include "camera_options.hpp"
#include "copy_pass.hpp"
#include "frame_capture.hpp"
#include "frame_description.hpp"
#include "timing_choice.hpp"

namespace pfx::inject {
namespace {

GLADapiproc load_through(void* user, const char* name) {
  const auto* loader = static_cast<const host::GlProcLoader*>(user);
  return reinterpret_cast<GLADapiproc>((*loader)(name));
}

// True for desktop OpenGL 4.5 or later; otherwise *why says what the context is instead.
bool desktop_gl_45(const host::GlProcLoader& loader, std::string* why) {
  // glGetString alone first: a full load fails on an ES context or one below 4.5.
  using GetString = const unsigned char* (*)(GLenum);
  auto get_string = reinterpret_cast<GetString>(loader("glGetString"));
  const char* version = get_string ? reinterpret_cast<const char*>(get_string(GL_VERSION)) : nullptr;
  const std::string text = version ? version : "";
  if (text.rfind("OpenGL ES", 0) == 0) {
    *why = "an " + text + " context: pfx needs desktop OpenGL 4.5";
    return false;
  }
  int major = 0, minor = 0;
  if (std::sscanf(text.c_str(), "%d.%d", &major, &minor) != 2 || major * 10 + minor < 45) {
    *why = "an OpenGL " + (text.empty() ? std::string("of unknown version") : text) +
           " context: pfx needs OpenGL 4.5";
    return false;
  }
  return true;
}

// The back buffer is 8-bit and display-referred: effects start from the defaults they give for
// such frames (bloom's threshold below 1.0), and a preset or --set overrides them as usual.
std::unique_ptr<host::ParamStore> make_params(const host::PluginRegistry& registry) {
  auto params = std::make_unique<host::ParamStore>(host::DefaultSet::DISPLAY_REFERRED);
  for (const auto& effect : registry.effects()) params->add_effect(effect.desc);
  return params;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

ContextPipeline::ContextPipeline(const host::PluginRegistry& registry, const InjectSettings& settings)
    : registry_(registry), settings_(settings) {}

std::unique_ptr<ContextPipeline> ContextPipeline::create(const host::PluginRegistry& registry,
                                                         const InjectSettings& settings, const ChainRecipe& recipe,
                                                         std::vector<std::string>* notes, std::string* reason) {
  const host::GlProcLoader& loader = registry.gl_loader();
  if (!desktop_gl_45(loader, reason)) return nullptr;
  if (!gladLoadGLUserPtr(load_through, const_cast<host::GlProcLoader*>(&loader)) || !GLAD_GL_VERSION_4_5) {
    *reason = "the context reports OpenGL 4.5 but its functions could not be loaded";
    return nullptr;
  }
  GLboolean double_buffered = GL_FALSE;
  glGetBooleanv(GL_DOUBLEBUFFER, &double_buffered);
  if (!double_buffered) {
    *reason = "a single-buffered window: there is no back buffer to run the chain over";
    return nullptr;
  }
  std::unique_ptr<ContextPipeline> pipeline(new ContextPipeline(registry, settings));
  const GLubyte* renderer = glGetString(GL_RENDERER);
  pipeline->renderer_ = renderer ? reinterpret_cast<const char*>(renderer) : "";
  pipeline->copy_.create();
  if (!pipeline->depth_check_.create(reason)) return nullptr;
  if (!pipeline->rebuild(recipe, notes, reason)) return nullptr;
  return pipeline;
}

ContextPipeline::~ContextPipeline() {
  // Instances before the store they read; the copy's objects go with the pipeline.
  chain_.reset();
  params_.reset();
}

pfx_frame ContextPipeline::frame_for(int width, int height, uint32_t inputs) const {
  app::CameraOptions camera;
  camera.near_plane = settings_.depth_near;
  camera.far_plane = settings_.depth_far;
  return app::describe_frame(width, height, inputs, PFX_DEPTH_HARDWARE, app::make_camera(camera, width, height));
}

bool ContextPipeline::same_effects(const ChainRecipe& recipe) const {
  return chain_ && recipe.chosen == built_.chosen && app::chain_holds_recipe(*chain_, recipe);
}

bool ContextPipeline::update_values(const ChainRecipe& recipe, std::vector<std::string>* notes, std::string* reason) {
  if (!app::replace_recipe_values(recipe, registry_, params_.get(), reason)) return false;
  // The flags the recipe gives (a default chain has every effect on); InputFit takes them as the
  // user's and fits them to the frame again.
  for (size_t i = 0; i < chain_->size(); ++i) chain_->set_enabled(i, !recipe.chosen || recipe.effects[i].enabled);
  const int width = copy_.width() ? copy_.width() : 64, height = copy_.height() ? copy_.height() : 64;
  if (!fit_.start(*chain_, false, frame_for(width, height, PFX_INPUT_COLOR | PFX_INPUT_DEPTH), notes, reason))
    return false;
  built_ = recipe;
  return true;
}

bool ContextPipeline::rebuild(const ChainRecipe& recipe, std::vector<std::string>* notes, std::string* reason) {
  // Only values or on/off flags changed (the live panel's sliders): no effect is created again.
  if (same_effects(recipe)) return update_values(recipe, notes, reason);
  auto params = make_params(registry_);
  auto chain = std::make_unique<host::Chain>(registry_, *params);
  InputFit fit;
  {
    // Effects compile programs and make textures as they are created: the application's
    // bindings survive that too.
    host::GlStateGuard guard(*chain);
    if (!build_chain(recipe, chain.get(), params.get(), reason)) return false;
  }
  const int width = copy_.width() ? copy_.width() : 64, height = copy_.height() ? copy_.height() : 64;
  if (!fit.start(*chain, !recipe.chosen, frame_for(width, height, PFX_INPUT_COLOR | PFX_INPUT_DEPTH), notes, reason))
    return false;
  // Times only for the control panel: on llvmpipe timing serialises the passes.
  if (!settings_.timings_file.empty()) chain->set_timing(app::default_timing(renderer_));
  chain_.reset();
  params_ = std::move(params);
  chain_ = std::move(chain);
  fit_ = std::move(fit);
  built_ = recipe;
  return true;
}

std::string ContextPipeline::chain_text() const {
  std::string text;
  for (size_t i = 0; i < chain_->size(); ++i)
    text += (text.empty() ? "" : ",") + chain_->instance_name(i) + (fit_.wanted(i) ? "" : " (off)");
  return text.empty() ? "none (frames presented as drawn)" : text;
}

bool ContextPipeline::wanted_any() const {
  for (size_t i = 0; i < chain_->size(); ++i)
    if (fit_.wanted(i)) return true;
  return false;
}

uint32_t ContextPipeline::fit_to_depth(const FrameWork& work, std::vector<std::string>* messages, std::string* reason,
                                       bool* ok) {
  *ok = true;
  uint32_t inputs = PFX_INPUT_COLOR;
  copy_.copy_depth_in();
  if (copy_.take_depth_lost()) messages->push_back("depth: " + copy_.depth_description());
  std::optional<DepthFinding> change;
  if (depth_check_.update(work.frame, copy_.depth(), work.width, work.height, &change)) inputs |= PFX_INPUT_DEPTH;
  if (change)
    messages->push_back("frame " + std::to_string(work.frame) + ": depth: " + copy_.depth_description() + ": " +
                        change->what +
                        (change->usable() ? ": read as hardware depth (near " + number_text(settings_.depth_near) +
                                                " m, far " + number_text(settings_.depth_far) + " m)"
                                          : ": not used"));
  const std::string lacking_depth = !copy_.has_depth() ? "the default framebuffer has none"
                                                       : "the depth buffer holds " + depth_check_.finding().what;
  *ok = fit_.fit(*chain_, frame_for(work.width, work.height, inputs), lacking_depth, messages, reason);
  return inputs;
}

bool ContextPipeline::nothing_to_run(const FrameWork& work, bool* nothing, std::string* reason) const {
  *nothing = !wanted_any();
  if (*nothing) return true;
  // An effect the fit switched off for lack of depth may come back once depth is usable: only the
  // depth check can tell, so the frame takes the full way.
  for (size_t i = 0; i < chain_->size(); ++i)
    if (fit_.wanted(i) != chain_->enabled(i)) return true;
  // Whatever the depth buffer turns out to hold: an effect may declare passes with depth and
  // without.
  for (uint32_t inputs : {uint32_t(PFX_INPUT_COLOR | PFX_INPUT_DEPTH), uint32_t(PFX_INPUT_COLOR)}) {
    pfx_frame frame = frame_for(work.width, work.height, inputs);
    frame.time_seconds = work.time_seconds;
    frame.frame_index = work.frame;
    bool passes = false;
    if (!chain_->plans_passes(frame, &passes, reason)) return false;
    if (passes) return true;
  }
  *nothing = true;
  return true;
}

bool ContextPipeline::process(const FrameWork& work, std::vector<std::string>* messages, std::string* reason) {
  // With every effect off or a no-op the frame is presented as the application drew it: not a
  // pixel is copied and no GL state is touched, unless a capture or the bench's copy pass asks for
  // GL.
  ran_passes_ = false;
  bool nothing = false;
  if (!nothing_to_run(work, &nothing, reason)) return false;
  if (nothing && work.captures.empty() && !work.measure_copy_pass) return true;
  const bool chain_may_run = wanted_any();
  host::GlStateGuard guard(*chain_);
  copy_.resize(work.width, work.height);
  if (!depth_said_ && !copy_.has_depth()) messages->push_back("depth: none (" + copy_.depth_description() + ")");
  depth_said_ = true;
  uint32_t inputs = PFX_INPUT_COLOR;
  if (chain_may_run) {
    bool fitted = false;
    inputs = fit_to_depth(work, messages, reason, &fitted);
    if (!fitted) return false;
  }
  pfx_frame frame = frame_for(work.width, work.height, inputs);
  frame.time_seconds = work.time_seconds;
  frame.frame_index = work.frame;
  // Effects that are all off or no-ops with their values change nothing: the frame stays in the
  // back buffer as it is (the copy in and out would give every code back anyway).
  bool passes = false;
  if (chain_may_run && any_enabled(*chain_) && !chain_->plans_passes(frame, &passes, reason)) return false;
  if ((passes || !work.captures.empty()) && !copy_.copy_colour_in(settings_.transfer, reason)) return false;
  host::FrameTextures textures;
  textures.color = copy_.color();
  if (inputs & PFX_INPUT_DEPTH) textures.depth = copy_.depth();

  // The chain draws its result straight into the back buffer where it can; a dry run leaves the
  // back buffer alone, so its result stays in a texture.
  const bool into_back_buffer = passes && !settings_.dry_run && copy_.back_buffer_takes_output();
  if (passes && !output_said_) {
    messages->push_back(into_back_buffer ? "output: the chain draws into the back buffer"
                        : settings_.dry_run ? "output: a texture (dry run)"
                                            : "output: an 8-bit texture blitted into the back buffer, which cannot "
                                              "encode sRGB as it is drawn into");
    output_said_ = true;
  }
  GLuint result = copy_.color();
  if (into_back_buffer) {
    host::FramebufferOutput output;
    output.srgb = settings_.transfer == Transfer::SRGB;
    if (!copy_.into_back_buffer([&] { return chain_->render(frame, textures, output, reason); })) return false;
    ran_passes_ = true;
  } else if (passes) {
    if (!chain_->render(frame, textures, copy_.output(), reason)) return false;
    result = copy_.output();
    ran_passes_ = true;
  }
  if (!work.captures.empty() && chain_may_run && any_enabled(*chain_)) {
    // Without passes the chain did not run: every instance was off or a no-op.
    std::string skipped;
    if (passes)
      for (const auto& id : chain_->report().effects_skipped) skipped += (skipped.empty() ? "" : ",") + id;
    else
      for (size_t i = 0; i < chain_->size(); ++i) skipped += (skipped.empty() ? "" : ",") + chain_->instance_name(i);
    if (!skipped.empty()) messages->push_back("frame " + std::to_string(work.frame) + ": skipped as no-ops or off: " + skipped);
  }
  // Every file that fails is named: one missing does not hide another.
  auto say = [&](const std::string& path, const std::string& error) {
    messages->push_back("frame " + std::to_string(work.frame) + ": capture " + path + " not written: " + error);
  };
  for (const auto& prefix : work.captures) {
    std::string error;
    if (!write_image_exr(copy_.linear_image(copy_.color()), prefix + ".app.exr", &error)) say(prefix + ".app.exr", error);
    const app::Image out = into_back_buffer ? copy_.linear_back_buffer() : copy_.linear_image(result);
    if (!write_image_exr(out, prefix + ".out.exr", &error)) say(prefix + ".out.exr", error);
  }
  if (passes && !settings_.dry_run && !into_back_buffer) copy_.copy_out(result);
  for (const auto& prefix : work.captures) {
    std::string error;
    if (!write_presented_png(copy_.read_back_buffer(), prefix + ".png", &error)) say(prefix + ".png", error);
  }
  // The unit every host measures in, under the guard like the passes around it.
  if (work.measure_copy_pass) copy_pass_ms_ = gl::median_copy_pass_ms(work.width, work.height, 9);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    *reason = "GL error " + host::gl_error_text(error) + " while copying the frame in or out";
    return false;
  }
  return true;
}

}  // namespace pfx::inject
