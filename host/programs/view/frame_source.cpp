#include "frame_source.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "camera_settings.hpp"
#include "demo_image.hpp"
#include "demo_scene.hpp"
#include "display_transfer.hpp"
#include "frame_description.hpp"
#include "image_texture.hpp"
#include "import_scene.hpp"
#include "input_image.hpp"
#include "png_io.hpp"

namespace pfx::app {
namespace {

bool same_camera(const Camera& a, const Camera& b) {
  return a.position == b.position && a.target == b.target && a.up == b.up && a.fovy_radians == b.fovy_radians &&
         a.near_plane == b.near_plane && a.far_plane == b.far_plane;
}

CameraOptions lens_of(const Camera& camera) {
  CameraOptions lens;
  lens.fovy_degrees = camera.fovy_radians * 180.0 / M_PI;
  lens.near_plane = camera.near_plane;
  lens.far_plane = camera.far_plane;
  return lens;
}

// --input IMG.exr, as pfx-render reads it.
bool read_exr_input(const ViewOptions& options, Image* image, InputReport* report, std::string* error) {
  InputFiles files;
  files.input = options.input_path;
  files.layer = options.layer;
  files.depth = options.depth_path;
  return read_input_image(files, image, report, error);
}

}  // namespace

std::unique_ptr<FrameSource> FrameSource::create(const ViewOptions& options, const pfx::host::PluginRegistry& registry,
                                                 std::string* error, bool* bad_input) {
  std::unique_ptr<FrameSource> self(new FrameSource);
  self->kind_ = options.input;
  *bad_input = false;
  if (options.input == ViewInput::DemoScene || options.input == ViewInput::ModelScene) {
    if (options.input == ViewInput::DemoScene) {
      self->scene_ = make_demo_scene({options.extra_lights, options.seed});
      self->description_ = "demo scene";
    } else {
      // As pfx-render --scene does it, so a preset gives the same picture in both.
      pfx::import::SceneImportOptions import_options;
      import_options.seed = options.seed;
      if (options.lights_given) import_options.lights = options.extra_lights;
      if (!pfx::import::load_scene_from_model(registry, options.scene_path, import_options, &self->scene_,
                                              &self->warnings_, error)) {
        *bad_input = true;
        return nullptr;
      }
      self->description_ = options.scene_path;
    }
    self->description_ += " (" + std::to_string(self->scene_.lights.size()) + " lights)";
    self->renderer_ = SceneRenderer::create(self->scene_, error);
    if (!self->renderer_) return nullptr;
    self->camera_ = self->scene_.camera;
  } else {
    // An image's camera sits at the origin looking down -Z (as in pfx-render).
    self->camera_.position = glm::dvec3(0.0);
    self->camera_.target = glm::dvec3(0.0, 0.0, -1.0);
    apply_camera_keys(CameraOptions{}, {"fovy", "near", "far"}, &self->camera_);
    if (options.input == ViewInput::Image && is_display_input(options.input_path)) {
      if (!self->load_codes(options, error)) {
        *bad_input = true;
        return nullptr;
      }
    } else if (options.input == ViewInput::Image) {
      Image image;
      InputReport report;
      if (!read_exr_input(options, &image, &report, error)) {
        *bad_input = true;
        return nullptr;
      }
      self->upload_image(image);
      self->description_ = options.input_path + " " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                           " (" + report.color + ")" +
                           (options.depth_path.empty() ? "" : ", " + options.depth_path + " (" + report.depth + ")");
    } else {
      self->description_ = "demo image";
    }
  }
  self->initial_camera_ = self->camera_;
  return self;
}

FrameSource::~FrameSource() {
  release_image();
  codes_.release();
}

bool FrameSource::load_codes(const ViewOptions& options, std::string* error) {
  if (!options.depth_path.empty() || !options.layer.empty()) {
    *error = options.input_path + ": --depth and --layer go with an EXR input, not a PNG";
    return false;
  }
  DisplayImage encoded;
  if (!read_png(options.input_path, &encoded, error)) return false;
  codes_.create(encoded.width, encoded.height);
  codes_.upload_top_first(encoded.rgba_pixels().data(), encoded.width, encoded.height);
  width_ = encoded.width;
  height_ = encoded.height;
  channels_ = encoded.channels;
  description_ = options.input_path + " " + std::to_string(width_) + "x" + std::to_string(height_) + " (" +
                 (channels_ == 4 ? "R, G, B, A" : "R, G, B") + ", 8-bit sRGB)";
  return true;
}

void FrameSource::upload_image(const Image& image) {
  release_image();
  color_ = upload_color_texture(image);
  depth_ = upload_depth_texture(image);
  has_depth_ = image.has_depth();
  width_ = image.width;
  height_ = image.height;
}

void FrameSource::release_image() {
  delete_texture(color_);
  delete_texture(depth_);
  color_ = depth_ = 0;
}

void FrameSource::prepare(int width, int height, bool force) {
  width = std::max(width, 1);
  height = std::max(height, 1);
  switch (kind_) {
    case ViewInput::Image:
      return;
    case ViewInput::DemoImage:
      if (width != width_ || height != height_) upload_image(make_demo_image(width, height));
      return;
    case ViewInput::DemoScene:
    case ViewInput::ModelScene:
      if (force || !rendered_once_ || width != width_ || height != height_ || !same_camera(camera_, rendered_camera_)) {
        renderer_->render(camera_, width, height);
        rendered_camera_ = camera_;
        rendered_once_ = true;
        width_ = width;
        height_ = height;
      }
      return;
  }
}

pfx_frame FrameSource::frame(double time_seconds, uint64_t frame_index) const {
  const uint32_t image_inputs = PFX_INPUT_COLOR | (has_depth_ ? uint32_t(PFX_INPUT_DEPTH) : 0u);
  pfx_frame frame = renderer_ ? make_scene_frame(scene_, camera_, width_, height_)
                              : describe_frame(width_, height_, image_inputs, PFX_DEPTH_LINEAR,
                                               make_camera(lens_of(camera_), width_, height_));
  frame.time_seconds = time_seconds;
  frame.frame_index = frame_index;
  return frame;
}

pfx::host::FrameTextures FrameSource::textures() const {
  if (renderer_) return renderer_->textures();
  pfx::host::FrameTextures textures;
  textures.color = codes_.texture ? codes_.srgb_view : color_;
  textures.depth = depth_;
  return textures;
}

}  // namespace pfx::app
