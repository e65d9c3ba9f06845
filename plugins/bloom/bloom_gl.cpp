#include "bloom_gl.hpp"

#include <string>

namespace pfx_bloom {
namespace {

// One triangle covering the viewport from gl_VertexID alone: the host binds an empty vertex
// array. The fragment shaders use gl_FragCoord, not an interpolated coordinate, so the texture
// coordinates are exactly (pixel + 0.5) / size, as the CPU reference assumes.
const char* const kVertexShader =
    "#version 450 core\n"
    "void main() {\n"
    "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
    "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";

GLADapiproc load_proc(void* userptr, const char* name) {
  const pfx_host* host = static_cast<const pfx_host*>(userptr);
  return reinterpret_cast<GLADapiproc>(host->get_proc_address(host->host_data, name));
}

void log_error(const pfx_host* host, const std::string& message) {
  host->log(host->host_data, PFX_LOG_ERROR, message.c_str());
}

}  // namespace

bool load_gl(const pfx_host* host) {
  // The table is private to this library; filling it per instance is cheap and keeps it right if
  // the host's context (and so its entry points) changed since the last instance.
  if (gladLoadGLUserPtr(load_proc, const_cast<pfx_host*>(host)) && GLAD_GL_VERSION_4_5) return true;
  log_error(host, "bloom: the host's context lacks OpenGL 4.5 core");
  return false;
}

GLuint build_program(const pfx_host* host, const char* name, const char* fragment_source) {
  const char* sources[2] = {kVertexShader, fragment_source};
  const GLenum stages[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
  char info[2048] = "";
  GLuint program = glCreateProgram();
  GLint ok = 1;
  for (int i = 0; i < 2 && ok; ++i) {
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
  log_error(host, std::string("bloom: shader '") + name + "': " + info);
  glDeleteProgram(program);
  return 0;
}

}  // namespace pfx_bloom
