// What the viewer shows, as the chain's frame inputs: the G-buffer of the demo scene or of a model
// imported through the importer plugins (rendered again when the camera or the size changes), the
// procedural demo image (made again when the size changes) or an image (its own size, always): an
// EXR in linear light, or a PNG kept as its 8-bit sRGB codes, as pfx-render and every host of
// 8-bit frames keep one, so an all-FX chain reads and writes the codes and nothing converts them.
#pragma once

#include <memory>
#include <string>

#include <pfx/host/chain.hpp>

#include "eight_bit_texture.hpp"
#include "gbuffer.hpp"
#include "image.hpp"
#include "scene.hpp"
#include "view_options.hpp"

namespace pfx::app {

class FrameSource {
 public:
  // Builds the scene or reads the image (GL context current). Null with *error; *bad_input tells
  // a bad input file (exit code 3) from a GL failure (1).
  static std::unique_ptr<FrameSource> create(const ViewOptions& options, const pfx::host::PluginRegistry& registry,
                                             std::string* error, bool* bad_input);
  // Warnings of the import (unread textures, skipped lines), for the messages.
  const std::vector<std::string>& warnings() const { return warnings_; }
  ~FrameSource();
  FrameSource(const FrameSource&) = delete;
  FrameSource& operator=(const FrameSource&) = delete;

  bool has_scene() const { return renderer_ != nullptr; }
  // Null without a scene.
  const Scene* scene() const { return renderer_ ? &scene_ : nullptr; }
  // The scene's camera (place and lens), or for an image a camera at the origin looking down -Z
  // whose lens the effects see.
  Camera& camera() { return camera_; }
  const Camera& camera() const { return camera_; }
  // The camera the scene (or the image's default lens) started with.
  const Camera& initial_camera() const { return initial_camera_; }

  // Makes the inputs for a frame of (about) this size: an image keeps its own size. Renders the
  // scene again when force is set or the camera or size changed.
  void prepare(int width, int height, bool force);
  int width() const { return width_; }
  int height() const { return height_; }
  pfx_frame frame(double time_seconds, uint64_t frame_index) const;
  pfx::host::FrameTextures textures() const;
  // An 8-bit picture: the frame's colour is an sRGB view of its codes, and the chain's result
  // belongs in 8-bit sRGB codes too. channels(): 3 or 4, what the file held.
  bool display_referred() const { return codes_.texture != 0; }
  int channels() const { return channels_; }
  // One line for the UI: "demo scene (400 lights)", "IMG.exr 640x480 with depth"...
  const std::string& description() const { return description_; }

 private:
  FrameSource() = default;
  void upload_image(const Image& image);
  void release_image();
  bool load_codes(const ViewOptions& options, std::string* error);

  ViewInput kind_ = ViewInput::DemoScene;
  Scene scene_;
  std::unique_ptr<SceneRenderer> renderer_;
  Camera camera_, initial_camera_, rendered_camera_;
  bool rendered_once_ = false;
  bool has_depth_ = false;
  uint32_t color_ = 0, depth_ = 0;
  gl::EightBitTexture codes_;
  int channels_ = 4;
  int width_ = 0, height_ = 0;
  std::string description_;
  std::vector<std::string> warnings_;
};

}  // namespace pfx::app
