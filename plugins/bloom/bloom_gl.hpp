// The little GL this plugin needs beyond its passes: loading its private GL function table through
// the host, building programs whose failures are logged with the shader's name, and the uniforms
// and draw every pass shares.
#pragma once

#include <string>

#include <glad/gl.h>
#include <pfx/core.h>

namespace pfx_bloom {

struct Settings;

// False (after logging) when the host's context lacks OpenGL 4.5 core.
bool load_gl(const pfx_host* host);

// A program to build: its name for messages and the function assembling its fragment shader.
struct ProgramSpec {
  const char* name;
  std::string (*source)();
};

// Builds count programs (the shared full-screen-triangle vertex shader and each spec's fragment
// shader) into out[0 .. count-1]; false (after logging "bloom: shader 'NAME': <compiler message>")
// when any fails, with the
// ones built so far left in out for the caller to delete. Never throws.
bool build_programs(const pfx_host* host, const ProgramSpec* specs, int count, GLuint* out);

// Every program that reads the frame: what a non-finite pixel counts as (location 600, past the
// blur program's 512 weights; shaders_common.cpp).
void set_nonfinite_uniform(GLuint program, const Settings& s);

// The bright programs' shared uniforms (locations 1-3 and 600, shaders_common.cpp); measure_override
// >= 0 replaces the settings' measure (2: every channel on its own, as the gaussian mode).
void set_bright_uniforms(GLuint program, const Settings& s, int measure_override = -1);

// Binds the program, draws the full-screen triangle, unbinds the program.
void draw_fullscreen(GLuint program);

}  // namespace pfx_bloom
