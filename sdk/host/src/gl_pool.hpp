// The GL objects behind a frame plan: one texture and framebuffer per pool slot, samplers per
// (filter, wrap), the empty vertex array full-screen passes draw with. Kept across
// frames; rebuilt only when the plan's slots change.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include <glad/gl.h>

#include "pfx/host/frame_plan.hpp"

namespace pfx::host {

GLenum gl_internal_format(pfx_format format);

class GlPool {
 public:
  GlPool();
  ~GlPool();
  GlPool(const GlPool&) = delete;
  GlPool& operator=(const GlPool&) = delete;

  // Makes the slots match the plan: keeps textures whose format and size still fit, frees the rest.
  void match(const std::vector<PoolSlot>& slots);
  GLuint texture(int slot) const { return slots_[slot].texture; }
  GLuint framebuffer(int slot) const { return slots_[slot].framebuffer; }
  // An RGBA8 slot read as sRGB (sampling decodes) and a framebuffer drawing into it that way
  // (with GL_FRAMEBUFFER_SRGB, drawing encodes): how a linear effect meets an "output" of sRGB
  // codes between effects. 0 for other formats.
  GLuint srgb_view(int slot) const { return slots_[slot].srgb_view; }
  GLuint srgb_framebuffer(int slot) const { return slots_[slot].srgb_framebuffer; }
  // A framebuffer around a texture the pool does not own (the chain's output); cached.
  GLuint framebuffer_for(GLuint texture);
  GLuint sampler(pfx_filter filter, pfx_wrap wrap);
  GLuint empty_vertex_array() const { return vertex_array_; }

 private:
  struct Slot {
    PoolSlot shape;
    GLuint texture = 0, framebuffer = 0;
    GLuint srgb_view = 0, srgb_framebuffer = 0;
  };
  static Slot make_slot(const PoolSlot& shape);
  static void free_slot(Slot& slot);
  // Deletes the framebuffers around external textures whose names are no longer textures.
  void forget_deleted_textures();
  std::vector<Slot> slots_;
  std::map<GLuint, GLuint> external_framebuffers_;
  std::map<uint32_t, GLuint> samplers_;
  GLuint vertex_array_ = 0;
};

}  // namespace pfx::host
