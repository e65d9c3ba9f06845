#include "render_rig.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glad/gl.h>
#include <pfx/host/gl_error.hpp>

#include "camera_options.hpp"
#include "display_transfer.hpp"
#include "eight_bit_texture.hpp"
#include "frame_description.hpp"
#include "image_texture.hpp"
#include "synthetic_inputs.hpp"
#include "tonemap.hpp"

namespace pfx::validate {
namespace {

// In front of the camera (which looks down -Z), one behind it and one at the near plane: the
// hard cases of a lighting effect, which must give a finite picture for each.
const pfx_light kLights[] = {
    {{0.0f, 1.0f, -5.0f}, 10.0f, {1.0f, 0.9f, 0.8f}, 4.0f},
    {{-2.0f, 0.0f, -20.0f}, 0.0f, {0.2f, 0.4f, 1.0f}, 50.0f},
    {{1.0f, 0.0f, 3.0f}, 5.0f, {1.0f, 0.0f, 0.0f}, 2.0f},
    {{0.0f, 0.0f, -0.1f}, 1.0f, {0.0f, 1.0f, 0.0f}, 1.0f},
};

std::string pixel_text(const float* p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%g, %g, %g, %g", p[0], p[1], p[2], p[3]);
  return buffer;
}

}  // namespace

RenderRig::~RenderRig() {
  chain_.reset();  // destroys the instances while the context is still current
  registry_.reset();
  context_.reset();
}

void RenderRig::problem_once(const std::string& text) {
  if (reported_.insert(text).second) report_.problem(text);
}

bool RenderRig::open_context() {
  report_.step("creating a headless OpenGL 4.5 context");
  std::string error;
  context_ = pfx::app::HeadlessContext::create(&error);
  if (!context_) {
    report_.problem(error);
    return false;
  }
  return true;
}

void RenderRig::unload() {
  chain_.reset();
  registry_.reset();
}

bool RenderRig::load(const std::string& plugin_path, const pfx_thread_pool* pool) {
  std::string error;
  pfx::host::LogSink sink = [this](pfx_log_level level, const std::string& source, const std::string& message) {
    if (level >= PFX_LOG_WARNING) plugin_log_.push_back(source + ": " + message);
  };
  registry_ = std::make_unique<pfx::host::PluginRegistry>(
      [](const char* name) { return pfx::app::HeadlessContext::get_proc_address(nullptr, name); }, sink,
      "pfx-validate");
  if (pool) registry_->set_thread_pool(pool);
  report_.step("loading the plugin through libpfxhost");
  if (!registry_->load(plugin_path, &error)) {
    report_.problem("the host runtime refuses the plugin: " + error);
    return false;
  }
  chain_ = std::make_unique<pfx::host::Chain>(*registry_, params_);
  chain_->set_timing(pfx::host::Timing::OFF);
  chain_->set_pass_hook([this](const std::string& effect, const std::string& pass, bool after) {
    if (!after) {
      before_pass_ = snapshot_gl_state();
      return;
    }
    for (const std::string& change : gl_state_changes(before_pass_, snapshot_gl_state()))
      problem_once("GL state not restored by " + effect + " pass '" + pass + "': " + change);
  });
  return true;
}

void RenderRig::check_gl_calls(const std::string& what, const GlStateSnapshot& before) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) problem_once(what + " left GL error " + pfx::host::gl_error_text(error));
  while (glGetError() != GL_NO_ERROR) {
  }
  for (const std::string& change : gl_state_changes(before, snapshot_gl_state()))
    problem_once(what + " changed GL state (it must leave bindings alone): " + change);
}

bool RenderRig::add_effect(const std::string& effect_id) {
  const pfx::host::EffectInfo* info = registry_->find_effect(effect_id);
  if (!info) {
    report_.problem("the host runtime does not list effect '" + effect_id + "'");
    return false;
  }
  effect_ = info->desc;
  while (glGetError() != GL_NO_ERROR) {
  }
  const GlStateSnapshot before = snapshot_gl_state();
  report_.step("create of '" + effect_id + "'");
  std::string error;
  if (!chain_->add(effect_id, &error)) {
    std::string log;
    for (const std::string& line : plugin_log_) log += " | " + line;
    report_.problem(error + log);
    return false;
  }
  check_gl_calls("create of '" + effect_id + "'", before);
  return true;
}

void RenderRig::remove_effect() {
  if (!chain_ || chain_->size() == 0) return;
  const GlStateSnapshot before = snapshot_gl_state();
  report_.step("destroy of '" + chain_->effect_id(0) + "'");
  const std::string what = "destroy of '" + chain_->effect_id(0) + "'";
  chain_->remove(0);
  check_gl_calls(what, before);
}

pfx_frame RenderRig::describe(int w, int h) const {
  pfx_frame frame = pfx::app::describe_frame(w, h, pfx::app::kEveryInput, PFX_DEPTH_LINEAR,
                                             pfx::app::make_camera(pfx::app::CameraOptions{}, w, h));
  frame.time_seconds = 0.5;
  frame.frame_index = 1;
  frame.lights = kLights;
  frame.light_count = sizeof kLights / sizeof kLights[0];
  return frame;
}

