#include "lr_instance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <pfx/cpp/gl_program.hpp>

#include "content_size.hpp"
#include "lr_glsl_pass.hpp"
#include "lr_uniform_values.hpp"

namespace pfx_libretro {

using namespace pfx::libretro;

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The vertices slang shaders read (location 0: vec4 Position, location 1: vec2 TexCoord), as
// RetroArch gives them: a quad over -1..1 for a pass into a texture of the chain (MVP the
// identity), over 0..1 for the pass into the output (MVP the projection below). TexCoord (0, 0) is
// the picture's top left in both.
constexpr float kVertices[] = {
    -1, -1, 0, 1, 0, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 1, 0, 1, 1, 1, 0, 1, 1, 1,  // into a texture
    0,  0,  0, 1, 0, 0, 1, 0,  0, 1, 1, 0, 0,  1, 0, 1, 0, 1, 1, 1, 0, 1, 1, 1,  // into the output
};
constexpr float kIdentity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
// Position (x, y) in 0..1 to clip (2x - 1, 1 - 2y): y = 0 at the output's top, since GL counts
// its rows from the bottom.
constexpr float kOutputMvp[16] = {2, 0, 0, 0, 0, -2, 0, 0, 0, 0, 1, 0, -1, 1, 0, 1};
// The GLSL form's MVPMatrix: RetroArch's orthographic projection of 0..1 (near -1, far 1), for
// every pass. Into a texture, y = 0 lands on its first row (the picture's top); into the output
// (bottom row first) the output pass's VertexCoord has y = 1 at the picture's top, as
// glsl_vertex_data() says, so the same matrix puts the top on top.
constexpr float kGlslMvp[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, -1, 0, -1, -1, 0, 1};

// The host's frame (bottom row first) into the original picture (top row first), each texel the
// average of taps x taps bilinear samples over its footprint: an exact copy at the same size.
constexpr const char* kContentShader = R"(#version 450 core
layout(binding = 0) uniform sampler2D frame;
layout(location = 0) uniform ivec2 taps;
layout(location = 1) uniform vec2 content_size;
layout(location = 0) out vec4 color;
void main() {
  vec4 sum = vec4(0.0);
  for (int j = 0; j < taps.y; ++j)
    for (int i = 0; i < taps.x; ++i) {
      vec2 at = (floor(gl_FragCoord.xy) + (vec2(i, j) + 0.5) / vec2(taps)) / content_size;
      sum += texture(frame, vec2(at.x, 1.0 - at.y));
    }
  color = sum / float(taps.x * taps.y);
}
)";

// The last pass's texture (top row first) stretched over the output (bottom row first).
constexpr const char* kFinishShader = R"(#version 450 core
layout(binding = 0) uniform sampler2D picture;
layout(location = 0) uniform vec2 output_size;
layout(location = 0) out vec4 color;
void main() {
  vec2 at = gl_FragCoord.xy / output_size;
  color = texture(picture, vec2(at.x, 1.0 - at.y));
}
)";

// What a pass changes of the state the ABI protects, put back when it returns.
class KeptState {
 public:
  // `units`: texture units beyond the ones the ABI leaves free that the pass binds (filled while it runs).
  explicit KeptState(std::vector<GLuint>& units) : high_units_(units) {
    high_units_.clear();
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
    srgb_ = glIsEnabled(GL_FRAMEBUFFER_SRGB);
  }
  ~KeptState() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glBindVertexArray(static_cast<GLuint>(vertex_array_));
    if (srgb_)
      glEnable(GL_FRAMEBUFFER_SRGB);
    else
      glDisable(GL_FRAMEBUFFER_SRGB);
    for (GLuint unit : high_units_) {  // beyond the units the ABI leaves free
      glBindTextureUnit(unit, 0);
      glBindSampler(unit, 0);
    }
  }

 private:
  GLint draw_ = 0, read_ = 0, viewport_[4] = {0, 0, 0, 0}, vertex_array_ = 0;
  GLboolean srgb_ = GL_FALSE;
  std::vector<GLuint>& high_units_;
};

}  // namespace

LrInstance::~LrInstance() {
  release_pass_programs(passes_);
  textures_.release();
  if (vao_) glDeleteVertexArrays(1, &vao_);
  if (vertices_) glDeleteBuffers(1, &vertices_);
  if (glsl_vertices_) glDeleteBuffers(1, &glsl_vertices_);
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (content_program_) glDeleteProgram(content_program_);
  if (finish_program_) glDeleteProgram(finish_program_);
}

void LrInstance::log(pfx_log_level level, const std::string& message) const {
  host_->log(host_->host_data, level, ("libretro: " + entry_.id + ": " + message).c_str());
}

