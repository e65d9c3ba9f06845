#include "gl_test_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

#include "camera_options.hpp"
#include "image_texture.hpp"

namespace pfx::test {

pfx::app::HeadlessContext& gl_context() {
  static std::unique_ptr<pfx::app::HeadlessContext> context;
  static std::string error;
  if (!context) context = pfx::app::HeadlessContext::create(&error);
  INFO(error);
  REQUIRE(context);
  return *context;
}

std::unique_ptr<pfx::host::PluginRegistry> make_registry(CollectedLog* log) {
  gl_context();
  pfx::host::LogSink sink = [log](pfx_log_level level, const std::string& source, const std::string& message) {
    if (log) log->lines.push_back(std::string(pfx::host::log_level_name(level)) + " " + source + ": " + message);
  };
  return std::make_unique<pfx::host::PluginRegistry>(
      [](const char* name) { return pfx::app::HeadlessContext::get_proc_address(nullptr, name); }, sink, "pfx-tests");
}

pfx_frame make_frame(int width, int height) {
  pfx_frame frame{};
  frame.struct_size = sizeof frame;
  frame.width = static_cast<uint32_t>(width);
  frame.height = static_cast<uint32_t>(height);
  frame.inputs = PFX_INPUT_COLOR;
  frame.camera = pfx::app::make_camera(pfx::app::CameraOptions{}, width, height);
  frame.light_struct_size = sizeof(pfx_light);
  return frame;
}

pfx::app::Image test_image(int width, int height) {
  pfx::app::Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(img.pixel_count() * 4);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = &img.rgba[(static_cast<size_t>(y) * width + x) * 4];
      p[0] = -1.0f + 9.0f * float(x) / float(width > 1 ? width - 1 : 1);
      p[1] = 0.25f * float((x * 7 + y * 3) % 5);
      p[2] = 0.5f + 0.5f * std::sin(0.3f * float(x + 2 * y));
      p[3] = 1.0f;
    }
  return img;
}

ChainRig::ChainRig(const char* plugin_path) {
  std::string error;
  INFO(error);
  REQUIRE(registry->load(plugin_path, &error));
  chain = std::make_unique<pfx::host::Chain>(*registry, params);
}

void ChainRig::add(const std::string& effect) {
  std::string error;
  INFO(error);
  REQUIRE(chain->add(effect, &error));
}

void ChainRig::set(const std::string& assignment) {
  std::string error;
  INFO(error);
  REQUIRE(params.set_assignment(assignment, &error));
}

pfx::app::Image ChainRig::render(const pfx::app::Image& img) {
  pfx::host::FrameTextures textures;
  textures.color = pfx::app::upload_color_texture(img);
  const uint32_t output = pfx::app::create_color_texture(img.width, img.height);
  std::string error;
  const bool ok = chain->render(make_frame(img.width, img.height), textures, output, &error);
  pfx::app::Image result = pfx::app::download_color_texture(output, img.width, img.height);
  pfx::app::delete_texture(textures.color);
  pfx::app::delete_texture(output);
  INFO(error);
  REQUIRE(ok);
  return result;
}

}  // namespace pfx::test
