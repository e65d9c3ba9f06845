#include "fx_instance.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>

#include <pfx/cpp/gl_program.hpp>
#include <pfx/cpp/srgb_glsl.hpp>

#include "fx_texture_files.hpp"

namespace pfx_fx {
namespace {

using pfx::fx::GeneratedPass;
using pfx::fx::PassInfo;

// Linear light -> the display-referred 8-bit values FX shaders expect, as the hosts' transfer
// programs encode an 8-bit frame: clamped to [0, 1], NaN -> 0.
const char* kEncodeMain = R"(
layout(binding = 0) uniform sampler2D scene_color;
layout(location = 0) out vec4 display;
void main() {
  vec4 value = texelFetch(scene_color, ivec2(gl_FragCoord.xy), 0);
  value = clamp(mix(value, vec4(0.0), isnan(value)), 0.0, 1.0);
  display = vec4(pfx_srgb_encode(value.rgb), value.a);
}
)";

// The back buffer -> linear light. Alpha is the frame's own: FX shaders treat the back buffer's
// alpha as scratch (FXAA keeps luma there), since a display never shows it.
const char* kDecodeMain = R"(
layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1) uniform sampler2D back_buffer;
layout(location = 0) out vec4 color;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 value = texelFetch(back_buffer, texel, 0);
  color = vec4(pfx_srgb_decode(value.rgb), texelFetch(scene_color, texel, 0).a);
}
)";

// The same for a host of ABI 1.6 or later, to which the effect declares itself display-referred
// (PFX_DECLARATION_DISPLAY_REFERRED): "color" and the output hold sRGB codes already, so the
// picture only moves, with the frame's alpha.
const char* kCopyMain = R"(
layout(binding = 0) uniform sampler2D scene_color;
layout(location = 0) out vec4 display;
void main() { display = texelFetch(scene_color, ivec2(gl_FragCoord.xy), 0); }
)";
const char* kFinishMain = R"(
layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1) uniform sampler2D back_buffer;
layout(location = 0) out vec4 color;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  color = vec4(texelFetch(back_buffer, texel, 0).rgb, texelFetch(scene_color, texel, 0).a);
}
)";

// pfx depth (window depth, reversed window depth, or metres) -> linear L in [0, 1] from the near to
// the far plane -> the window depth d of a projection with near 1 and far F = 1000, which
// GetLinearizedDepth turns back into L: d / (F - d (F - 1)) = L.
const char* kDepthMain = R"(
layout(binding = 1) uniform sampler2D scene_depth;
layout(location = 0) uniform int encoding;  // 1 hardware, 2 reversed, 3 linear metres
layout(location = 1) uniform float near_plane;
layout(location = 2) uniform float far_plane;  // may be +infinity
layout(location = 0) out float fx_depth;
void main() {
  float d = texelFetch(scene_depth, ivec2(gl_FragCoord.xy), 0).r;
  float z;  // metres
  if (encoding == 3) z = d;
  else {
    if (encoding == 2) d = 1.0 - d;
    // Window depth of a standard projection, finite or infinite far plane.
    z = isinf(far_plane) ? near_plane / max(1.0 - d, 1e-30) : near_plane * far_plane / max(far_plane - d * (far_plane - near_plane), 1e-30);
  }
  float linear_depth = isinf(far_plane) ? 1.0 - near_plane / max(z, near_plane) : (z - near_plane) / (far_plane - near_plane);
  linear_depth = clamp(isnan(linear_depth) ? 1.0 : linear_depth, 0.0, 1.0);
  const float F = 1000.0;
  fx_depth = linear_depth * F / (1.0 + linear_depth * (F - 1.0));
}
)";

GLuint transfer_program(const char* main, std::string* error) {
  std::string source = std::string("#version 450 core\n") + pfx::gl::srgb_glsl_functions() + main;
  return pfx::gl::build_fullscreen_program(source.c_str(), error);
}

