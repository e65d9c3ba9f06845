#include "frame_chain.hpp"

#include <cmath>
#include <cstdio>

#include "camera_options.hpp"
#include "frame_description.hpp"

namespace pfx::adapters {

std::unique_ptr<FrameChain> FrameChain::build(const host::PluginRegistry& registry, const app::ChainRecipe& recipe,
                                              const std::string& set_origin, std::vector<std::string>* notes,
                                              std::string* error) {
  std::unique_ptr<FrameChain> self(new FrameChain);
  self->params_ = std::make_unique<host::ParamStore>(host::DefaultSet::DISPLAY_REFERRED);
  for (const auto& effect : registry.effects()) self->params_->add_effect(effect.desc);
  self->chain_ = std::make_unique<host::Chain>(registry, *self->params_);
  if (!app::build_chain(recipe, self->chain_.get(), self->params_.get(), error, notes, set_origin)) return nullptr;
  return self;
}

bool FrameChain::update(const host::PluginRegistry& registry, const app::ChainRecipe& recipe,
                        const std::string& set_origin, std::vector<std::string>* notes, std::string* error) {
  if (!app::chain_holds_recipe(*chain_, recipe)) {
    std::unique_ptr<FrameChain> fresh = build(registry, recipe, set_origin, notes, error);
    if (!fresh) return false;
    chain_.reset();  // the old instances before the store they read
    params_ = std::move(fresh->params_);
    chain_ = std::move(fresh->chain_);
    return true;
  }
  if (!app::replace_recipe_values(recipe, registry, params_.get(), error, notes, set_origin)) return false;
  for (size_t i = 0; i < chain_->size(); ++i) chain_->set_enabled(i, recipe.effects[i].enabled);
  return true;
}

std::string FrameChain::text() const {
  std::string text;
  for (size_t i = 0; i < chain_->size(); ++i)
    text += (text.empty() ? "" : ",") + chain_->instance_name(i) + (chain_->enabled(i) ? "" : " (off)");
  return text.empty() ? "none" : text;
}

FrameChain::~FrameChain() {
  // Instances before the store they read.
  chain_.reset();
  params_.reset();
}

bool FrameChain::runs_effects() const { return app::any_enabled(*chain_); }

pfx_frame describe_video_frame(int width, int height, double time_seconds, uint64_t frame_index) {
  pfx_frame description = app::describe_frame(width, height, PFX_INPUT_COLOR, PFX_DEPTH_NONE,
                                              app::make_camera(app::CameraOptions{}, width, height));
  // As the host gives it (docs/hosts.md says what each host passes).
  description.time_seconds = std::isfinite(time_seconds) ? time_seconds : 0.0;
  description.frame_index = frame_index;
  return description;
}

bool FrameChain::plans_passes(int width, int height, double time_seconds, uint64_t frame_index, bool* passes,
                              std::string* error) const {
  *passes = false;
  if (!runs_effects()) return true;
  return chain_->plans_passes(describe_video_frame(width, height, time_seconds, frame_index), passes, error);
}

bool FrameChain::render(gl::DisplayFrame& frame, double time_seconds, uint64_t frame_index, GLuint* result,
                        std::string* error) {
  if (!runs_effects()) {
    *result = frame.color();
    return true;
  }
  host::FrameTextures textures;
  textures.color = frame.color();
  if (!chain_->render(describe_video_frame(frame.width(), frame.height(), time_seconds, frame_index), textures, frame.output(),
                      error))
    return false;
  *result = frame.output();
  return true;
}

bool FrameChain::render(GLuint color, GLuint output, int width, int height, double time_seconds,
                        uint64_t frame_index, std::string* error) {
  if (!runs_effects()) {
    glCopyImageSubData(color, GL_TEXTURE_2D, 0, 0, 0, 0, output, GL_TEXTURE_2D, 0, 0, 0, 0, width, height, 1);
    return true;
  }
  host::FrameTextures textures;
  textures.color = color;
  return chain_->render(describe_video_frame(width, height, time_seconds, frame_index), textures, output, error);
}

bool no_gl_error(std::string* error) {
  const GLenum gl_error = glGetError();
  if (gl_error == GL_NO_ERROR) return true;
  char text[64];
  std::snprintf(text, sizeof text, "GL error 0x%04x while running the chain", gl_error);
  *error = text;
  return false;
}

}  // namespace pfx::adapters
