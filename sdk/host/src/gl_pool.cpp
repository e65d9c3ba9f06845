#include "gl_pool.hpp"

namespace pfx::host {

GLenum gl_internal_format(pfx_format format) {
  switch (format) {
    case PFX_FORMAT_RGBA16F: return GL_RGBA16F;
    case PFX_FORMAT_RGBA32F: return GL_RGBA32F;
    case PFX_FORMAT_R16F: return GL_R16F;
    case PFX_FORMAT_R32F: return GL_R32F;
    case PFX_FORMAT_RG16F: return GL_RG16F;
    case PFX_FORMAT_RG32F: return GL_RG32F;
    case PFX_FORMAT_RGBA8: return GL_RGBA8;
    default: return GL_RGBA16F;
  }
}

GlPool::GlPool() { glCreateVertexArrays(1, &vertex_array_); }

GlPool::~GlPool() {
  for (auto& slot : slots_) free_slot(slot);
  for (auto& [texture, framebuffer] : external_framebuffers_) glDeleteFramebuffers(1, &framebuffer);
  for (auto& [key, sampler] : samplers_) glDeleteSamplers(1, &sampler);
  glDeleteVertexArrays(1, &vertex_array_);
}

GlPool::Slot GlPool::make_slot(const PoolSlot& shape) {
  Slot slot;
  slot.shape = shape;
  glCreateTextures(GL_TEXTURE_2D, 1, &slot.texture);
  glTextureStorage2D(slot.texture, 1, gl_internal_format(shape.format), static_cast<GLsizei>(shape.width),
                     static_cast<GLsizei>(shape.height));
  glCreateFramebuffers(1, &slot.framebuffer);
  glNamedFramebufferTexture(slot.framebuffer, GL_COLOR_ATTACHMENT0, slot.texture, 0);
  if (shape.format == PFX_FORMAT_RGBA8) {
    glGenTextures(1, &slot.srgb_view);  // a view takes a name that is not yet a texture
    glTextureView(slot.srgb_view, GL_TEXTURE_2D, slot.texture, GL_SRGB8_ALPHA8, 0, 1, 0, 1);
    glCreateFramebuffers(1, &slot.srgb_framebuffer);
    glNamedFramebufferTexture(slot.srgb_framebuffer, GL_COLOR_ATTACHMENT0, slot.srgb_view, 0);
  }
  return slot;
}

void GlPool::free_slot(Slot& slot) {
  if (slot.srgb_view) {
    glDeleteFramebuffers(1, &slot.srgb_framebuffer);
    glDeleteTextures(1, &slot.srgb_view);
  }
  glDeleteFramebuffers(1, &slot.framebuffer);
  glDeleteTextures(1, &slot.texture);
  slot = Slot{};
}

void GlPool::match(const std::vector<PoolSlot>& wanted) {
  // Reuse existing textures of the same shape in any position: a resize frees and allocates,
  // a parameter change that keeps sizes reallocates nothing.
  std::vector<Slot> old = std::move(slots_);
  slots_.assign(wanted.size(), Slot{});
  std::vector<bool> taken(old.size(), false);
  for (size_t i = 0; i < wanted.size(); ++i) {
    for (size_t j = 0; j < old.size(); ++j) {
      const PoolSlot& shape = old[j].shape;
      if (!taken[j] && shape.format == wanted[i].format && shape.width == wanted[i].width &&
          shape.height == wanted[i].height) {
        slots_[i] = old[j];
        taken[j] = true;
        break;
      }
    }
    if (!slots_[i].texture) slots_[i] = make_slot(wanted[i]);
  }
  for (size_t j = 0; j < old.size(); ++j)
    if (!taken[j]) free_slot(old[j]);
}

GLuint GlPool::framebuffer_for(GLuint texture) {
  const bool new_texture = external_framebuffers_.find(texture) == external_framebuffers_.end();
  // A host that hands over a fresh output texture each frame would otherwise leave a framebuffer
  // behind per frame (drivers need not reuse texture names: Mesa counts up): those of the
  // textures it has deleted since go when a new one comes.
  if (new_texture) forget_deleted_textures();
  GLuint& framebuffer = external_framebuffers_[texture];
  if (!framebuffer) glCreateFramebuffers(1, &framebuffer);
  // Attach every time: the caller may have deleted the texture and got the same name back for a
  // new one, and a framebuffer keeps a deleted texture's storage alive.
  glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0);
  return framebuffer;
}

void GlPool::forget_deleted_textures() {
  for (auto it = external_framebuffers_.begin(); it != external_framebuffers_.end();) {
    if (glIsTexture(it->first)) {
      ++it;
      continue;
    }
    glDeleteFramebuffers(1, &it->second);
    it = external_framebuffers_.erase(it);
  }
}

GLuint GlPool::sampler(pfx_filter filter, pfx_wrap wrap) {
  uint32_t key = filter * 16 + wrap;
  auto it = samplers_.find(key);
  if (it != samplers_.end()) return it->second;
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  GLint gl_filter = filter == PFX_FILTER_NEAREST ? GL_NEAREST : GL_LINEAR;
  GLint gl_wrap = GL_CLAMP_TO_EDGE;
  if (wrap == PFX_WRAP_CLAMP_TO_BORDER) gl_wrap = GL_CLAMP_TO_BORDER;
  if (wrap == PFX_WRAP_REPEAT) gl_wrap = GL_REPEAT;
  if (wrap == PFX_WRAP_MIRRORED_REPEAT) gl_wrap = GL_MIRRORED_REPEAT;
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, gl_filter);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, gl_filter);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, gl_wrap);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, gl_wrap);
  const GLfloat transparent_black[4] = {0, 0, 0, 0};
  glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, transparent_black);
  samplers_[key] = sampler;
  return sampler;
}

}  // namespace pfx::host