// Framebuffer bindings and viewport as the host set them, put back when a pass returns.
struct SavedTargets {
  GLint draw = 0, read = 0, viewport[4] = {0, 0, 0, 0};
  SavedTargets() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    glGetIntegerv(GL_VIEWPORT, viewport);
  }
  ~SavedTargets() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  }
};

}  // namespace

FxInstance::~FxInstance() {
  release_gl();
  if (encode_program_) glDeleteProgram(encode_program_);
  if (decode_program_) glDeleteProgram(decode_program_);
  if (depth_program_) glDeleteProgram(depth_program_);
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
}

void FxInstance::log(pfx_log_level level, const std::string& message) const {
  host_->log(host_->host_data, level, ("fx: " + entry_.id + ": " + message).c_str());
}

bool FxInstance::create_gl() {
  if (!pfx::gl::load_gl_or_log(host_, "fx")) return false;
  std::string error;
  // Codes in and out where the host can hand them (ABI 1.6), linear light otherwise.
  display_referred_ = host_->abi_minor >= 6;
  encode_program_ = transfer_program(display_referred_ ? kCopyMain : kEncodeMain, &error);
  if (encode_program_) decode_program_ = transfer_program(display_referred_ ? kFinishMain : kDecodeMain, &error);
  if (decode_program_) depth_program_ = transfer_program(kDepthMain, &error);
  if (!depth_program_) {
    log(PFX_LOG_ERROR, "the colour transfer programs did not build: " + error);
    return false;
  }
  glCreateFramebuffers(1, &framebuffer_);
  return true;
}

const pfx::fx::TechniqueInfo& FxInstance::technique() const {
  return compiled_->model.techniques[static_cast<std::size_t>(entry_.technique_index)];
}

std::unique_ptr<pfx::fx::CompiledEffect> FxInstance::compile_at(int width, int height, std::string* error) {
  const auto start = std::chrono::steady_clock::now();
  pfx::fx::FrontEndOptions options = compile_options(width, height);
  // After the file's defaults and pfx's own, which set_definitions already left out.
  options.preprocessor.defines.insert(options.preprocessor.defines.end(), definitions_.begin(), definitions_.end());
  redefined_ = false;
  auto compiled = pfx::fx::compile_effect(entry_.file, options, true);
  compile_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!compiled->ok()) {
    *error = "does not compile at " + std::to_string(width) + "x" + std::to_string(height) + ":\n" + compiled->errors();
    watch_.watch(*compiled, entry_.file);  // an edit that fixes it is picked up too
    return nullptr;
  }
  watch_.watch(*compiled, entry_.file);
  const auto& techniques = compiled->model.techniques;
  if (static_cast<std::size_t>(entry_.technique_index) >= techniques.size() ||
      techniques[static_cast<std::size_t>(entry_.technique_index)].name != entry_.technique) {
    *error = "technique '" + entry_.technique + "' is not in " + entry_.file + " at this frame size";
    return nullptr;
  }
  return compiled;
}

void FxInstance::adopt(std::unique_ptr<pfx::fx::CompiledEffect> compiled) {
  compiled_ = std::move(compiled);
  gl_current_ = false;
  passes_.clear();
  const auto& generated = compiled_->passes[static_cast<std::size_t>(entry_.technique_index)];
  needs_depth_ = false;
  for (const GeneratedPass& g : generated)
    for (int s : g.sampler_units) {
      int t = compiled_->model.samplers[static_cast<std::size_t>(s)].texture;
      needs_depth_ = needs_depth_ || (t >= 0 && compiled_->model.textures[static_cast<std::size_t>(t)].semantic == pfx::fx::TextureSemantic::kDepth);
    }
  layout_ = plan_pass_layout(*compiled_, entry_.technique_index, display_referred_);
  programs_.set_output_pass(layout_.output_pass);
  declare_passes();
  uniforms_.reset(compiled_->model, entry_.params);
  frame_params_.reset(compiled_->model, entry_.params, compiled_width_, compiled_height_);
}

