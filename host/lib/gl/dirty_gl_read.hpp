// Reading GL state back as plain numbers, for DirtyGlState's items (dirty_gl_state.hpp), and the
// numbers of units and binding points they cover.
#pragma once

#include <initializer_list>
#include <vector>

#include <glad/gl.h>

namespace pfx::app::dirty_gl {

constexpr GLuint kUnits = 16;          // texture units, sampler units, uniform buffer bindings
constexpr GLuint kImageUnits = 8;      // image units, storage buffer bindings
constexpr GLuint kFeedbackBuffers = 4;
constexpr GLuint kDrawBuffers = 8;
constexpr GLuint kViewports = 16;
constexpr GLuint kClipDistances = 8;

inline double get_integer(GLenum pname) {
  GLint v[4] = {0, 0, 0, 0};
  glGetIntegerv(pname, v);
  return v[0];
}

inline std::vector<double> get_integers(std::initializer_list<GLenum> pnames) {
  std::vector<double> values;
  for (GLenum pname : pnames) values.push_back(get_integer(pname));
  return values;
}

// An indexed state's values at one index (a draw buffer's, an image unit's), as glGetIntegeri_v reads them.
inline std::vector<double> get_integers_at(std::initializer_list<GLenum> pnames, GLuint index) {
  std::vector<double> values;
  for (GLenum pname : pnames) {
    GLint value = 0;
    glGetIntegeri_v(pname, index, &value);
    values.push_back(value);
  }
  return values;
}

inline std::vector<double> get_floats(GLenum pname, int count) {
  GLfloat v[4] = {0, 0, 0, 0};
  glGetFloatv(pname, v);
  return std::vector<double>(v, v + count);
}

inline std::vector<double> get_enabled(std::initializer_list<GLenum> caps) {
  std::vector<double> values;
  for (GLenum cap : caps) values.push_back(glIsEnabled(cap));
  return values;
}

inline void append(std::vector<double>* to, const std::vector<double>& values) { to->insert(to->end(), values.begin(), values.end()); }

inline std::vector<double> get_indexed_buffers(GLenum binding, GLenum start, GLenum size, GLuint count) {
  std::vector<double> values;
  for (GLuint i = 0; i < count; ++i) {
    GLint name = 0;
    GLint64 offset = 0, length = 0;
    glGetIntegeri_v(binding, i, &name);
    glGetInteger64i_v(start, i, &offset);
    glGetInteger64i_v(size, i, &length);
    values.insert(values.end(), {double(name), double(offset), double(length)});
  }
  return values;
}

}  // namespace pfx::app::dirty_gl
