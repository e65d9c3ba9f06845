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

// The first half of build_program: compiles and links without asking how it went, so a driver
// that compiles on threads of its own (KHR_parallel_shader_compile) keeps the caller waiting for
// nothing; program_ready() says when finish_program() will not wait. `retrievable`: the program's
// binary may be read back afterwards (glGetProgramBinary), for a cache of compiled programs.
inline GLuint start_program(const GLenum* stages, const char* const* sources, int count, bool retrievable = false) {
  GLuint program = glCreateProgram();
  if (retrievable) glProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
  for (int i = 0; i < count; ++i) {
    GLuint shader = glCreateShader(stages[i]);
    glShaderSource(shader, 1, &sources[i], nullptr);
    glCompileShader(shader);
    glAttachShader(program, shader);
    glDeleteShader(shader);  // only flagged: the program keeps it alive, and finish_program reads its log
  }
  glLinkProgram(program);
  return program;
}

// Whether the GL offers KHR_parallel_shader_compile (or its ARB twin), whose query
// program_ready() needs: compiling in the background is then the driver's to do.
inline bool has_parallel_compile() {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (name && (std::string(name) == "GL_KHR_parallel_shader_compile" || std::string(name) == "GL_ARB_parallel_shader_compile"))
      return true;
  }
  return false;
}

// Whether the driver has finished compiling and linking `program`, without waiting for it
// (GL_COMPLETION_STATUS_KHR; only where has_parallel_compile()).
inline bool program_ready(GLuint program) {
  constexpr GLenum kCompletionStatus = 0x91B1;  // GL_COMPLETION_STATUS_KHR, as GL_COMPLETION_STATUS_ARB
  GLint done = GL_TRUE;
  glGetProgramiv(program, kCompletionStatus, &done);
  return done == GL_TRUE;
}

// The second half: the program when it linked; else 0, the program deleted, and the compiler's
// message for the first shader that failed (or the linker's) in *error.
inline GLuint finish_program(GLuint program, std::string* error) {
  char info[2048] = "";
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok) return program;
  GLuint shaders[8] = {};
  GLsizei count = 0;
  glGetAttachedShaders(program, 8, &count, shaders);
  for (GLsizei i = 0; i < count && !info[0]; ++i) {
    GLint compiled = 1;
    glGetShaderiv(shaders[i], GL_COMPILE_STATUS, &compiled);
    if (!compiled) glGetShaderInfoLog(shaders[i], sizeof info, nullptr, info);
  }
  if (!info[0]) glGetProgramInfoLog(program, sizeof info, nullptr, info);
  if (error) *error = info;
  glDeleteProgram(program);
  return 0;
}

// Compiles and links one shader per stage. Returns 0 and the compiler's or linker's message in
// *error on failure. `retrievable` as for start_program.
inline GLuint build_program(const GLenum* stages, const char* const* sources, int count, std::string* error,
                            bool retrievable = false) {
  return finish_program(start_program(stages, sources, count, retrievable), error);
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
