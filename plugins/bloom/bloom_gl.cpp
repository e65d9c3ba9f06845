#include "bloom_gl.hpp"

#include <pfx/cpp/gl_program.hpp>
#include <pfx/cpp/plugin_entry.hpp>

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

bool build_programs(const pfx_host* host, const ProgramSpec* specs, int count, GLuint* out) {
  for (int i = 0; i < count; ++i) {
    out[i] = 0;
    // Assembling a source or a message can throw std::bad_alloc, which must not cross the ABI.
    const pfx_status built = pfx::plugin::without_exceptions([&] {
      std::string error;
      out[i] = pfx::gl::build_fullscreen_program(specs[i].source().c_str(), &error);
      if (!out[i]) log_error(host, (std::string("bloom: shader '") + specs[i].name + "': " + error).c_str());
      return out[i] ? PFX_OK : PFX_GL_ERROR;
    });
    if (built != PFX_OK) return false;
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
