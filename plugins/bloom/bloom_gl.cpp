#include "bloom_gl.hpp"

#include <string>

#include <pfx/cpp/gl_program.hpp>

namespace pfx_bloom {
namespace {

void log_error(const pfx_host* host, const std::string& message) {
  host->log(host->host_data, PFX_LOG_ERROR, message.c_str());
}

}  // namespace

bool load_gl(const pfx_host* host) {
  // The table is private to this library; filling it per instance is cheap and keeps it right if
  // the host's context (and so its entry points) changed since the last instance.
  if (pfx::gl::load_gl(host)) return true;
  log_error(host, "bloom: the host's context lacks OpenGL 4.5 core");
  return false;
}

GLuint build_program(const pfx_host* host, const char* name, const char* fragment_source) {
  std::string error;
  GLuint program = pfx::gl::build_fullscreen_program(fragment_source, &error);
  if (!program) log_error(host, std::string("bloom: shader '") + name + "': " + error);
  return program;
}

}  // namespace pfx_bloom
