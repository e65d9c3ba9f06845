#include "bloom_gl.hpp"

#include <pfx/cpp/gl_program.hpp>

#include "bloom_params.hpp"

namespace pfx_bloom {
namespace {

void log_error(const pfx_host* host, const char* message) { host->log(host->host_data, PFX_LOG_ERROR, message); }

}  // namespace

bool load_gl(const pfx_host* host) {
  // The table is private to this library; filling it per instance is cheap and keeps it right if
  // the host's context (and so its entry points) changed since the last instance.
  return pfx::gl::load_gl_or_log(host, "bloom");
}

GLuint build_program(const pfx_host* host, const char* name, const std::string& fragment_source) {
  try {
    std::string error;
    GLuint program = pfx::gl::build_fullscreen_program(fragment_source.c_str(), &error);
    if (!program) log_error(host, (std::string("bloom: shader '") + name + "': " + error).c_str());
    return program;
  } catch (...) {  // only std::bad_alloc; nothing may cross the ABI
    return 0;
  }
}

bool build_programs(const pfx_host* host, const ProgramSpec* specs, int count, GLuint* out) {
  for (int i = 0; i < count; ++i) {
    try {
      out[i] = build_program(host, specs[i].name, specs[i].source());
    } catch (...) {  // std::bad_alloc assembling a source; nothing may cross the ABI
      out[i] = 0;
    }
    if (!out[i]) return false;
  }
  return true;
}

void set_bright_uniforms(GLuint program, const Settings& s, int measure_override) {
  glProgramUniform2f(program, 1, static_cast<float>(s.threshold), static_cast<float>(s.knee));
  glProgramUniform1i(program, 2, measure_override >= 0 ? measure_override : s.measure);
  glProgramUniform1f(program, 3, static_cast<float>(s.firefly_clamp));
  set_nonfinite_uniform(program, s);
}

void set_nonfinite_uniform(GLuint program, const Settings& s) { glProgramUniform1i(program, 600, s.nonfinite); }

void draw_fullscreen(GLuint program) {
  glUseProgram(program);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glUseProgram(0);
}

}  // namespace pfx_bloom
