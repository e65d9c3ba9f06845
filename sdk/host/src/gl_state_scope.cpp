#include "gl_state_scope.hpp"

#include <algorithm>

namespace pfx::host {
namespace {

// Capabilities and the value every chain starts from: GL's initial value, except dithering, which
// is off so that 8-bit targets get the same bits on every implementation.
struct Capability {
  GLenum cap;
  GLboolean chain_value;
};
const Capability kCapabilities[] = {
    {GL_DEPTH_TEST, GL_FALSE},
    {GL_STENCIL_TEST, GL_FALSE},
    {GL_CULL_FACE, GL_FALSE},
    {GL_RASTERIZER_DISCARD, GL_FALSE},
    {GL_COLOR_LOGIC_OP, GL_FALSE},
    {GL_FRAMEBUFFER_SRGB, GL_FALSE},
    {GL_MULTISAMPLE, GL_TRUE},
    {GL_SAMPLE_ALPHA_TO_COVERAGE, GL_FALSE},
    {GL_SAMPLE_ALPHA_TO_ONE, GL_FALSE},
    {GL_SAMPLE_COVERAGE, GL_FALSE},
    {GL_SAMPLE_MASK, GL_FALSE},
    {GL_SAMPLE_SHADING, GL_FALSE},
    {GL_PRIMITIVE_RESTART, GL_FALSE},
    {GL_PRIMITIVE_RESTART_FIXED_INDEX, GL_FALSE},
    {GL_DEPTH_CLAMP, GL_FALSE},
    {GL_POLYGON_OFFSET_FILL, GL_FALSE},
    {GL_POLYGON_OFFSET_LINE, GL_FALSE},
    {GL_POLYGON_OFFSET_POINT, GL_FALSE},
    {GL_POLYGON_SMOOTH, GL_FALSE},
    {GL_LINE_SMOOTH, GL_FALSE},
    {GL_PROGRAM_POINT_SIZE, GL_FALSE},
    {GL_DITHER, GL_FALSE},
    {GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_FALSE},
};

// Single integer values: each with the value every chain starts from and the call that sets it.
struct IntegerState {
  GLenum pname;
  GLint chain_value;
  void (*set)(GLenum pname, GLint value);
};
GLenum as_enum(GLint value) { return static_cast<GLenum>(value); }
// The pixel store, for plugins that upload or read back from client memory.
void set_pixel_store(GLenum pname, GLint value) { glPixelStorei(pname, value); }
const IntegerState kIntegers[] = {
    {GL_CULL_FACE_MODE, GL_BACK, [](GLenum, GLint v) { glCullFace(as_enum(v)); }},
    {GL_FRONT_FACE, GL_CCW, [](GLenum, GLint v) { glFrontFace(as_enum(v)); }},
    {GL_PROVOKING_VERTEX, GL_LAST_VERTEX_CONVENTION, [](GLenum, GLint v) { glProvokingVertex(as_enum(v)); }},
    {GL_DEPTH_FUNC, GL_LESS, [](GLenum, GLint v) { glDepthFunc(as_enum(v)); }},
    {GL_DEPTH_WRITEMASK, GL_TRUE, [](GLenum, GLint v) { glDepthMask(v ? GL_TRUE : GL_FALSE); }},
    {GL_STENCIL_CLEAR_VALUE, 0, [](GLenum, GLint v) { glClearStencil(v); }},
    {GL_CLAMP_READ_COLOR, GL_FIXED_ONLY, [](GLenum pname, GLint v) { glClampColor(pname, as_enum(v)); }},
    {GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_DONT_CARE, [](GLenum pname, GLint v) { glHint(pname, as_enum(v)); }},
    {GL_PATCH_VERTICES, 3, [](GLenum pname, GLint v) { glPatchParameteri(pname, v); }},
    {GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT, [](GLenum pname, GLint v) { glPointParameteri(pname, v); }},
    {GL_UNPACK_SWAP_BYTES, GL_FALSE, set_pixel_store},
    {GL_UNPACK_LSB_FIRST, GL_FALSE, set_pixel_store},
    {GL_UNPACK_ROW_LENGTH, 0, set_pixel_store},
    {GL_UNPACK_IMAGE_HEIGHT, 0, set_pixel_store},
    {GL_UNPACK_SKIP_ROWS, 0, set_pixel_store},
    {GL_UNPACK_SKIP_PIXELS, 0, set_pixel_store},
    {GL_UNPACK_SKIP_IMAGES, 0, set_pixel_store},
    {GL_UNPACK_ALIGNMENT, 4, set_pixel_store},
    {GL_UNPACK_COMPRESSED_BLOCK_WIDTH, 0, set_pixel_store},
    {GL_UNPACK_COMPRESSED_BLOCK_HEIGHT, 0, set_pixel_store},
    {GL_UNPACK_COMPRESSED_BLOCK_DEPTH, 0, set_pixel_store},
    {GL_UNPACK_COMPRESSED_BLOCK_SIZE, 0, set_pixel_store},
    {GL_PACK_SWAP_BYTES, GL_FALSE, set_pixel_store},
    {GL_PACK_LSB_FIRST, GL_FALSE, set_pixel_store},
    {GL_PACK_ROW_LENGTH, 0, set_pixel_store},
    {GL_PACK_IMAGE_HEIGHT, 0, set_pixel_store},
    {GL_PACK_SKIP_ROWS, 0, set_pixel_store},
    {GL_PACK_SKIP_PIXELS, 0, set_pixel_store},
    {GL_PACK_SKIP_IMAGES, 0, set_pixel_store},
    {GL_PACK_ALIGNMENT, 4, set_pixel_store},
    {GL_PACK_COMPRESSED_BLOCK_WIDTH, 0, set_pixel_store},
    {GL_PACK_COMPRESSED_BLOCK_HEIGHT, 0, set_pixel_store},
    {GL_PACK_COMPRESSED_BLOCK_DEPTH, 0, set_pixel_store},
    {GL_PACK_COMPRESSED_BLOCK_SIZE, 0, set_pixel_store},
};

// Single float values, likewise.
struct FloatState {
  GLenum pname;
  GLfloat chain_value;
  void (*set)(GLenum pname, GLfloat value);
};
const FloatState kFloats[] = {
    {GL_POINT_SIZE, 1.0f, [](GLenum, GLfloat v) { glPointSize(v); }},
    {GL_LINE_WIDTH, 1.0f, [](GLenum, GLfloat v) { glLineWidth(v); }},
    {GL_POINT_FADE_THRESHOLD_SIZE, 1.0f, [](GLenum pname, GLfloat v) { glPointParameterf(pname, v); }},
};

// Clip origin and depth mode are two values that one call (glClipControl) sets together.
constexpr ClipControl kChainClipControl = {GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE};
void set_clip_control(const ClipControl& clip) {
  glClipControl(static_cast<GLenum>(clip.origin), static_cast<GLenum>(clip.depth_mode));
}

// Where each saved blend and stencil value comes from.
struct BlendValue {
  GLenum pname;
  GLint BlendState::*field;
};
const BlendValue kBlendValues[] = {
    {GL_BLEND_EQUATION_RGB, &BlendState::equation_rgb}, {GL_BLEND_EQUATION_ALPHA, &BlendState::equation_alpha},
    {GL_BLEND_SRC_RGB, &BlendState::src_rgb},           {GL_BLEND_DST_RGB, &BlendState::dst_rgb},
    {GL_BLEND_SRC_ALPHA, &BlendState::src_alpha},       {GL_BLEND_DST_ALPHA, &BlendState::dst_alpha},
};
struct StencilValue {
  GLenum front, back;
  GLint StencilFace::*field;
};
const StencilValue kStencilValues[] = {
    {GL_STENCIL_FUNC, GL_STENCIL_BACK_FUNC, &StencilFace::func},
    {GL_STENCIL_REF, GL_STENCIL_BACK_REF, &StencilFace::ref},
    {GL_STENCIL_VALUE_MASK, GL_STENCIL_BACK_VALUE_MASK, &StencilFace::value_mask},
    {GL_STENCIL_FAIL, GL_STENCIL_BACK_FAIL, &StencilFace::fail},
    {GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_BACK_PASS_DEPTH_FAIL, &StencilFace::depth_fail},
    {GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_BACK_PASS_DEPTH_PASS, &StencilFace::depth_pass},
    {GL_STENCIL_WRITEMASK, GL_STENCIL_BACK_WRITEMASK, &StencilFace::write_mask},
};

void restore_stencil(GLenum face, const StencilFace& s) {
  glStencilFuncSeparate(face, as_enum(s.func), s.ref, static_cast<GLuint>(s.value_mask));
  glStencilOpSeparate(face, as_enum(s.fail), as_enum(s.depth_fail), as_enum(s.depth_pass));
  glStencilMaskSeparate(face, static_cast<GLuint>(s.write_mask));
}

void set_capability(GLenum cap, GLboolean on) {
  if (on) glEnable(cap);
  else glDisable(cap);
}

void set_capability(GLenum cap, GLuint index, GLboolean on) {
  if (on) glEnablei(cap, index);
  else glDisablei(cap, index);
}

}  // namespace

GlLimits GlLimits::query() {
  GlLimits limits;
  auto get = [](GLenum pname) {
    GLint v = 0;
    glGetIntegerv(pname, &v);
    return v;
  };
  limits.compatibility_profile = (get(GL_CONTEXT_PROFILE_MASK) & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
  limits.viewports = std::max(1, get(GL_MAX_VIEWPORTS));
  limits.draw_buffers = std::max(1, get(GL_MAX_DRAW_BUFFERS));
  limits.clip_distances = get(GL_MAX_CLIP_DISTANCES);
  limits.texture_units = std::min(kFreeTextureUnits, get(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS));
  limits.image_units = std::min(kFreeImageUnits, get(GL_MAX_IMAGE_UNITS));
  limits.uniform_buffers = std::min(kFreeUniformBuffers, get(GL_MAX_UNIFORM_BUFFER_BINDINGS));
  limits.storage_buffers = std::min(kFreeStorageBuffers, get(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS));
  limits.atomic_buffers = std::min(kFreeAtomicBuffers, get(GL_MAX_ATOMIC_COUNTER_BUFFER_BINDINGS));
  limits.feedback_buffers = get(GL_MAX_TRANSFORM_FEEDBACK_BUFFERS);
  return limits;
}

GlStateScope::GlStateScope(const GlLimits& limits, Mode mode) : limits_(limits), mode_(mode) {
  if (mode_ == SAVE) save();
  set_chain_state();
  // The fixed-function items are only saved and turned off; a host holding a guard has them off.
  if (mode_ == SAVE && limits_.compatibility_profile) legacy_ = std::make_unique<LegacyStateScope>(true);
}

GlStateScope::~GlStateScope() {
  if (mode_ == SAVE) restore();
}

void GlStateScope::save() {
  for (const Capability& c : kCapabilities) enables_.push_back(glIsEnabled(c.cap));
  for (GLint i = 0; i < limits_.clip_distances; ++i)
    clip_distances_.push_back(glIsEnabled(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i)));
  for (GLint i = 0; i < limits_.draw_buffers; ++i) {
    const GLuint b = static_cast<GLuint>(i);
    blend_enabled_.push_back(glIsEnabledi(GL_BLEND, b));
    BlendState blend{};
    for (const BlendValue& value : kBlendValues) glGetIntegeri_v(value.pname, b, &(blend.*value.field));
    blend_.push_back(blend);
    std::array<GLboolean, 4> mask{};
    glGetBooleani_v(GL_COLOR_WRITEMASK, b, mask.data());
    color_masks_.push_back(mask);
  }
  for (GLint i = 0; i < limits_.viewports; ++i) {
    const GLuint v = static_cast<GLuint>(i);
    scissor_enabled_.push_back(glIsEnabledi(GL_SCISSOR_TEST, v));
    std::array<GLfloat, 4> viewport{};
    glGetFloati_v(GL_VIEWPORT, v, viewport.data());
    viewports_.push_back(viewport);
    std::array<GLdouble, 2> range{};
    glGetDoublei_v(GL_DEPTH_RANGE, v, range.data());
    depth_ranges_.push_back(range);
  }
  for (const IntegerState& s : kIntegers) {
    GLint v[4] = {0, 0, 0, 0};
    glGetIntegerv(s.pname, v);
    integers_.push_back(v[0]);
  }
  for (const FloatState& s : kFloats) {
    GLfloat v[4] = {0, 0, 0, 0};
    glGetFloatv(s.pname, v);
    floats_.push_back(v[0]);
  }
  glGetIntegerv(GL_CLIP_ORIGIN, &clip_control_.origin);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clip_control_.depth_mode);
  glGetIntegerv(GL_POLYGON_MODE, polygon_mode_);
  for (const StencilValue& value : kStencilValues) {
    glGetIntegerv(value.front, &(stencil_front_.*value.field));
    glGetIntegerv(value.back, &(stencil_back_.*value.field));
  }
  glGetFloatv(GL_BLEND_COLOR, blend_color_);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear_color_);
  glGetDoublev(GL_DEPTH_CLEAR_VALUE, &clear_depth_);
  bindings_.save(limits_);
}

