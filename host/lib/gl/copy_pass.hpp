// The unit every time is divided by: a plain full-screen pass copying an RGBA16F texture into
// another of the same size, the cheapest thing a post effect can do. Absolute times on a shared
// software renderer drift; ratios to this pass, measured in the same run, do not.
#pragma once

#include <cstdint>

namespace pfx::gl {

class CopyPass {
 public:
  CopyPass();  // compiles the program; GL current
  ~CopyPass();
  CopyPass(const CopyPass&) = delete;
  CopyPass& operator=(const CopyPass&) = delete;
  // Draws source into the framebuffer around target (both width x height).
  void run(uint32_t source, uint32_t target, int width, int height);

 private:
  uint32_t program_ = 0, vertex_array_ = 0, framebuffer_ = 0;
};

// The median time in milliseconds of `repeats` copy passes between two new RGBA16F textures of
// that size, each timed with glFinish around it and a clock (after three not counted): the unit
// where no timer query is trusted (a software renderer). GL current. It changes bindings, the
// viewport and blending: inside a context the host does not own (pfx-inject's), call it under a
// GlStateGuard, which puts the application's state back.
double median_copy_pass_ms(int width, int height, int repeats);

}  // namespace pfx::gl
