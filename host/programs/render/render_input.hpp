// The frame pfx-render runs the chain over and the GL textures it reads: the G-buffer of the demo
// scene or of an imported model (--demo, --scene), or an image (--demo-image, an --input file, one
// frame of a sequence). It owns what it made: the scene and its renderer, and the textures it
// uploaded (an 8-bit input's textures are the DisplayInput's).
#pragma once

#include <memory>
#include <string>

#include <pfx/host/chain.hpp>
#include <pfx/host/plugin_registry.hpp>

#include "display_input.hpp"
#include "gbuffer.hpp"
#include "image.hpp"
#include "input_image.hpp"
#include "preset.hpp"
#include "render_options.hpp"
#include "scene.hpp"

namespace pfx::app {

class RenderInput {
 public:
  RenderInput() = default;
  ~RenderInput();
  RenderInput(const RenderInput&) = delete;
  RenderInput& operator=(const RenderInput&) = delete;

  // --demo or --scene: the scene, seen by its own camera with `camera` over it (the preset's and
  // --camera's settings), its G-buffer rendered at --size. kOk, or an exit code (exit_codes.hpp)
  // with *message.
  int load_scene(const RenderOptions& options, const PresetCamera& camera, const host::PluginRegistry& registry,
                 std::string* message);
  // --demo-image, or the image file `input` (with `depth`, a file of linear depth, when not
  // empty), seen from the origin through the lens `camera` gives. An 8-bit input is decoded into
  // display's textures. False with *error "PATH: reason".
  bool load_image(const RenderOptions& options, const std::string& input, const std::string& depth,
                  const PresetCamera& camera, DisplayInput* display, std::string* error);

  const pfx_frame& frame() const { return frame_; }
  // Frame `number` of a sequence: its index, and its time at 24 frames a second (effects that
  // animate, ReShade FX's timer and framecount, see it advance).
  void set_sequence_frame(long long number) {
    frame_.frame_index = static_cast<uint64_t>(number < 0 ? 0 : number);
    frame_.time_seconds = static_cast<double>(number) / 24.0;
  }
  const host::FrameTextures& textures() const { return textures_; }
  // Which channels of the input (and depth) file became the frame, in words.
  const InputReport& files_read() const { return files_read_; }

 private:
  Scene scene_;  // the frame's lights point into it
  std::unique_ptr<SceneRenderer> scene_renderer_;
  pfx_frame frame_{};
  host::FrameTextures textures_;
  bool uploaded_ = false;  // textures_ are ours to delete
  InputReport files_read_;
};

}  // namespace pfx::app
