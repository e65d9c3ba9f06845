// GlBindings (gl_state_scope.hpp): the bindings a chain or a plugin may change, saved before the
// chain and put back after it.
#include "gl_state_scope.hpp"

#include <cstddef>
#include <iterator>

namespace pfx::host {
namespace {

struct TextureTarget {
  GLenum target, binding;
};
const TextureTarget kTextureTargets[] = {
    {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D},
    {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D},
    {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D},
    {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY},
    {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE},
    {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP},
    {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY},
    {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER},
    {GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_BINDING_2D_MULTISAMPLE},
    {GL_TEXTURE_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY},
};

struct BufferTarget {
  GLenum target, binding;
};
// The generic (non-indexed) binding points. The element array buffer belongs to the vertex array.
const BufferTarget kGenericBuffers[] = {
    {GL_ARRAY_BUFFER, GL_ARRAY_BUFFER_BINDING},
    {GL_ATOMIC_COUNTER_BUFFER, GL_ATOMIC_COUNTER_BUFFER_BINDING},
    {GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER_BINDING},
    {GL_COPY_WRITE_BUFFER, GL_COPY_WRITE_BUFFER_BINDING},
    {GL_DISPATCH_INDIRECT_BUFFER, GL_DISPATCH_INDIRECT_BUFFER_BINDING},
    {GL_DRAW_INDIRECT_BUFFER, GL_DRAW_INDIRECT_BUFFER_BINDING},
    {GL_PIXEL_PACK_BUFFER, GL_PIXEL_PACK_BUFFER_BINDING},
    {GL_PIXEL_UNPACK_BUFFER, GL_PIXEL_UNPACK_BUFFER_BINDING},
    {GL_QUERY_BUFFER, GL_QUERY_BUFFER_BINDING},
    {GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING},
    {GL_TEXTURE_BUFFER, GL_TEXTURE_BUFFER_BINDING},
    {GL_TRANSFORM_FEEDBACK_BUFFER, GL_TRANSFORM_FEEDBACK_BUFFER_BINDING},
    {GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING},
};

GLint get_integer(GLenum pname) {
  GLint v = 0;
  glGetIntegerv(pname, &v);
  return v;
}

template <typename Buffer>
std::vector<Buffer> save_indexed(GLenum binding, GLenum start, GLenum size, GLint count) {
  std::vector<Buffer> buffers(static_cast<size_t>(count));
  for (GLint i = 0; i < count; ++i) {
    const GLuint index = static_cast<GLuint>(i);
    glGetIntegeri_v(binding, index, &buffers[i].name);
    glGetInteger64i_v(start, index, &buffers[i].start);
    glGetInteger64i_v(size, index, &buffers[i].size);
  }
  return buffers;
}

template <typename Buffer>
void restore_indexed(GLenum target, const std::vector<Buffer>& buffers) {
  for (size_t i = 0; i < buffers.size(); ++i) {
    const Buffer& b = buffers[i];
    const GLuint index = static_cast<GLuint>(i);
    // A size of 0 is what a whole-buffer binding (BindBufferBase) reads back as.
    if (b.name == 0 || b.size == 0) glBindBufferBase(target, index, static_cast<GLuint>(b.name));
    else glBindBufferRange(target, index, static_cast<GLuint>(b.name), b.start, b.size);
  }
}

}  // namespace

void GlBindings::save(const GlLimits& limits) {
  static_assert(std::size(kTextureTargets) == kTargetsPerUnit, "one saved binding per texture target");
  draw_framebuffer_ = get_integer(GL_DRAW_FRAMEBUFFER_BINDING);
  read_framebuffer_ = get_integer(GL_READ_FRAMEBUFFER_BINDING);
  renderbuffer_ = get_integer(GL_RENDERBUFFER_BINDING);
  vertex_array_ = get_integer(GL_VERTEX_ARRAY_BINDING);
  program_ = get_integer(GL_CURRENT_PROGRAM);
  pipeline_ = get_integer(GL_PROGRAM_PIPELINE_BINDING);
  active_texture_ = get_integer(GL_ACTIVE_TEXTURE);
  transform_feedback_ = get_integer(GL_TRANSFORM_FEEDBACK_BINDING);

  textures_.assign(static_cast<size_t>(limits.texture_units), {});
  samplers_.assign(static_cast<size_t>(limits.texture_units), 0);
  for (GLint unit = 0; unit < limits.texture_units; ++unit) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    for (int t = 0; t < kTargetsPerUnit; ++t) textures_[unit][t] = get_integer(kTextureTargets[t].binding);
    samplers_[unit] = get_integer(GL_SAMPLER_BINDING);
  }
  glActiveTexture(static_cast<GLenum>(active_texture_));

