// Header-only C++ helpers for plugin authors: loading a plugin's private GL table
// through the host, and building full-screen, compute and other programs. Needs a GL 4.5 loader
// header declaring the GL functions (glad, as this tree generates it) included as <glad/gl.h>;
// built in this tree, not installed (an out-of-tree plugin brings its own loader, docs/sdk.md §1.10).
#pragma once

#include <string>

#include <glad/gl.h>
#include <pfx/core.h>

namespace pfx::gl {

// One triangle covering the viewport from gl_VertexID alone: the host binds an empty vertex array.
// Fragment shaders use gl_FragCoord, so texture coordinates are exactly (pixel + 0.5) / size.
inline const char* fullscreen_vertex_shader() {
  return "#version 450 core\n"
         "void main() {\n"
         "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
         "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
         "}\n";
}

// Fills this library's GL table through the host's get_proc_address (create time: a context is
// current). False when the context lacks OpenGL 4.5 core.
inline bool load_gl(const pfx_host* host) {
  auto loader = [](void* user, const char* name) {
    const auto* h = static_cast<const pfx_host*>(user);
    return reinterpret_cast<GLADapiproc>(h->get_proc_address(h->host_data, name));
  };
  return gladLoadGLUserPtr(loader, const_cast<pfx_host*>(host)) && GLAD_GL_VERSION_4_5;
}

// load_gl, saying in the host's log what went wrong ("<who>: the host's context lacks OpenGL 4.5
// core") when it fails, as create must before it returns PFX_GL_ERROR.
inline bool load_gl_or_log(const pfx_host* host, const char* who) {
  if (load_gl(host)) return true;
  host->log(host->host_data, PFX_LOG_ERROR, (std::string(who) + ": the host's context lacks OpenGL 4.5 core").c_str());
  return false;
}

// Compiles and links one shader per stage. Returns 0 and the compiler's or linker's message in
// *error on failure. `retrievable`: the program's binary may be read back afterwards
// (glGetProgramBinary), for a cache of compiled programs.
inline GLuint build_program(const GLenum* stages, const char* const* sources, int count, std::string* error,
                            bool retrievable = false) {
  char info[2048] = "";
  GLuint program = glCreateProgram();
  if (retrievable) glProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
  GLint ok = 1;
  for (int i = 0; i < count && ok; ++i) {
    GLuint shader = glCreateShader(stages[i]);
    glShaderSource(shader, 1, &sources[i], nullptr);
    glCompileShader(shader);
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) glGetShaderInfoLog(shader, sizeof info, nullptr, info);
    glAttachShader(program, shader);
    glDeleteShader(shader);  // only flagged: the program keeps it alive
  }
  if (ok) {
    glLinkProgram(program);
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) glGetProgramInfoLog(program, sizeof info, nullptr, info);
  }
  if (ok) return program;
  if (error) *error = info;
  glDeleteProgram(program);
  return 0;
}

// Links the full-screen vertex shader with fragment_source.
inline GLuint build_fullscreen_program(const char* fragment_source, std::string* error) {
  const char* sources[2] = {fullscreen_vertex_shader(), fragment_source};
  const GLenum stages[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
  return build_program(stages, sources, 2, error);
}

// A compute program of one shader.
inline GLuint build_compute_program(const char* source, std::string* error) {
  const GLenum stage = GL_COMPUTE_SHADER;
  return build_program(&stage, &source, 1, error);
}

}  // namespace pfx::gl
