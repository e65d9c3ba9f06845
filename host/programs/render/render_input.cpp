#include "render_input.hpp"

#include <cstdio>

#include "camera_settings.hpp"
#include "demo_image.hpp"
#include "demo_scene.hpp"
#include "exit_codes.hpp"
#include "frame_description.hpp"
#include "image_texture.hpp"
#include "import_scene.hpp"

namespace pfx::app {

RenderInput::~RenderInput() {
  if (!uploaded_) return;
  delete_texture(textures_.color);
  delete_texture(textures_.depth);
}

int RenderInput::load_scene(const RenderOptions& options, const PresetCamera& camera,
                            const host::PluginRegistry& registry, std::string* message) {
  if (options.demo) {
    scene_ = make_demo_scene({options.extra_lights, options.seed});
  } else {
    import::SceneImportOptions import_options;
    import_options.seed = options.seed;
    if (options.lights_given) import_options.lights = options.extra_lights;
    std::vector<std::string> warnings;
    if (!import::load_scene_from_model(registry, options.scene, import_options, &scene_, &warnings, message))
      return exit_code::kBadInput;
    for (const auto& warning : warnings) std::fprintf(stderr, "pfx-render: warning: %s\n", warning.c_str());
  }
  apply_preset_camera(camera, &scene_.camera);
  if (!validate_scene(scene_, message)) {
    *message = "--camera: " + *message;
    return exit_code::kUsage;
  }
  scene_renderer_ = SceneRenderer::create(scene_, message);
  if (!scene_renderer_) return exit_code::kInternal;
  scene_renderer_->render(scene_.camera, options.width, options.height);
  frame_ = make_scene_frame(scene_, scene_.camera, options.width, options.height);
  textures_ = scene_renderer_->textures();
  return exit_code::kOk;
}

bool RenderInput::load_image(const RenderOptions& options, const std::string& input, const std::string& depth,
                             const PresetCamera& camera, DisplayInput* display, std::string* error) {
  Image image;
  if (options.demo_image) {
    image = make_demo_image(options.width, options.height);
  } else if (display) {
    if (!display->load(input, input_transfer(options), options.max_input_pixels, error)) return false;
    image.width = display->width();
    image.height = display->height();
    files_read_.color = display->description();
  } else {
    InputFiles files;
    files.input = input;
    files.layer = options.layer;
    files.depth = depth;
    files.limits.max_pixels = options.max_input_pixels;
    if (!read_input_image(files, &image, &files_read_, error)) return false;
  }
  CameraOptions lens;
  apply_preset_camera(camera, &lens);
  frame_ = describe_frame(image.width, image.height,
                          PFX_INPUT_COLOR | (image.has_depth() ? uint32_t(PFX_INPUT_DEPTH) : 0u), PFX_DEPTH_LINEAR,
                          make_camera(lens, image.width, image.height));
  if (display) {
    textures_.color = display->color();
    return true;
  }
  textures_.color = upload_color_texture(image);
  textures_.depth = upload_depth_texture(image);
  uploaded_ = true;
  return true;
}

}  // namespace pfx::app