pfx_status LrInstance::create() {
  if (host_->abi_minor < 6) {
    log(PFX_LOG_ERROR, "needs a host of pfx ABI 1.6 or later, which hands display-referred frames (this one is 1." +
                           std::to_string(host_->abi_minor) + ")");
    return PFX_UNSUPPORTED;
  }
  if (!pfx::gl::load_gl_or_log(host_, "libretro")) return PFX_GL_ERROR;
  for (const std::string& warning : entry_.warnings) log(PFX_LOG_WARNING, warning);
  std::string error;
  Clock::time_point start = Clock::now();
  if (!compile_passes(entry_, &passes_, &error)) {
    log(PFX_LOG_ERROR, error);
    return PFX_ERROR;
  }
  compile_ms_ = ms_since(start);
  start = Clock::now();
  const std::vector<float>& glsl_vertices = glsl_vertex_data();
  glCreateBuffers(1, &glsl_vertices_);
  glNamedBufferStorage(glsl_vertices_, static_cast<GLsizeiptr>(glsl_vertices.size() * sizeof(float)),
                       glsl_vertices.data(), 0);
  const pfx::gl::ProgramCache cache = libretro_program_cache();
  // GLSL passes first: what they read is known once linked.
  if (!link_glsl_passes(entry_, passes_, glsl_vertices_, cache, &programs_from_cache_, &error)) {
    log(PFX_LOG_ERROR, error);
    return PFX_ERROR;
  }
  std::vector<std::string> formats;
  std::vector<PassInterface> reads;
  for (const LrPass& pass : passes_) formats.push_back(pass.format), reads.push_back(pass.reads);
  plan_ = plan_chain(entry_.preset, formats, reads);
  const bool last_to_output = !plan_.passes.empty() && plan_.passes.back().to_output;
  if (!build_pass_programs(passes_, last_to_output, cache, &programs_from_cache_, &error) ||
      !(content_program_ = pfx::gl::build_fullscreen_program(kContentShader, &error)) ||
      !(finish_program_ = pfx::gl::build_fullscreen_program(kFinishShader, &error))) {
    log(PFX_LOG_ERROR, error);
    return PFX_GL_ERROR;
  }
  if (!textures_.load_lookups(entry_.preset, &error)) {
    log(PFX_LOG_ERROR, error);
    return PFX_ERROR;
  }
  for (std::size_t i = 0; i < entry_.preset.textures.size(); ++i)
    lookup_sizes_.push_back(textures_.lookup_size(static_cast<int>(i)));
  gl_build_ms_ = ms_since(start);
  glCreateBuffers(1, &vertices_);
  glNamedBufferStorage(vertices_, sizeof(kVertices), kVertices, 0);
  glCreateVertexArrays(1, &vao_);
  glVertexArrayVertexBuffer(vao_, 0, vertices_, 0, 6 * sizeof(float));
  glEnableVertexArrayAttrib(vao_, 0);
  glEnableVertexArrayAttrib(vao_, 1);
  glVertexArrayAttribFormat(vao_, 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribFormat(vao_, 1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float));
  glVertexArrayAttribBinding(vao_, 0, 0);
  glVertexArrayAttribBinding(vao_, 1, 0);
  glCreateFramebuffers(1, &framebuffer_);
  return PFX_OK;
}

pfx_status LrInstance::declare(const pfx_frame* frame, const pfx_value* params, pfx_declaration* out) {
  const LrParameters& p = entry_.params;
  const PixelSize viewport{static_cast<int>(std::min<uint32_t>(frame->width, kMaxTextureSide)),
                           static_cast<int>(std::min<uint32_t>(frame->height, kMaxTextureSide))};
  const PixelSize content = content_size(viewport, static_cast<int>(params[p.content_width].v[0]),
                                         static_cast<int>(params[p.content_height].v[0]));
  std::vector<PixelSize> sizes = pass_sizes(entry_.preset, plan_, content, viewport);
  if (viewport != viewport_ || content != content_ || sizes != sizes_) remake_ = true;
  viewport_ = viewport, content_ = content, sizes_ = std::move(sizes);
  values_.resize(p.shader_ids.size());
  for (std::size_t k = 0; k < values_.size(); ++k)
    values_[k] = p.descriptor[k] >= 0 ? params[p.descriptor[k]].v[0] : p.fixed[k];

  pass_names_ = {"content"};
  for (std::size_t i = 0; i < passes_.size(); ++i) {
    const std::string& alias = entry_.preset.passes[i].alias.empty() ? passes_[i].name : entry_.preset.passes[i].alias;
    pass_names_.push_back(alias.empty() ? "pass" + std::to_string(i) : alias);
  }
  if (plan_.finish) pass_names_.push_back("finish");
  color_input_ = {PFX_INPUT_NAME_COLOR, PFX_FILTER_LINEAR, PFX_WRAP_CLAMP_TO_EDGE};
  pass_descs_.clear();
  for (std::size_t i = 0; i < pass_names_.size(); ++i) {
    pfx_pass_desc d{};
    d.struct_size = sizeof(pfx_pass_desc);
    d.name = pass_names_[i].c_str();
    d.kind = PFX_PASS_CUSTOM;
    d.user_tag = static_cast<uint32_t>(i);
    if (i == 0) d.inputs = &color_input_, d.input_count = 1;
    if (i + 1 == pass_names_.size()) d.output = PFX_OUTPUT_NAME;
    pass_descs_.push_back(d);
  }
  out->passes = pass_descs_.data();
  out->pass_count = static_cast<uint32_t>(pass_descs_.size());
  if (PFX_STRUCT_HAS(out, pfx_declaration, flags))
    out->flags |= PFX_DECLARATION_SAMPLES_AND_DRAWS | PFX_DECLARATION_DISPLAY_REFERRED;
  return PFX_OK;
}

