// DirtyGlState's pixel-store and binding items (dirty_gl_state.hpp).
#include "dirty_gl_state.hpp"

#include <array>
#include <string>
#include <tuple>
#include <utility>

#include "dirty_gl_read.hpp"

namespace pfx::app {

using namespace dirty_gl;

void DirtyGlState::add_pixel_store() {
  auto store = [this](const std::string& name, std::vector<std::pair<GLenum, GLint>> dirty) {
    items_.push_back({name,
                      [dirty] {
                        for (auto [pname, value] : dirty) glPixelStorei(pname, value);
                      },
                      [dirty] {
                        for (auto [pname, value] : dirty)
                          glPixelStorei(pname, pname == GL_UNPACK_ALIGNMENT || pname == GL_PACK_ALIGNMENT ? 4 : 0);
                      },
                      [dirty] {
                        std::vector<double> v;
                        for (auto [pname, value] : dirty) v.push_back(get_integer(pname));
                        return v;
                      }});
  };
  store("GL_UNPACK_ALIGNMENT 8", {{GL_UNPACK_ALIGNMENT, 8}});
  store("unpack row length 7, image height 3, skipping 1 pixel, row and image",
        {{GL_UNPACK_ROW_LENGTH, 7}, {GL_UNPACK_IMAGE_HEIGHT, 3}, {GL_UNPACK_SKIP_PIXELS, 1},
         {GL_UNPACK_SKIP_ROWS, 1}, {GL_UNPACK_SKIP_IMAGES, 1}});
  store("unpack with swapped bytes, LSB first", {{GL_UNPACK_SWAP_BYTES, GL_TRUE}, {GL_UNPACK_LSB_FIRST, GL_TRUE}});
  store("pack alignment 1, row length 7, skipping 1 pixel and row, swapped bytes",
        {{GL_PACK_ALIGNMENT, 1}, {GL_PACK_ROW_LENGTH, 7}, {GL_PACK_SKIP_PIXELS, 1}, {GL_PACK_SKIP_ROWS, 1},
         {GL_PACK_SWAP_BYTES, GL_TRUE}});
  using Bound = std::tuple<GLenum, GLenum, const char*>;
  const Bound bound[] = {Bound{GL_PIXEL_UNPACK_BUFFER, GL_PIXEL_UNPACK_BUFFER_BINDING, "a pixel unpack buffer"},
                         Bound{GL_PIXEL_PACK_BUFFER, GL_PIXEL_PACK_BUFFER_BINDING, "a pixel pack buffer"},
                         Bound{GL_QUERY_BUFFER, GL_QUERY_BUFFER_BINDING, "a query buffer"}};
  for (auto [target, binding, name] : bound)
    items_.push_back({std::string(name) + " bound", [this, target = target] { glBindBuffer(target, buffer_); },
                      [target = target] { glBindBuffer(target, 0); }, [binding = binding] { return get_integers({binding}); }});
}

void DirtyGlState::add_bindings() {
  items_.push_back({"the engine's framebuffer bound for drawing", [this] { glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_); },
                    [] { glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0); },
                    [] { return get_integers({GL_DRAW_FRAMEBUFFER_BINDING}); }});
  items_.push_back({"the engine's framebuffer bound for reading", [this] { glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_); },
                    [] { glBindFramebuffer(GL_READ_FRAMEBUFFER, 0); },
                    [] { return get_integers({GL_READ_FRAMEBUFFER_BINDING}); }});
  items_.push_back({"a renderbuffer bound", [this] { glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer_); },
                    [] { glBindRenderbuffer(GL_RENDERBUFFER, 0); }, [] { return get_integers({GL_RENDERBUFFER_BINDING}); }});
  items_.push_back({"the engine's program in use", [this] { glUseProgram(program_); }, [] { glUseProgram(0); },
                    [] { return get_integers({GL_CURRENT_PROGRAM}); }});
  items_.push_back({"a program pipeline bound", [this] { glBindProgramPipeline(pipeline_); }, [] { glBindProgramPipeline(0); },
                    [] { return get_integers({GL_PROGRAM_PIPELINE_BINDING}); }});
  items_.push_back({"the engine's vertex array bound (element buffer, attribute 0)",
                    [this] { glBindVertexArray(vertex_array_); }, [] { glBindVertexArray(0); },
                    [] { return get_integers({GL_VERTEX_ARRAY_BINDING}); }});
  items_.push_back({"textures on units 0..15 (2D and cube map), unit 5 active",
                    [this] {
                      for (GLuint unit = 0; unit < kUnits; ++unit) {
                        glActiveTexture(GL_TEXTURE0 + unit);
                        glBindTexture(GL_TEXTURE_2D, texture_);
                        glBindTexture(GL_TEXTURE_CUBE_MAP, cube_texture_);
                      }
                      glActiveTexture(GL_TEXTURE5);
                    },
                    [] {
                      glBindTextures(0, kUnits, nullptr);
                      glActiveTexture(GL_TEXTURE0);
                    },
                    [] {
                      const double active = get_integer(GL_ACTIVE_TEXTURE);
                      std::vector<double> v{active};
                      for (GLuint unit = 0; unit < kUnits; ++unit) {
                        glActiveTexture(GL_TEXTURE0 + unit);
                        append(&v, get_integers({GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_CUBE_MAP}));
                      }
                      glActiveTexture(static_cast<GLenum>(active));
                      return v;
                    }});
  items_.push_back({"a nearest, repeating, LOD-biased, comparing sampler on units 0..15",
                    [this] {
                      for (GLuint unit = 0; unit < kUnits; ++unit) glBindSampler(unit, sampler_);
                    },
                    [] { glBindSamplers(0, kUnits, nullptr); },
                    [] {
                      const double active = get_integer(GL_ACTIVE_TEXTURE);
                      std::vector<double> v;
                      for (GLuint unit = 0; unit < kUnits; ++unit) {
                        glActiveTexture(GL_TEXTURE0 + unit);
                        v.push_back(get_integer(GL_SAMPLER_BINDING));
                      }
                      glActiveTexture(static_cast<GLenum>(active));
                      return v;
                    }});
  items_.push_back({"images on units 0..7",
                    [this] {
                      for (GLuint unit = 0; unit < kImageUnits; ++unit)
                        glBindImageTexture(unit, texture_, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
                    },
                    [] { glBindImageTextures(0, kImageUnits, nullptr); },
                    [] {
                      std::vector<double> v;
                      for (GLuint unit = 0; unit < kImageUnits; ++unit)
                        for (GLenum pname : {GL_IMAGE_BINDING_NAME, GL_IMAGE_BINDING_ACCESS, GL_IMAGE_BINDING_FORMAT}) {
                          GLint value = 0;
                          glGetIntegeri_v(pname, unit, &value);
                          v.push_back(value);
                        }
                      return v;
                    }});
  struct Indexed {
    const char* name;
    GLenum target, binding, start, size, alignment;
    GLuint count;
  };
  for (const Indexed& b :
       {Indexed{"uniform buffer ranges on bindings 0..15", GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING,
                GL_UNIFORM_BUFFER_START, GL_UNIFORM_BUFFER_SIZE, GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, kUnits},
        Indexed{"storage buffer ranges on bindings 0..7", GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING,
                GL_SHADER_STORAGE_BUFFER_START, GL_SHADER_STORAGE_BUFFER_SIZE, GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT,
                kImageUnits},
        Indexed{"an atomic counter buffer range on binding 0", GL_ATOMIC_COUNTER_BUFFER, GL_ATOMIC_COUNTER_BUFFER_BINDING,
                GL_ATOMIC_COUNTER_BUFFER_START, GL_ATOMIC_COUNTER_BUFFER_SIZE, 0, 1}}) {
    items_.push_back({b.name,
                      [this, b] {
                        const GLintptr offset = b.alignment ? static_cast<GLintptr>(get_integer(b.alignment)) : 4;
                        for (GLuint i = 0; i < b.count; ++i) glBindBufferRange(b.target, i, buffer_, offset, 64);
                      },
                      [b] {
                        glBindBuffersBase(b.target, 0, static_cast<GLsizei>(b.count), nullptr);
                        glBindBuffer(b.target, 0);
                      },
                      [b] { return get_indexed_buffers(b.binding, b.start, b.size, b.count); }});
  }
  items_.push_back({"buffer ranges on the default transform feedback's bindings 0..3",
                    [this] {
                      for (GLuint i = 0; i < kFeedbackBuffers; ++i) glTransformFeedbackBufferRange(0, i, buffer_, 16, 64);
                    },
                    [] {
                      for (GLuint i = 0; i < kFeedbackBuffers; ++i) glTransformFeedbackBufferBase(0, i, 0);
                    },
                    [] {
                      std::vector<double> v;
                      for (GLuint i = 0; i < kFeedbackBuffers; ++i) {
                        GLint name = 0;
                        GLint64 start = 0, size = 0;
                        glGetTransformFeedbacki_v(0, GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, i, &name);
                        glGetTransformFeedbacki64_v(0, GL_TRANSFORM_FEEDBACK_BUFFER_START, i, &start);
                        glGetTransformFeedbacki64_v(0, GL_TRANSFORM_FEEDBACK_BUFFER_SIZE, i, &size);
                        v.insert(v.end(), {double(name), double(start), double(size)});
                      }
                      return v;
                    }});
  items_.push_back({"the engine's transform feedback object bound",
                    [this] { glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback_); },
                    [] { glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0); },
                    [] { return get_integers({GL_TRANSFORM_FEEDBACK_BINDING}); }});
  const std::array<std::pair<GLenum, GLenum>, 10> generic = {{
      {GL_ARRAY_BUFFER, GL_ARRAY_BUFFER_BINDING},
      {GL_COPY_READ_BUFFER, GL_COPY_READ_BUFFER_BINDING},
      {GL_COPY_WRITE_BUFFER, GL_COPY_WRITE_BUFFER_BINDING},
      {GL_DRAW_INDIRECT_BUFFER, GL_DRAW_INDIRECT_BUFFER_BINDING},
      {GL_DISPATCH_INDIRECT_BUFFER, GL_DISPATCH_INDIRECT_BUFFER_BINDING},
      {GL_TEXTURE_BUFFER, GL_TEXTURE_BUFFER_BINDING},
      {GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING},
      {GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING},
      {GL_ATOMIC_COUNTER_BUFFER, GL_ATOMIC_COUNTER_BUFFER_BINDING},
      {GL_TRANSFORM_FEEDBACK_BUFFER, GL_TRANSFORM_FEEDBACK_BUFFER_BINDING},
  }};
  items_.push_back({"buffers on the generic array, copy, indirect, texture, uniform, storage, atomic and feedback bindings",
                    [this, generic] {
                      for (auto [target, binding] : generic) glBindBuffer(target, buffer_);
                    },
                    [generic] {
                      for (auto [target, binding] : generic) glBindBuffer(target, 0);
                    },
                    [generic] {
                      std::vector<double> v;
                      for (auto [target, binding] : generic) v.push_back(get_integer(binding));
                      return v;
                    }});
}

}  // namespace pfx::app
