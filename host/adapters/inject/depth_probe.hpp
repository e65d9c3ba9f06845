// Reads a grid of the application's depth values back to the CPU, for depth_judge.hpp: a small
// full-screen pass picks up to 64 x 64 evenly spread texels of the depth copy into an R32F
// target, which is copied into a buffer behind a fence, so a later present can take the values
// without waiting for the GPU. Runs inside the state guard, like the frame copy.
#pragma once

#include <string>
#include <vector>

#include <glad/gl.h>

namespace pfx::inject {

class DepthProbe {
 public:
  // False with *error when the program does not build. The context must stay current for every
  // call below and the destructor.
  bool create(std::string* error);
  ~DepthProbe();

  // Samples `depth` (a depth texture of width x height) and starts copying the samples back,
  // replacing any reading still in flight. Leaves its program, vertex array, texture unit 0 and
  // draw framebuffer bound.
  void start(GLuint depth, int width, int height);
  bool pending() const { return fence_ != nullptr; }
  // The samples of the reading started last, once the GPU has them (`wait`: waits for them);
  // false while they are not there yet, or when none was started.
  bool finish(bool wait, std::vector<float>* samples);

 private:
  void resize(int columns, int rows);
  GLuint program_ = 0, vertex_array_ = 0, framebuffer_ = 0, target_ = 0, buffer_ = 0;
  int columns_ = 0, rows_ = 0;
  GLsync fence_ = nullptr;
};

}  // namespace pfx::inject