pfx_status LrInstance::run_pass(const pfx_pass_context* context) {
  if (passes_.empty() || context->user_tag >= pass_descs_.size()) return PFX_INVALID_ARGUMENT;
  KeptState kept(high_units_);
  const uint32_t tag = context->user_tag;
  if (tag == 0)
    run_content(*context);
  else if (tag <= passes_.size())
    run_preset_pass(static_cast<int>(tag - 1));
  else
    run_finish(*context);
  return PFX_OK;
}

void LrInstance::draw_into(GLuint texture, PixelSize size, bool srgb) {
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, size.width, size.height);
  if (srgb)
    glEnable(GL_FRAMEBUFFER_SRGB);
  else
    glDisable(GL_FRAMEBUFFER_SRGB);
}

void LrInstance::run_content(const pfx_pass_context& context) {
  textures_.upload_lookups();
  if (remake_ || !textures_.made()) {
    textures_.make(plan_, content_, sizes_);
    remake_ = false;
  } else {
    textures_.advance();
  }
  const pfx_frame& frame = *context.frame;
  frame_count_ = static_cast<std::uint32_t>(frame.frame_index);
  const double delta = last_time_ >= 0 ? frame.time_seconds - last_time_ : 0;
  if (delta > 0 && delta < 10) {
    frame_time_delta_us_ = static_cast<std::uint32_t>(std::lround(delta * 1e6));
    fps_ = static_cast<float>(std::min(1.0 / delta, 1000.0));
  }
  last_time_ = frame.time_seconds;

  draw_into(textures_.original(0), content_, false);
  glUseProgram(content_program_);
  const GLint taps_x = std::clamp(static_cast<int>(std::ceil(static_cast<double>(viewport_.width) / content_.width)), 1,
                                  8);
  const GLint taps_y = std::clamp(static_cast<int>(std::ceil(static_cast<double>(viewport_.height) / content_.height)),
                                  1, 8);
  glUniform2i(0, taps_x, taps_y);
  glUniform2f(1, static_cast<float>(content_.width), static_cast<float>(content_.height));
  glBindTextureUnit(0, context.inputs[0].texture);  // sampled as the host bound it, by its sampler
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (textures_.original_levels() > 1) glGenerateTextureMipmap(textures_.original(0));
}

GLuint LrInstance::sampler_for(int settings_pass, bool integer) {
  const PresetPass& pass = entry_.preset.passes[static_cast<std::size_t>(settings_pass)];
  // No filter_linearN: nearest, RetroArch's default for its "bilinear filtering" setting.
  const bool linear = !integer && pass.filter_linear.value_or(false);
  return textures_.sampler(linear, pass.wrap, !integer && pass.mipmap_input);
}

void LrInstance::bind_samplers(int index) {
  const int last = static_cast<int>(passes_.size()) - 1;
  for (const ReflectedSampler& s : passes_[static_cast<std::size_t>(index)].reads.samplers) {
    GLuint texture = 0, sampler = 0;
    const int k = s.semantic.index;
    switch (s.semantic.kind) {
      case SemanticKind::kOriginal:
      case SemanticKind::kOriginalHistory:
        texture = textures_.original(s.semantic.kind == SemanticKind::kOriginal ? 0 : k);
        sampler = sampler_for(0, false);
        break;
      case SemanticKind::kSource:
        texture = index == 0 ? textures_.original(0) : textures_.pass_output(index - 1);
        sampler = sampler_for(index,
                              index > 0 && is_integer_format(plan_.passes[static_cast<std::size_t>(index - 1)].format));
        break;
      case SemanticKind::kPassOutput:
        texture = textures_.pass_output(k);
        sampler = sampler_for(std::min(k + 1, last),
                              is_integer_format(plan_.passes[static_cast<std::size_t>(k)].format));
        break;
      case SemanticKind::kPassFeedback: {
        texture = textures_.pass_feedback(k);
        const PresetPass& own = entry_.preset.passes[static_cast<std::size_t>(k)];
        const bool integer = is_integer_format(plan_.passes[static_cast<std::size_t>(k)].format);
        sampler = textures_.sampler(!integer && own.filter_linear.value_or(false), own.wrap, false);
        break;
      }
      case SemanticKind::kUser: {
        const LookupTexture& lookup = entry_.preset.textures[static_cast<std::size_t>(k)];
        texture = textures_.lookup(k);
        // No ID_linear: linear, as RetroArch's glcore and Vulkan drivers load lookup textures.
        sampler = textures_.sampler(lookup.linear.value_or(true), lookup.wrap, lookup.mipmap);
        break;
      }
      default:
        break;
    }
    glBindTextureUnit(s.binding, texture);
    glBindSampler(s.binding, sampler);
    if (s.binding >= 16) high_units_.push_back(s.binding);
  }
}

