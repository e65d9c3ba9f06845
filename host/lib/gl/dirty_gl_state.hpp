// An engine's leftover GL state: every item of the GL state contract (docs/sdk.md §1.5) that
// could change a pass, set away from what a chain needs, and read back with glGet. The GL runtime
// tests and pfx-validate render under it to show that a chain's output does not depend on what
// the engine left behind, and that the engine finds its state as it left it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glad/gl.h>

namespace pfx::app {

struct DirtyGlItem {
  std::string name;                           // "glPolygonMode(GL_LINE)"
  std::function<void()> make_dirty;           // the engine's leftover value
  std::function<void()> make_clean;           // back to the value of a fresh context
  std::function<std::vector<double>()> read;  // every value the item sets, as glGet reads it
};

class DirtyGlState {
 public:
  // Needs the current context (with this program's GL functions loaded): makes the buffer,
  // textures, sampler, program, vertex array, framebuffer and so on that the items bind.
  DirtyGlState();
  ~DirtyGlState();
  DirtyGlState(const DirtyGlState&) = delete;
  DirtyGlState& operator=(const DirtyGlState&) = delete;

  const std::vector<DirtyGlItem>& items() const { return items_; }
  void make_all_dirty() const;
  void make_all_clean() const;
  // One entry per item, in order.
  std::vector<std::vector<double>> read_all() const;

 private:
  void add_capabilities();
  void add_fragment_state();
  void add_pixel_store();
  void add_bindings();

  GLuint buffer_ = 0, texture_ = 0, cube_texture_ = 0, sampler_ = 0, program_ = 0, pipeline_ = 0;
  GLuint vertex_array_ = 0, framebuffer_ = 0, renderbuffer_ = 0, feedback_ = 0;
  std::vector<DirtyGlItem> items_;
};

}  // namespace pfx::app
