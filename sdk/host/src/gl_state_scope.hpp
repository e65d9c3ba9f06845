// The GL state a chain runs under (docs/sdk.md §1.5): the engine's values are saved, the chain's
// starting values set, and the engine's put back when the scope ends, so that render() neither
// depends on nor disturbs what the embedding engine left in its context.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include <glad/gl.h>

#include "legacy_state.hpp"

namespace pfx::host {

// How many indexed items of each kind are saved, set and restored: the implementation's maximum
// for those GL keeps per viewport or draw buffer, and the contract's numbers (docs/sdk.md §1.5)
// for the binding points a plugin may use freely. Queried once per chain.
struct GlLimits {
  GLint viewports = 1, draw_buffers = 1, clip_distances = 0;
  bool compatibility_profile = false;  // fixed-function state still applies (LegacyStateScope)
  GLint texture_units = 0, image_units = 0, uniform_buffers = 0, storage_buffers = 0, atomic_buffers = 0,
        feedback_buffers = 0;
  static GlLimits query();
};

// The contract's binding points a plugin may use without restoring them (clamped to what the
// implementation has). GL 4.5 guarantees at least these many of each.
constexpr GLint kFreeTextureUnits = 16;
constexpr GLint kFreeImageUnits = 8;
constexpr GLint kFreeUniformBuffers = 16;
constexpr GLint kFreeStorageBuffers = 8;
constexpr GLint kFreeAtomicBuffers = 1;

// Every binding the chain or a plugin may change: framebuffers, vertex array, program, texture
// and sampler units, image units, indexed and generic buffer bindings, transform feedback.
class GlBindings {
 public:
  void save(const GlLimits& limits);
  // Unbinds what could reach a plugin by accident (textures, samplers, images and buffers of the
  // free binding points, pixel and query buffers) and binds the default transform feedback.
  void set_clean(const GlLimits& limits) const;
  void restore() const;

 private:
  struct IndexedBuffer {
    GLint name = 0;
    GLint64 start = 0, size = 0;
  };
  struct ImageUnit {
    GLint name = 0, level = 0, layered = 0, layer = 0, access = GL_READ_ONLY, format = GL_R8;
  };
  static constexpr int kTargetsPerUnit = 11;  // the texture targets gl_bindings.cpp lists
  GLint draw_framebuffer_ = 0, read_framebuffer_ = 0, renderbuffer_ = 0;
  GLint vertex_array_ = 0, program_ = 0, pipeline_ = 0, active_texture_ = GL_TEXTURE0;
  GLint transform_feedback_ = 0;
  std::vector<std::array<GLint, kTargetsPerUnit>> textures_;  // per unit, per target
  std::vector<GLint> samplers_;
  std::vector<ImageUnit> images_;
  std::vector<IndexedBuffer> uniform_buffers_, storage_buffers_, atomic_buffers_, feedback_buffers_;
  std::vector<GLint> generic_buffers_;  // per target in kGenericBufferTargets
};

// glClipControl's two values, which it sets together.
struct ClipControl {
  GLint origin, depth_mode;
};

// One draw buffer's blend equations and functions.
struct BlendState {
  GLint equation_rgb, equation_alpha, src_rgb, dst_rgb, src_alpha, dst_alpha;
};

// One face's stencil test and operations.
struct StencilFace {
  GLint func, ref, value_mask, fail, depth_fail, depth_pass, write_mask;
};

// Raster, per-fragment and pixel-store state, and the bindings, for the life of one render().
class GlStateScope {
 public:
  // SAVE: save the engine's values, set the chain's, put the engine's back at the end.
  // SET_ONLY: set the chain's values and nothing else, for a render() inside a GlStateGuard,
  // which saved the engine's values already and puts them back itself.
  enum Mode { SAVE, SET_ONLY };
  explicit GlStateScope(const GlLimits& limits, Mode mode = SAVE);
  ~GlStateScope();
  GlStateScope(const GlStateScope&) = delete;
  GlStateScope& operator=(const GlStateScope&) = delete;

 private:
  void save();
  void set_chain_state() const;
  void restore() const;

  const GlLimits& limits_;
  Mode mode_;
  std::vector<GLboolean> enables_;            // per capability in the fixed list
  std::vector<GLboolean> clip_distances_;
  std::vector<GLboolean> blend_enabled_, scissor_enabled_;
  std::vector<BlendState> blend_;             // per draw buffer
  std::vector<std::array<GLboolean, 4>> color_masks_;
  std::vector<std::array<GLfloat, 4>> viewports_;
  std::vector<std::array<GLdouble, 2>> depth_ranges_;
  std::vector<GLint> integers_;               // per value in the integer list
  std::vector<GLfloat> floats_;               // per value in the float list
  ClipControl clip_control_{};
  GLint polygon_mode_[2] = {GL_FILL, GL_FILL};
  StencilFace stencil_front_{}, stencil_back_{};
  GLfloat blend_color_[4] = {}, clear_color_[4] = {};
  GLdouble clear_depth_ = 1;
  GlBindings bindings_;
  std::unique_ptr<LegacyStateScope> legacy_;  // in a compatibility-profile context only
};

}  // namespace pfx::host