void LrInstance::update_block(const ReflectedBlock& block, const PassValues& values, GLuint buffer,
                              std::vector<unsigned char>& uploaded) {
  // A still picture with still parameters gives the same values every frame: upload only a change.
  // `uploaded` starts as the buffer was made (zeros), so it always holds what the buffer holds.
  scratch_ = uploaded;
  write_block_values(block, values, scratch_);
  if (scratch_ == uploaded) return;
  uploaded.swap(scratch_);
  glNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(uploaded.size()), uploaded.data());
}

void LrInstance::run_preset_pass(int index) {
  LrPass& pass = passes_[static_cast<std::size_t>(index)];
  const PassPlan& plan = plan_.passes[static_cast<std::size_t>(index)];
  const PresetPass& preset_pass = entry_.preset.passes[static_cast<std::size_t>(index)];
  if (!plan.to_output)
    draw_into(textures_.pass_output(index), sizes_[static_cast<std::size_t>(index)], plan.format == "R8G8B8A8_SRGB");
  // else: the host bound its output and viewport, and left sRGB encoding off (display-referred).

  PassValues values;
  if (pass.glsl)
    values.mvp = kGlslMvp;
  else
    values.mvp = plan.to_output ? kOutputMvp : kIdentity;
  values.output = sizes_[static_cast<std::size_t>(index)];
  values.source = index == 0 ? content_ : sizes_[static_cast<std::size_t>(index - 1)];
  values.original = content_;
  values.viewport = viewport_;
  values.pass_sizes = &sizes_;
  values.lookup_sizes = &lookup_sizes_;
  values.parameters = &values_;
  values.frame_count = preset_pass.frame_count_mod ? frame_count_ % preset_pass.frame_count_mod : frame_count_;
  values.frame_time_delta_us = frame_time_delta_us_;
  values.original_fps = fps_;
  if (pass.uniform_buffer) {
    update_block(pass.reads.uniforms, values, pass.uniform_buffer, pass.uniform_bytes);
    glBindBufferBase(GL_UNIFORM_BUFFER, pass.reads.uniforms.binding, pass.uniform_buffer);
  }
  if (pass.push_buffer) {
    update_block(pass.reads.push, values, pass.push_buffer, pass.push_bytes);
    glBindBufferBase(GL_UNIFORM_BUFFER, pass.code.push_binding, pass.push_buffer);
  }
  if (pass.glsl) set_glsl_values(pass, values);
  bind_samplers(index);
  glUseProgram(pass.program);
  glBindVertexArray(pass.glsl ? pass.glsl_vao : vao_);
  glDrawArrays(GL_TRIANGLE_STRIP, plan.to_output ? 4 : 0, 4);  // each vertex buffer's second strip: onto the output
  if (plan.mipmapped) glGenerateTextureMipmap(textures_.pass_output(index));
}

void LrInstance::run_finish(const pfx_pass_context& context) {
  glUseProgram(finish_program_);
  glUniform2f(0, static_cast<float>(context.output_width), static_cast<float>(context.output_height));
  glBindTextureUnit(0, textures_.pass_output(static_cast<int>(passes_.size()) - 1));
  // Stretched as RetroArch's stock pass does: linear, clamped to the edge.
  glBindSampler(0, textures_.sampler(true, WrapMode::kClampToEdge, false));
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

const char* LrInstance::report_json() {
  char text[256];
  std::snprintf(text, sizeof text,
                "\"passes\": %zu, \"compile_ms\": %.1f, \"gl_build_ms\": %.1f, \"programs_from_cache\": %d, "
                "\"texture_bytes\": %zu",
                passes_.size(), compile_ms_, gl_build_ms_, programs_from_cache_, textures_.bytes());
  report_ = text;
  return report_.c_str();
}

}  // namespace pfx_libretro
