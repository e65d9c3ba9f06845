// The little GL this plugin needs beyond its passes: loading its private GL function table through
// the host, and building programs whose failures are logged with the shader's name.
#pragma once

#include <glad/gl.h>
#include <pfx/core.h>

namespace pfx_bloom {

// False (after logging) when the host's context lacks OpenGL 4.5 core.
bool load_gl(const pfx_host* host);

// A program of the shared full-screen-triangle vertex shader and this fragment shader; 0 after
// logging "bloom: shader 'NAME': <compiler message>".
GLuint build_program(const pfx_host* host, const char* name, const char* fragment_source);

}  // namespace pfx_bloom