void FxInstance::declare_passes() {
  const bool moves_out = layout_.output_pass < 0;  // a last pass of pfx's moves the picture out
  // Names first: the descriptors point into these strings, which must not move afterwards.
  pass_names_.clear();
  pass_names_.push_back(layout_.samples_frame ? "begin" : layout_.display_referred ? "copy in" : "encode");
  for (std::size_t i = 0; i < technique().passes.size(); ++i)
    pass_names_.push_back(technique().passes[i].name.empty() ? "pass" + std::to_string(i) : technique().passes[i].name);
  if (moves_out) pass_names_.push_back(layout_.display_referred ? "finish" : "decode");
  const std::size_t output = moves_out ? pass_names_.size() - 1 : static_cast<std::size_t>(layout_.output_pass) + 1;
  color_input_[0] = {PFX_INPUT_NAME_COLOR, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  color_input_[1] = {PFX_INPUT_NAME_DEPTH, PFX_FILTER_NEAREST, PFX_WRAP_CLAMP_TO_EDGE};
  for (std::size_t i = 0; i < pass_names_.size(); ++i) {
    pfx_pass_desc p{};
    p.struct_size = sizeof(pfx_pass_desc);
    p.name = pass_names_[i].c_str();
    p.kind = PFX_PASS_CUSTOM;
    p.user_tag = static_cast<uint32_t>(i);
    // The pass that writes "output" reads the frame's alpha; the technique's passes sample the
    // picture in the frame until one of them writes the back buffer.
    if (i == output || (layout_.samples_frame && i > 0)) {
      p.inputs = color_input_;
      p.input_count = 1;
    }
    if (i == 0) {
      p.inputs = color_input_;
      p.input_count = needs_depth_ ? 2 : 1;
    }
    if (i == output) p.output = PFX_OUTPUT_NAME;
    passes_.push_back(p);
  }
}

bool FxInstance::compile_source(int width, int height) {
  compiled_width_ = width, compiled_height_ = height;
  std::string error;
  auto compiled = compile_at(width, height, &error);
  if (!compiled) {
    log(PFX_LOG_ERROR, error);
    compiled_.reset();
    gl_current_ = false;
    return false;
  }
  adopt(std::move(compiled));
  note_ignored_features();
  return true;
}

void FxInstance::note_ignored_features() {
  if (told_ignored_) return;
  told_ignored_ = true;
  const pfx::fx::FrontEndResult& front = *compiled_->front;
  for (const pfx::fx::Pragma& pragma : front.preprocessed.pragmas)
    if (!pragma.tokens.empty() && pragma.tokens[0].text == "reshade")
      log(PFX_LOG_INFO, front.diagnostics.format({pfx::fx::Severity::kWarning, pragma.location,
                                                  "'#pragma " + pfx::fx::spell(pragma.tokens) + "' is ignored"}));
}

void FxInstance::reload_if_edited() {
  const bool redefined = redefined_;
  if (!redefined && !watch_.edited()) return;
  std::string error;
  auto compiled = compile_at(compiled_width_, compiled_height_, &error);
  if (!compiled) {
    log(PFX_LOG_ERROR, std::string(redefined ? "with the new preprocessor definitions, it " : "edited, and ") + error +
                           "\nThe last version that compiled keeps running.");
    return;
  }
  // The host planned this frame's passes at the last declare: a version declaring the same passes
  // runs from this frame on, one declaring others waits for the next declare.
  std::size_t passes = compiled->model.techniques[static_cast<std::size_t>(entry_.technique_index)].passes.size();
  const FxPassLayout layout = plan_pass_layout(*compiled, entry_.technique_index, display_referred_);
  if (layout != layout_ || layout.declared_passes(passes) != passes_.size()) {
    pending_ = std::move(compiled);
    log(PFX_LOG_INFO, "reloaded " + entry_.file + "; its new passes run from the next resize or parameter change");
    return;
  }
  adopt(std::move(compiled));
  log(PFX_LOG_INFO, "reloaded " + entry_.file);
}

pfx_status FxInstance::declare(const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  (void)params;
  int w = static_cast<int>(frame->width), h = static_cast<int>(frame->height);
  if (compiled_ && redefined_ && w == compiled_width_ && h == compiled_height_) reload_if_edited();
  if (!compiled_ || w != compiled_width_ || h != compiled_height_) {
    if (!compiled_ && w == compiled_width_ && h == compiled_height_) {  // failed at this size: wait for an edit
      watch_.look_next_time();
      reload_if_edited();
      if (pending_) adopt(std::move(pending_));
      if (!compiled_) return PFX_ERROR;
    } else if (!compile_source(w, h)) {
      return PFX_ERROR;
    }
  }
  if (pending_) adopt(std::move(pending_));
  // An effect that samples depth runs without it too (ReShade's effects test bufready_depth, or
  // read the far plane): its depth input is declared only when the frame has one.
  depth_in_frame_ = needs_depth_ && (frame->inputs & PFX_INPUT_DEPTH) && frame->depth_encoding != PFX_DEPTH_NONE;
  passes_[0].input_count = depth_in_frame_ ? 2 : 1;
  if (needs_depth_ && !depth_in_frame_ && !told_no_depth_) {
    told_no_depth_ = true;
    log(PFX_LOG_INFO, "this frame has no depth: the effect's depth buffer reads as the far plane");
  }
  out->passes = passes_.data();
  out->pass_count = static_cast<uint32_t>(passes_.size());
  // The first pass and the technique's (samples_frame_) only sample "color", and the last only
  // draws into the framebuffer the host bound; every other pass works on the effect's own
  // textures. So a host of 8-bit frames hands its frame in and takes the result as they are, with
  // no conversion to RGBA16F and back around the effect; one of ABI 1.6 hands sRGB codes.
  if (PFX_STRUCT_HAS(out, pfx_declaration, flags))
    out->flags |= PFX_DECLARATION_SAMPLES_AND_DRAWS | (display_referred_ ? uint32_t{PFX_DECLARATION_DISPLAY_REFERRED} : 0u);
  return PFX_OK;
}

pfx_status FxInstance::set_definitions(const char* list) {
  Definitions definitions;
  std::string error;
  if (!parse_definitions(list, &definitions, &error)) {
    log(PFX_LOG_ERROR, "preprocessor definitions refused: " + error);
    return PFX_INVALID_ARGUMENT;
  }
  // pfx converts the frame's depth itself (fx_instance.hpp): a preset's depth settings were made
  // for a game's raw depth buffer and would read pfx's wrong.
  const std::vector<std::string> ignored = remove_own_definitions(compile_options(1, 1).preprocessor.defines,
                                                                  &definitions);
  if (!ignored.empty()) {
    std::string names;
    for (const std::string& name : ignored) names += (names.empty() ? "" : ", ") + name;
    log(PFX_LOG_WARNING,
        "preprocessor definitions ignored: " + names + " (pfx hands FX effects its own depth and sets these)");
  }
  if (definitions == definitions_) return PFX_OK;
  definitions_ = std::move(definitions);
  redefined_ = true;
  return PFX_OK;
}

void FxInstance::release_gl() {
  leave_frame();
  programs_.release();
  for (GlTexture& t : textures_) delete_texture(t);
  textures_.clear();
  if (!samplers_.empty()) glDeleteSamplers(static_cast<GLsizei>(samplers_.size()), samplers_.data());
  samplers_.clear();
  delete_texture(back_buffer_[0]);
  delete_texture(back_buffer_[1]);
  delete_texture(fx_depth_);
  stencil_.release();
  if (uniform_buffer_) glDeleteBuffers(1, &uniform_buffer_);
  uniform_buffer_ = 0;
  uploaded_block_.clear();
  gl_current_ = false;
}

void FxInstance::upload_uniforms() {
  if (!uniform_buffer_) return;
  pfx::fx::pack_uniform_block(compiled_->model, block_layout_, uniforms_.all(), block_bytes_);
  if (block_bytes_ == uploaded_block_) return;  // the buffer holds these values already
  glNamedBufferSubData(uniform_buffer_, 0, static_cast<GLsizeiptr>(block_bytes_.size()), block_bytes_.data());
  uploaded_block_ = block_bytes_;
}

bool FxInstance::build_gl() {
  const auto start = std::chrono::steady_clock::now();
  struct Timed {
    std::chrono::steady_clock::time_point start;
    double* out;
    ~Timed() { *out = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(); }
  } timed{start, &gl_build_ms_};
  release_gl();
  const pfx::fx::EffectModel& model = compiled_->model;
  std::string error;
  const GlFormat f = gl_format(pfx::fx::TextureFormat::kRGBA8);
  for (GlTexture& b : back_buffer_)
    if (!create_texture_2d(compiled_width_, compiled_height_, f.internal, f.srgb_internal, b, error)) return log(PFX_LOG_ERROR, error), false;
  if (needs_depth_) {
    if (!create_texture_2d(compiled_width_, compiled_height_, GL_R32F, 0, fx_depth_, error)) return log(PFX_LOG_ERROR, error), false;
    const float far = 1.0f;
    glClearTexImage(fx_depth_.texture, 0, GL_RED, GL_FLOAT, &far);
  }
  if (!stencil_.create(technique(), compiled_width_, compiled_height_, error)) return log(PFX_LOG_ERROR, error), false;
  block_layout_ = pfx::fx::layout_uniform_block(model);
  if (block_layout_.size) {
    glCreateBuffers(1, &uniform_buffer_);
    glNamedBufferStorage(uniform_buffer_, static_cast<GLsizeiptr>(block_layout_.size), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  textures_.resize(model.textures.size());
  for (std::size_t i = 0; i < model.textures.size(); ++i) {
    const pfx::fx::TextureInfo& info = model.textures[i];
    if (info.semantic != pfx::fx::TextureSemantic::kNone) continue;
    if (!create_texture(info, textures_[i], error)) return log(PFX_LOG_ERROR, "texture '" + info.name + "': " + error), false;
    if (!info.source.empty() && !load_texture_file(info, entry_.file, textures_[i], error))
      return log(PFX_LOG_ERROR, "texture '" + info.name + "': " + error), false;
  }
  for (const pfx::fx::SamplerInfo& s : model.samplers) {
    std::size_t t = static_cast<std::size_t>(std::max(s.texture, 0));
    int levels = s.texture >= 0 && textures_[t].texture ? textures_[t].levels : 1;
    bool integer = s.texture >= 0 && pfx::fx::integer_class(model.textures[t].format) != 0;
    samplers_.push_back(create_sampler(s, levels, integer));
  }
  gl_current_ = true;
  return true;
}

const char* FxInstance::report_json() {
  char text[128];
  std::snprintf(text, sizeof text,
                "\"compile_ms\": %.3f, \"gl_build_ms\": %.3f, \"programs_from_cache\": %d, \"uniforms_as_constants\": %d",
                compile_ms_, gl_build_ms_ + programs_.build_ms(), programs_.cache_hits(), programs_.running().constant_count);
  report_ = text;
  return report_.c_str();
}

pfx_status FxInstance::run_pass(const pfx_pass_context* context) {
  if (!compiled_) return PFX_ERROR;
  if (context->pass_index == 0) reload_if_edited();  // hosts declare only on changes; runs are every frame
  if (!gl_current_ && !build_gl()) {
    release_gl();
    return PFX_GL_ERROR;
  }
  uint32_t index = context->pass_index;
  if (index == 0) {
    run_encode(*context);
    // After the uniforms took this frame's values: the programs the technique's passes run.
    std::string error;
    if (!programs_.choose(*compiled_, entry_.technique_index, uniforms_, &error)) {
      log(PFX_LOG_ERROR, error);
      release_gl();
      return PFX_GL_ERROR;
    }
  } else if (index + 1 == passes_.size() && layout_.output_pass < 0) {
    run_decode(*context);
  } else {
    run_fx_pass(static_cast<int>(index) - 1, *context);
  }
  return PFX_OK;
}

void FxInstance::run_encode(const pfx_pass_context& context) {
  bool depth = context.input_count > 1;
  std::vector<std::string> notes;
  const pfx_value* values = frame_params_.resolve(entry_.params, context.params, notes);
  for (const std::string& note : notes) log(PFX_LOG_WARNING, note);
  uniforms_.update(compiled_->model, entry_.params, values, *context.frame, depth);
  upload_uniforms();
  SavedTargets saved;
  if (depth) convert_depth(context);
  current_ = 0;
  draw_into(&back_buffer_[0].texture, 1, compiled_width_, compiled_height_);
  stencil_.clear(framebuffer_);  // the technique starts: zeros, as in ReShade
  // sRGB codes from a host of ABI 1.6: the technique samples the frame's own texture until a pass
  // writes the back buffer.
  leave_frame();
  if (layout_.samples_frame) {
    frame_color_ = context.inputs[0].texture;
    // The host's textures for a display-referred effect have immutable storage (pfx/effect.h): an
    // sRGB view of the frame decodes for the samplers that ask for it.
    if (layout_.srgb_frame_view) {
      glGenTextures(1, &frame_color_srgb_);
      glTextureView(frame_color_srgb_, GL_TEXTURE_2D, frame_color_, GL_SRGB8_ALPHA8, 0, 1, 0, 1);
    }
    return;
  }
  glUseProgram(encode_program_);  // unit 0: the frame's colour, bound by the host
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void FxInstance::convert_depth(const pfx_pass_context& context) {
  const pfx_frame& frame = *context.frame;
  draw_into(&fx_depth_.texture, 1, compiled_width_, compiled_height_);
  glProgramUniform1i(depth_program_, 0, static_cast<GLint>(frame.depth_encoding));
  glProgramUniform1f(depth_program_, 1, frame.camera.near_plane);
  glProgramUniform1f(depth_program_, 2, frame.camera.far_plane);
  glUseProgram(depth_program_);  // unit 1: the frame's depth, bound by the host
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void FxInstance::draw_into(const GLuint* textures, int count, int width, int height) {
  GLenum buffers[pfx::fx::kMaxRenderTargets];
  for (int i = 0; i < pfx::fx::kMaxRenderTargets; ++i) {
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), i < count ? textures[i] : 0, 0);
    buffers[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
  }
  glNamedFramebufferDrawBuffers(framebuffer_, count, buffers);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width, height);
}

void FxInstance::run_decode(const pfx_pass_context& context) {
  (void)context;  // the host bound the output, its viewport and the frame's colour on unit 0
  glBindTextureUnit(1, frame_color_ ? frame_color_ : back_buffer_[current_].texture);
  leave_frame();
  glUseProgram(decode_program_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

GLuint FxInstance::texture_for_sampler(const pfx::fx::SamplerInfo& sampler) const {
  if (sampler.texture < 0) return 0;
  const pfx::fx::TextureInfo& info = compiled_->model.textures[static_cast<std::size_t>(sampler.texture)];
  if (info.semantic == pfx::fx::TextureSemantic::kDepth) return fx_depth_.texture;
  if (info.semantic == pfx::fx::TextureSemantic::kColor && frame_color_)
    return sampler.srgb && frame_color_srgb_ ? frame_color_srgb_ : frame_color_;
  const GlTexture& t = info.semantic == pfx::fx::TextureSemantic::kColor ? back_buffer_[current_] : textures_[static_cast<std::size_t>(sampler.texture)];
  return sampler.srgb && t.srgb_view ? t.srgb_view : t.texture;
}

void FxInstance::bind_resources(const GeneratedPass& g, const PassProgram& p, int target_height) {
  const pfx::fx::EffectModel& model = compiled_->model;
  for (std::size_t unit = 0; unit < g.sampler_units.size(); ++unit) {
    const pfx::fx::SamplerInfo& s = model.samplers[static_cast<std::size_t>(g.sampler_units[unit])];
    glBindTextureUnit(static_cast<GLuint>(unit), texture_for_sampler(s));
    glBindSampler(static_cast<GLuint>(unit), samplers_[static_cast<std::size_t>(g.sampler_units[unit])]);
  }
  for (std::size_t unit = 0; unit < g.image_units.size(); ++unit) {
    const pfx::fx::StorageInfo& s = model.storages[static_cast<std::size_t>(g.image_units[unit])];
    const GlTexture& t = textures_[static_cast<std::size_t>(s.texture)];
    glBindImageTexture(static_cast<GLuint>(unit), t.texture, s.mip_level, t.target == GL_TEXTURE_3D ? GL_TRUE : GL_FALSE, 0, GL_READ_WRITE, t.internal);
  }
  if (uniform_buffer_) glBindBufferBase(GL_UNIFORM_BUFFER, pfx::fx::kUniformBlockBinding, uniform_buffer_);
  if (p.target_height_location >= 0) glProgramUniform1f(p.program, p.target_height_location, static_cast<float>(target_height));
}

void FxInstance::run_fx_pass(int index, const pfx_pass_context& context) {
  (void)context;
  const PassInfo& pass = technique().passes[static_cast<std::size_t>(index)];
  const GeneratedPass& g = programs_.running().generated[static_cast<std::size_t>(index)];
  const PassProgram& p = programs_.running().programs[static_cast<std::size_t>(index)];
  const pfx::fx::EffectModel& model = compiled_->model;
  if (!g.compute.empty()) {
    bind_resources(g, p, compiled_height_);
    glUseProgram(p.program);
    glDispatchCompute(static_cast<GLuint>(pass.dispatch[0]), static_cast<GLuint>(pass.dispatch[1]), static_cast<GLuint>(pass.dispatch[2]));
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    if (pass.generate_mipmaps)
      for (int unit : g.image_units) {
        const GlTexture& t = textures_[static_cast<std::size_t>(model.storages[static_cast<std::size_t>(unit)].texture)];
        if (t.levels > 1) glGenerateTextureMipmap(t.texture);
      }
    return;
  }
  if (index == layout_.output_pass) return draw_output(pass, g, p, context);
  SavedTargets saved;
  int count = std::max(1, pass.render_target_count);
  int width = compiled_width_, height = compiled_height_;
  GLuint targets[pfx::fx::kMaxRenderTargets];
  for (int i = 0; i < count; ++i) {
    const GlTexture& t = pass.render_target_count == 0 ? back_buffer_[1 - current_] : textures_[static_cast<std::size_t>(pass.render_targets[i])];
    targets[i] = pass.srgb_write && t.srgb_view ? t.srgb_view : t.texture;
    if (i == 0) width = t.width, height = t.height;
  }
  if (pass.render_target_count == 0 && !p.covers_target)
    glCopyImageSubData(back_buffer_[current_].texture, GL_TEXTURE_2D, 0, 0, 0, 0, back_buffer_[1 - current_].texture, GL_TEXTURE_2D, 0, 0, 0, 0,
                       compiled_width_, compiled_height_, 1);
  draw_into(targets, count, width, height);
  if (pass.clear_render_targets)
    for (int i = 0; i < count; ++i) {
      const GLuint zeros[4] = {0, 0, 0, 0};
      int integral = pass.render_target_count ? pfx::fx::integer_class(model.textures[static_cast<std::size_t>(pass.render_targets[i])].format) : 0;
      if (integral == 1) glClearNamedFramebufferiv(framebuffer_, GL_COLOR, i, reinterpret_cast<const GLint*>(zeros));
      else if (integral == 2) glClearNamedFramebufferuiv(framebuffer_, GL_COLOR, i, zeros);
      else glClearNamedFramebufferfv(framebuffer_, GL_COLOR, i, reinterpret_cast<const GLfloat*>(zeros));
    }
  if (pass.srgb_write) glEnable(GL_FRAMEBUFFER_SRGB);
  for (int i = 0; i < count; ++i) {
    const pfx::fx::BlendTarget& b = pass.blend[i];
    if (b.enable) {
      glEnablei(GL_BLEND, static_cast<GLuint>(i));
      glBlendEquationSeparatei(static_cast<GLuint>(i), gl_blend_op(b.color_op), gl_blend_op(b.alpha_op));
      glBlendFuncSeparatei(static_cast<GLuint>(i), gl_blend_factor(b.src), gl_blend_factor(b.dest), gl_blend_factor(b.src_alpha),
                           gl_blend_factor(b.dest_alpha));
    }
    glColorMaski(static_cast<GLuint>(i), b.write_mask & 1, (b.write_mask >> 1) & 1, (b.write_mask >> 2) & 1, (b.write_mask >> 3) & 1);
  }
  const bool stencil = stencil_.applies(pass, width, height);
  if (stencil) stencil_.begin(framebuffer_, pass.stencil);
  bind_resources(g, p, height);
  glUseProgram(p.program);
  glDrawArrays(gl_topology(pass.topology), 0, pass.vertex_count);
  if (stencil) stencil_.end(framebuffer_);
  // Put back what the GL state contract protects: blending off with (ADD, ONE, ONE), every
  // colour written, no sRGB encoding.
  for (int i = 0; i < count; ++i) {
    glDisablei(GL_BLEND, static_cast<GLuint>(i));
    glBlendEquationi(static_cast<GLuint>(i), GL_FUNC_ADD);
    glBlendFunci(static_cast<GLuint>(i), GL_ONE, GL_ONE);
    glColorMaski(static_cast<GLuint>(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  if (pass.srgb_write) glDisable(GL_FRAMEBUFFER_SRGB);
  if (pass.render_target_count == 0) {
    current_ = 1 - current_;
    leave_frame();  // the picture is in the back buffer from now on
    return;
  }
  if (pass.generate_mipmaps)
    for (int i = 0; i < pass.render_target_count; ++i) {
      const GlTexture& t = textures_[static_cast<std::size_t>(pass.render_targets[i])];
      if (t.levels > 1) glGenerateTextureMipmap(t.texture);
    }
}

void FxInstance::draw_output(const PassInfo& pass, const GeneratedPass& g, const PassProgram& p,
                             const pfx_pass_context& context) {
  // Into what the host bound, at the frame's size: the pass writes every pixel with no blending or
  // stencil, and its program encodes an sRGB write itself (fx_pass_layout), so none of the back
  // buffer's state applies.
  bind_resources(g, p, compiled_height_);
  const auto alpha_unit = static_cast<GLuint>(g.sampler_units.size());
  glBindTextureUnit(alpha_unit, context.inputs[0].texture);  // "color", as declared
  glBindSampler(alpha_unit, 0);                              // texelFetch: no filtering
  glUseProgram(p.program);
  glDrawArrays(gl_topology(pass.topology), 0, pass.vertex_count);
  leave_frame();
}

void FxInstance::leave_frame() {
  frame_color_ = 0;
  if (frame_color_srgb_) glDeleteTextures(1, &frame_color_srgb_);
  frame_color_srgb_ = 0;
}

}  // namespace pfx_fx