pfx::host::FrameTextures RenderRig::auxiliary_textures(const pfx::app::Image& input) const {
  const int w = input.width, h = input.height;
  pfx::host::FrameTextures textures;
  textures.depth = pfx::app::upload_depth_texture(input);
  textures.normal = pfx::app::upload_color_texture(aux_frame(AuxKind::Normal, w, h));
  textures.albedo = pfx::app::upload_color_texture(aux_frame(AuxKind::Albedo, w, h));
  textures.emissive = pfx::app::upload_color_texture(aux_frame(AuxKind::Emissive, w, h));
  return textures;
}

bool RenderRig::run_chain(const pfx_frame& frame, const pfx::host::FrameTextures& textures, uint32_t out,
                          const std::string& label) {
  report_.step("rendering " + label);
  plugin_log_.clear();
  std::string error;
  if (before_chain_) before_chain_();
  const bool rendered = chain_->render(frame, textures, out, &error);
  if (after_chain_) after_chain_();
  if (rendered) return true;
  std::string log;
  for (const std::string& line : plugin_log_) log += " | " + line;
  problem_once(label + ": " + error + log);
  return false;
}

bool RenderRig::render(const pfx::app::Image& input, const std::string& label, pfx::app::Image* output) {
  const int w = input.width, h = input.height;
  pfx::host::FrameTextures textures = auxiliary_textures(input);
  textures.color = pfx::app::upload_color_texture(input);
  const uint32_t out = pfx::app::create_color_texture(w, h);
  const bool rendered = run_chain(describe(w, h), textures, out, label);
  pfx::app::Image result, seen;
  if (rendered) {
    result = pfx::app::download_color_texture(out, w, h);
    // What the effect saw: half-float storage already turned values above 65504 into infinity.
    seen = pfx::app::download_color_texture(textures.color, w, h);
  }
  for (uint32_t texture : {textures.color, textures.depth, textures.normal, textures.albedo, textures.emissive, out})
    pfx::app::delete_texture(texture);
  if (!rendered) return false;

  size_t bad = 0, first = 0;
  for (size_t i = 0; i < seen.pixel_count(); ++i)
    if (pixel_is_finite(seen, i) && !pixel_is_finite(result, i) && bad++ == 0) first = i;
  if (bad > 0) {
    problem_once(label + ": " + std::to_string(bad) + " pixel(s) not finite where the input was (first at x=" +
                 std::to_string(first % w) + ", y=" + std::to_string(first / w) + " from the top: " +
                 pixel_text(&result.rgba[first * 4]) + ")");
    return false;
  }
  if (output) *output = std::move(result);
  return true;
}

bool RenderRig::render_display(const pfx::app::DisplayImage& codes, const std::string& label,
                               pfx::app::DisplayImage* eight_bit, pfx::app::DisplayImage* wide, int* own_passes) {
  const int w = codes.width, h = codes.height;
  pfx::app::Image decoded = pfx::app::decode_display_image(codes, pfx::app::Transfer::SRGB);
  decoded.depth = gradient_image(w, h).depth;
  const pfx_frame frame = describe(w, h);
  pfx::host::FrameTextures textures = auxiliary_textures(decoded);
  bool rendered = false;
  {
    pfx::gl::EightBitTexture in, out;
    in.create(w, h);
    out.create(w, h);
    in.upload_top_first(codes.pixels.data(), w, h);
    textures.color = in.srgb_view;
    rendered = run_chain(frame, textures, out.srgb_view, label + " as 8-bit textures");
    if (rendered) {
      *eight_bit = codes;
      out.read_top_first(eight_bit->pixels.data(), w, h);
      *own_passes = 0;
      for (const auto& pass : chain_->report().passes) *own_passes += pass.effect == "chain";
    }
    in.release();
    out.release();
  }
  // The second render gets a fresh instance: an effect may keep state from frame to frame (an FX
  // effect's textures and counters do, as in ReShade), and each render must be its first frame.
  if (rendered) {
    const std::string effect_id = effect_->id;
    remove_effect();
    rendered = add_effect(effect_id);
  }
  if (rendered) {
    textures.color = pfx::app::upload_color_texture(decoded);
    const uint32_t out = pfx::app::create_color_texture(w, h);
    rendered = run_chain(frame, textures, out, label + " in RGBA16F");
    if (rendered) {
      const pfx::app::Image result = pfx::app::download_color_texture(out, w, h);
      wide->width = w;
      wide->height = h;
      wide->channels = 4;
      wide->pixels.resize(static_cast<size_t>(w) * h * 4);
      for (size_t i = 0; i < wide->pixels.size(); ++i) {
        const float v = result.rgba[i];
        wide->pixels[i] = i % 4 == 3 ? static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255))
                                     : pfx::app::encode_srgb8(v);
      }
    }
    pfx::app::delete_texture(textures.color);
    pfx::app::delete_texture(out);
  }
  for (uint32_t texture : {textures.depth, textures.normal, textures.albedo, textures.emissive})
    pfx::app::delete_texture(texture);
  return rendered;
}

}  // namespace pfx::validate