  images_.assign(static_cast<size_t>(limits.image_units), {});
  for (GLint unit = 0; unit < limits.image_units; ++unit) {
    const GLuint u = static_cast<GLuint>(unit);
    ImageUnit& image = images_[unit];
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, u, &image.name);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, u, &image.level);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, u, &image.layered);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, u, &image.layer);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, u, &image.access);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, u, &image.format);
  }

  uniform_buffers_ = save_indexed<IndexedBuffer>(GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START,
                                                 GL_UNIFORM_BUFFER_SIZE, limits.uniform_buffers);
  storage_buffers_ = save_indexed<IndexedBuffer>(GL_SHADER_STORAGE_BUFFER_BINDING, GL_SHADER_STORAGE_BUFFER_START,
                                                 GL_SHADER_STORAGE_BUFFER_SIZE, limits.storage_buffers);
  atomic_buffers_ = save_indexed<IndexedBuffer>(GL_ATOMIC_COUNTER_BUFFER_BINDING, GL_ATOMIC_COUNTER_BUFFER_START,
                                                GL_ATOMIC_COUNTER_BUFFER_SIZE, limits.atomic_buffers);
  // The default transform feedback object's buffers: the chain binds that object, so a plugin's
  // transform feedback writes its bindings, which the engine may use too.
  feedback_buffers_.assign(static_cast<size_t>(limits.feedback_buffers), {});
  for (GLint i = 0; i < limits.feedback_buffers; ++i) {
    const GLuint index = static_cast<GLuint>(i);
    glGetTransformFeedbacki_v(0, GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, index, &feedback_buffers_[i].name);
    glGetTransformFeedbacki64_v(0, GL_TRANSFORM_FEEDBACK_BUFFER_START, index, &feedback_buffers_[i].start);
    glGetTransformFeedbacki64_v(0, GL_TRANSFORM_FEEDBACK_BUFFER_SIZE, index, &feedback_buffers_[i].size);
  }

  generic_buffers_.clear();
  for (const BufferTarget& b : kGenericBuffers) generic_buffers_.push_back(get_integer(b.binding));
}

void GlBindings::set_clean(const GlLimits& limits) const {
  glBindTextures(0, limits.texture_units, nullptr);
  glBindSamplers(0, limits.texture_units, nullptr);
  glBindImageTextures(0, limits.image_units, nullptr);
  glBindBuffersBase(GL_UNIFORM_BUFFER, 0, limits.uniform_buffers, nullptr);
  glBindBuffersBase(GL_SHADER_STORAGE_BUFFER, 0, limits.storage_buffers, nullptr);
  glBindBuffersBase(GL_ATOMIC_COUNTER_BUFFER, 0, limits.atomic_buffers, nullptr);
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
  // Bound, these turn a plugin's client-memory pointers into buffer offsets (and its query reads
  // into buffer writes).
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glBindBuffer(GL_QUERY_BUFFER, 0);
  glUseProgram(0);
  glBindProgramPipeline(0);
  glActiveTexture(GL_TEXTURE0);
}

void GlBindings::restore() const {
  for (size_t unit = 0; unit < textures_.size(); ++unit) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    for (int t = 0; t < kTargetsPerUnit; ++t)
      glBindTexture(kTextureTargets[t].target, static_cast<GLuint>(textures_[unit][t]));
    glBindSampler(static_cast<GLuint>(unit), static_cast<GLuint>(samplers_[unit]));
  }
  for (size_t unit = 0; unit < images_.size(); ++unit) {
    const ImageUnit& image = images_[unit];
    glBindImageTexture(static_cast<GLuint>(unit), static_cast<GLuint>(image.name), image.level,
                       image.layered ? GL_TRUE : GL_FALSE, image.layer, static_cast<GLenum>(image.access),
                       static_cast<GLenum>(image.format));
  }
  for (size_t i = 0; i < feedback_buffers_.size(); ++i) {
    const IndexedBuffer& b = feedback_buffers_[i];
    const GLuint index = static_cast<GLuint>(i);
    if (b.name == 0 || b.size == 0) glTransformFeedbackBufferBase(0, index, static_cast<GLuint>(b.name));
    else glTransformFeedbackBufferRange(0, index, static_cast<GLuint>(b.name), b.start, b.size);
  }
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, static_cast<GLuint>(transform_feedback_));
  restore_indexed(GL_UNIFORM_BUFFER, uniform_buffers_);
  restore_indexed(GL_SHADER_STORAGE_BUFFER, storage_buffers_);
  restore_indexed(GL_ATOMIC_COUNTER_BUFFER, atomic_buffers_);
  // After the indexed ones: binding an indexed point binds its generic point too.
  for (size_t i = 0; i < generic_buffers_.size(); ++i)
    glBindBuffer(kGenericBuffers[i].target, static_cast<GLuint>(generic_buffers_[i]));
  glActiveTexture(static_cast<GLenum>(active_texture_));
  glUseProgram(static_cast<GLuint>(program_));
  glBindProgramPipeline(static_cast<GLuint>(pipeline_));
  glBindVertexArray(static_cast<GLuint>(vertex_array_));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer_));
  glBindRenderbuffer(GL_RENDERBUFFER, static_cast<GLuint>(renderbuffer_));
}

}  // namespace pfx::host
