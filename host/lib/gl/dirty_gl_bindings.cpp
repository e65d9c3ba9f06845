// DirtyGlState's pixel-store and binding items (dirty_gl_state.hpp).
#include "dirty_gl_state.hpp"

#include <initializer_list>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

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

namespace {

// An object the engine leaves bound where a fresh context binds none, read back through its binding.
DirtyGlItem bound_object(const char* name, GLuint object, GLenum binding, void (*bind)(GLuint)) {
  return {name, [bind, object] { bind(object); }, [bind] { bind(0); }, [binding] { return get_integers({binding}); }};
}

// pnames read on each texture unit in turn; the unit that was active is active again after.
std::vector<double> read_each_unit(std::initializer_list<GLenum> pnames) {
  const double active = get_integer(GL_ACTIVE_TEXTURE);
  std::vector<double> v;
  for (GLuint unit = 0; unit < kUnits; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    append(&v, get_integers(pnames));
  }
  glActiveTexture(static_cast<GLenum>(active));
  return v;
}

DirtyGlItem textures_on_units(GLuint texture, GLuint cube_texture) {
  return {"textures on units 0..15 (2D and cube map), unit 5 active",
          [texture, cube_texture] {
            for (GLuint unit = 0; unit < kUnits; ++unit) {
              glActiveTexture(GL_TEXTURE0 + unit);
              glBindTexture(GL_TEXTURE_2D, texture);
              glBindTexture(GL_TEXTURE_CUBE_MAP, cube_texture);
            }
            glActiveTexture(GL_TEXTURE5);
          },
          [] {
            glBindTextures(0, kUnits, nullptr);
            glActiveTexture(GL_TEXTURE0);
          },
          [] {
            std::vector<double> v{get_integer(GL_ACTIVE_TEXTURE)};
            append(&v, read_each_unit({GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_CUBE_MAP}));
            return v;
          }};
}

DirtyGlItem sampler_on_units(GLuint sampler) {
  return {"a nearest, repeating, LOD-biased, comparing sampler on units 0..15",
          [sampler] {
            for (GLuint unit = 0; unit < kUnits; ++unit) glBindSampler(unit, sampler);
          },
          [] { glBindSamplers(0, kUnits, nullptr); }, [] { return read_each_unit({GL_SAMPLER_BINDING}); }};
}

DirtyGlItem images_on_units(GLuint texture) {
  return {
      "images on units 0..7",
      [texture] {
        for (GLuint unit = 0; unit < kImageUnits; ++unit)
          glBindImageTexture(unit, texture, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
      },
      [] { glBindImageTextures(0, kImageUnits, nullptr); },
      [] {
        std::vector<double> v;
        for (GLuint unit = 0; unit < kImageUnits; ++unit)
          append(&v, get_integers_at({GL_IMAGE_BINDING_NAME, GL_IMAGE_BINDING_ACCESS, GL_IMAGE_BINDING_FORMAT}, unit));
        return v;
      }};
}

// An indexed buffer target whose bindings the engine leaves holding ranges of its buffer.
struct IndexedTarget {
  const char* name;
  GLenum target, binding, start, size;
  GLenum alignment;  // the glGet name of the alignment the ranges start at; 0: they start at 4
  GLuint count;      // bindings 0..count-1
};

constexpr IndexedTarget kIndexedTargets[] = {
    {"uniform buffer ranges on bindings 0..15", GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START,
     GL_UNIFORM_BUFFER_SIZE, GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, kUnits},
    {"storage buffer ranges on bindings 0..7", GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING,
     GL_SHADER_STORAGE_BUFFER_START, GL_SHADER_STORAGE_BUFFER_SIZE, GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT,
     kImageUnits},
    {"an atomic counter buffer range on binding 0", GL_ATOMIC_COUNTER_BUFFER, GL_ATOMIC_COUNTER_BUFFER_BINDING,
     GL_ATOMIC_COUNTER_BUFFER_START, GL_ATOMIC_COUNTER_BUFFER_SIZE, 0, 1},
};

DirtyGlItem buffer_ranges(const IndexedTarget& b, GLuint buffer) {
  return {b.name,
          [b, buffer] {
            const GLintptr offset = b.alignment ? static_cast<GLintptr>(get_integer(b.alignment)) : 4;
            for (GLuint i = 0; i < b.count; ++i) glBindBufferRange(b.target, i, buffer, offset, 64);
          },
          [b] {
            glBindBuffersBase(b.target, 0, static_cast<GLsizei>(b.count), nullptr);
            glBindBuffer(b.target, 0);
          },
          [b] { return get_indexed_buffers(b.binding, b.start, b.size, b.count); }};
}

DirtyGlItem feedback_buffer_ranges(GLuint buffer) {
  return {"buffer ranges on the default transform feedback's bindings 0..3",
          [buffer] {
            for (GLuint i = 0; i < kFeedbackBuffers; ++i) glTransformFeedbackBufferRange(0, i, buffer, 16, 64);
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
          }};
}

// The buffer targets glBindBuffer binds (the indexed ones' general binding point among them), each
// with the glGet name that reads it back.
constexpr std::pair<GLenum, GLenum> kGenericTargets[] = {
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
};

DirtyGlItem generic_buffers(GLuint buffer) {
  return {"buffers on the generic array, copy, indirect, texture, uniform, storage, atomic and feedback bindings",
          [buffer] {
            for (auto [target, binding] : kGenericTargets) glBindBuffer(target, buffer);
          },
          [] {
            for (auto [target, binding] : kGenericTargets) glBindBuffer(target, 0);
          },
          [] {
            std::vector<double> v;
            for (auto [target, binding] : kGenericTargets) v.push_back(get_integer(binding));
            return v;
          }};
}

}  // namespace

void DirtyGlState::add_bindings() {
  items_.push_back(bound_object("the engine's framebuffer bound for drawing", framebuffer_, GL_DRAW_FRAMEBUFFER_BINDING,
                                [](GLuint f) { glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f); }));
  items_.push_back(bound_object("the engine's framebuffer bound for reading", framebuffer_, GL_READ_FRAMEBUFFER_BINDING,
                                [](GLuint f) { glBindFramebuffer(GL_READ_FRAMEBUFFER, f); }));
  items_.push_back(bound_object("a renderbuffer bound", renderbuffer_, GL_RENDERBUFFER_BINDING,
                                [](GLuint r) { glBindRenderbuffer(GL_RENDERBUFFER, r); }));
  items_.push_back(
      bound_object("the engine's program in use", program_, GL_CURRENT_PROGRAM, [](GLuint p) { glUseProgram(p); }));
  items_.push_back(bound_object("a program pipeline bound", pipeline_, GL_PROGRAM_PIPELINE_BINDING,
                                [](GLuint p) { glBindProgramPipeline(p); }));
  items_.push_back(bound_object("the engine's vertex array bound (element buffer, attribute 0)", vertex_array_,
                                GL_VERTEX_ARRAY_BINDING, [](GLuint a) { glBindVertexArray(a); }));
  items_.push_back(textures_on_units(texture_, cube_texture_));
  items_.push_back(sampler_on_units(sampler_));
  items_.push_back(images_on_units(texture_));
  for (const IndexedTarget& target : kIndexedTargets) items_.push_back(buffer_ranges(target, buffer_));
  items_.push_back(feedback_buffer_ranges(buffer_));
  items_.push_back(bound_object("the engine's transform feedback object bound", feedback_,
                                GL_TRANSFORM_FEEDBACK_BINDING,
                                [](GLuint f) { glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, f); }));
  items_.push_back(generic_buffers(buffer_));
}

}  // namespace pfx::app
