#include "fx_stencil.hpp"

namespace pfx_fx {

using pfx::fx::CompareFunc;
using pfx::fx::StencilOp;

GLenum gl_compare_func(CompareFunc func) {
  switch (func) {
    case CompareFunc::kNever: return GL_NEVER;
    case CompareFunc::kLess: return GL_LESS;
    case CompareFunc::kEqual: return GL_EQUAL;
    case CompareFunc::kLessEqual: return GL_LEQUAL;
    case CompareFunc::kGreater: return GL_GREATER;
    case CompareFunc::kNotEqual: return GL_NOTEQUAL;
    case CompareFunc::kGreaterEqual: return GL_GEQUAL;
    case CompareFunc::kAlways: break;
  }
  return GL_ALWAYS;
}

GLenum gl_stencil_op(StencilOp op) {
  switch (op) {
    case StencilOp::kKeep: break;
    case StencilOp::kZero: return GL_ZERO;
    case StencilOp::kReplace: return GL_REPLACE;
    case StencilOp::kIncrSat: return GL_INCR;  // GL's INCR and DECR saturate
    case StencilOp::kDecrSat: return GL_DECR;
    case StencilOp::kInvert: return GL_INVERT;
    case StencilOp::kIncr: return GL_INCR_WRAP;
    case StencilOp::kDecr: return GL_DECR_WRAP;
  }
  return GL_KEEP;
}

bool FxStencil::create(const pfx::fx::TechniqueInfo& technique, int width, int height, std::string& error) {
  release();
  bool wanted = false;
  for (const pfx::fx::PassInfo& pass : technique.passes) wanted = wanted || (pass.stencil.enable && !pass.compute_shader);
  if (!wanted) return true;
  glCreateRenderbuffers(1, &renderbuffer_);
  glNamedRenderbufferStorage(renderbuffer_, GL_STENCIL_INDEX8, width, height);
  GLenum status = glGetError();
  if (status != GL_NO_ERROR) {
    release();
    error = "GL error " + std::to_string(status) + " creating a " + std::to_string(width) + "x" + std::to_string(height) + " stencil buffer";
    return false;
  }
  attachment_ = GL_STENCIL_ATTACHMENT;
  checked_ = false;
  width_ = width, height_ = height;
  return true;
}

void FxStencil::release() {
  if (renderbuffer_) glDeleteRenderbuffers(1, &renderbuffer_);
  renderbuffer_ = 0;
  checked_ = false;
}

bool FxStencil::applies(const pfx::fx::PassInfo& pass, int width, int height) const {
  return renderbuffer_ && pass.stencil.enable && width == width_ && height == height_;
}

void FxStencil::attach(GLuint framebuffer, GLuint renderbuffer) const {
  glNamedFramebufferRenderbuffer(framebuffer, attachment_, GL_RENDERBUFFER, renderbuffer);
}

void FxStencil::clear(GLuint framebuffer) {
  if (!renderbuffer_) return;
  attach(framebuffer, renderbuffer_);
  if (!checked_) {
    checked_ = true;
    // A stencil-only attachment is optional for an implementation: fall back to depth and stencil.
    if (glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      attach(framebuffer, 0);
      glDeleteRenderbuffers(1, &renderbuffer_);
      glCreateRenderbuffers(1, &renderbuffer_);
      glNamedRenderbufferStorage(renderbuffer_, GL_DEPTH24_STENCIL8, width_, height_);
      attachment_ = GL_DEPTH_STENCIL_ATTACHMENT;
      attach(framebuffer, renderbuffer_);
    }
  }
  const GLint zero = 0;
  glClearNamedFramebufferiv(framebuffer, GL_STENCIL, 0, &zero);  // the write mask is ~0 between passes
  attach(framebuffer, 0);
}

void FxStencil::begin(GLuint framebuffer, const pfx::fx::StencilState& state) {
  attach(framebuffer, renderbuffer_);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(gl_compare_func(state.func), static_cast<GLint>(state.ref), state.read_mask);
  glStencilOp(gl_stencil_op(state.fail_op), gl_stencil_op(state.depth_fail_op), gl_stencil_op(state.pass_op));
  glStencilMask(state.write_mask);
}

void FxStencil::end(GLuint framebuffer) {
  glDisable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, ~0u);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(~0u);
  attach(framebuffer, 0);
}

}  // namespace pfx_fx
