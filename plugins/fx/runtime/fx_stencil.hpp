#pragma once
// The stencil buffer of an FX effect, as ReShade keeps it: one 8-bit buffer of the frame's size,
// made when a pass of the technique enables the stencil test, cleared to 0 when the technique
// starts (every frame) and kept from pass to pass within it. A pass that enables the test uses it
// when its render targets have the frame's size; at another size it draws without stencil. The
// depth test stays off, so StencilDepthFailOp never applies.
#include <string>

#include <glad/gl.h>

#include "model/effect_model.hpp"

namespace pfx_fx {

GLenum gl_compare_func(pfx::fx::CompareFunc func);
GLenum gl_stencil_op(pfx::fx::StencilOp op);

class FxStencil {
 public:
  FxStencil() = default;
  FxStencil(const FxStencil&) = delete;
  FxStencil& operator=(const FxStencil&) = delete;
  ~FxStencil() { release(); }

  // A buffer of width x height when a pass of `technique` enables the stencil test (none
  // otherwise). Returns false with `error` when GL refuses.
  bool create(const pfx::fx::TechniqueInfo& technique, int width, int height, std::string& error);
  void release();
  bool exists() const { return renderbuffer_ != 0; }
  // Whether `pass` tests stencil when it draws into targets of width x height.
  bool applies(const pfx::fx::PassInfo& pass, int width, int height) const;
  // Zeros in the buffer, through `framebuffer` (its colour attachments as they are), which is left
  // without the buffer attached. Nothing when there is no buffer.
  void clear(GLuint framebuffer);
  // Attaches the buffer to `framebuffer` and sets the pass's stencil test and operations.
  void begin(GLuint framebuffer, const pfx::fx::StencilState& state);
  // The GL state contract's values again (test off, function (ALWAYS, 0, ~0), operations KEEP,
  // write mask ~0), and the buffer detached from `framebuffer`.
  void end(GLuint framebuffer);

 private:
  void attach(GLuint framebuffer, GLuint renderbuffer) const;

  GLuint renderbuffer_ = 0;
  GLenum attachment_ = GL_STENCIL_ATTACHMENT;
  bool checked_ = false;  // the framebuffer was found complete with the buffer attached
  int width_ = 0, height_ = 0;
};

}  // namespace pfx_fx