void GlStateScope::set_chain_state() const {
  for (const Capability& c : kCapabilities) set_capability(c.cap, c.chain_value);
  for (GLint i = 0; i < limits_.clip_distances; ++i) glDisable(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i));
  // The unindexed calls set every draw buffer and every viewport.
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthRange(0.0, 1.0);
  for (const IntegerState& s : kIntegers) s.set(s.pname, s.chain_value);
  for (const FloatState& s : kFloats) s.set(s.pname, s.chain_value);
  set_clip_control(kChainClipControl);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glStencilFunc(GL_ALWAYS, 0, ~0u);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(~0u);
  glBlendColor(0, 0, 0, 0);
  glClearColor(0, 0, 0, 0);
  glClearDepth(1.0);
  bindings_.set_clean(limits_);
}

void GlStateScope::restore() const {
  bindings_.restore();
  for (size_t i = 0; i < enables_.size(); ++i) set_capability(kCapabilities[i].cap, enables_[i]);
  for (size_t i = 0; i < clip_distances_.size(); ++i)
    set_capability(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i), clip_distances_[i]);
  for (size_t i = 0; i < blend_.size(); ++i) {
    const GLuint b = static_cast<GLuint>(i);
    const BlendState& e = blend_[i];
    set_capability(GL_BLEND, b, blend_enabled_[i]);
    glBlendEquationSeparatei(b, as_enum(e.equation_rgb), as_enum(e.equation_alpha));
    glBlendFuncSeparatei(b, as_enum(e.src_rgb), as_enum(e.dst_rgb), as_enum(e.src_alpha), as_enum(e.dst_alpha));
    const auto& m = color_masks_[i];
    glColorMaski(b, m[0], m[1], m[2], m[3]);
  }
  for (size_t i = 0; i < viewports_.size(); ++i) {
    const GLuint v = static_cast<GLuint>(i);
    set_capability(GL_SCISSOR_TEST, v, scissor_enabled_[i]);
    glViewportIndexedfv(v, viewports_[i].data());
    glDepthRangeIndexed(v, depth_ranges_[i][0], depth_ranges_[i][1]);
  }
  for (size_t i = 0; i < integers_.size(); ++i) kIntegers[i].set(kIntegers[i].pname, integers_[i]);
  for (size_t i = 0; i < floats_.size(); ++i) kFloats[i].set(kFloats[i].pname, floats_[i]);
  set_clip_control(clip_control_);
  glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygon_mode_[0]));
  restore_stencil(GL_FRONT, stencil_front_);
  restore_stencil(GL_BACK, stencil_back_);
  glBlendColor(blend_color_[0], blend_color_[1], blend_color_[2], blend_color_[3]);
  glClearColor(clear_color_[0], clear_color_[1], clear_color_[2], clear_color_[3]);
  glClearDepth(clear_depth_);
}

}  // namespace pfx::host
