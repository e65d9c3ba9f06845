// pfx-dof-scene: writes the synthetic depth-of-field scene (dof_scene.hpp) as files pfx-render and
// pfx-bench read: the pinhole frame with its depth, the lens-sampled ground truth, and the sharp
// subject's mask for the halo measure. A developer tool beside the reference it renders; it uses
// the host's EXR writer, which the plugin never does.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "camera_options.hpp"
#include "cli_text.hpp"
#include "dof_camera.hpp"
#include "exr_io.hpp"
#include "image_texture.hpp"
#include "reference/dof_scene.hpp"

namespace {

const char* const kUsage =
    "usage: pfx-dof-scene --size WxH [--camera fovy=45] [--focus M] [--f-number N] [--sensor MM]\n"
    "                     [--lens-samples N] --out DIR\n"
    "\n"
    "Renders the synthetic depth-of-field scene (plugins/dof/reference/dof_scene.hpp) by casting rays\n"
    "in double precision and writes, each file whole or not at all:\n"
    "  DIR/frame.exr    the pinhole frame: RGB (float) and Z, linear view depth in metres\n"
    "  DIR/truth.exr    the thin-lens ground truth: every pixel averaged over --lens-samples rays\n"
    "                   from points spread over the aperture, through the plane in focus\n"
    "  DIR/subject.exr  R = 1 where the pinhole frame shows the sharp subject (for --halo-mask)\n"
    "\n"
    "The lens is dof's (dof_camera.hpp): give the same values to the effect, e.g.\n"
    "  pfx-bench --input DIR/frame.exr --truth DIR/truth.exr --halo-mask DIR/subject.exr \\\n"
    "            --set dof.focus_distance=5 --set dof.f_number=0.6 --effects dof\n"
    "\n"
    "  --size WxH          frame size\n"
    "  --camera fovy=DEG   vertical field of view (default 45; near and far are ignored)\n"
    "  --focus M           focus distance in metres (default 5: the subject's front face)\n"
    "  --f-number N        default 1.4\n"
    "  --sensor MM         sensor width (default 36)\n"
    "  --lens-samples N    rays per pixel (default 256; rounded up to a square of a multiple of 4)\n"
    "  --out DIR           output folder (made if missing)\n"
    "exit codes: 0 ok, 1 a file could not be written, 2 usage\n";

int usage_error(const std::string& message) {
  std::fprintf(stderr, "pfx-dof-scene: %s\n\n%s", message.c_str(), kUsage);
  return 2;
}

bool number(const std::string& text, double lo, double* out) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !(v >= lo) || std::isinf(v)) return false;
  *out = v;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  int width = 0, height = 0;
  double focus = pfx_dof::kSceneFocusDistance, f_number = 1.4, sensor = 36, samples = 256;
  pfx::app::CameraOptions camera;
  std::string out, error;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (i + 1 >= args.size()) return usage_error(arg + " needs a value (or is unknown)");
    const std::string& value = args[++i];
    if (arg == "--size") {
      if (!pfx::app::parse_frame_size("--size", value, &width, &height, &error)) return usage_error(error);
    } else if (arg == "--camera") {
      if (!pfx::app::parse_camera_options(value, &camera, &error)) return usage_error(error);
    } else if (arg == "--focus") {
      if (!number(value, pfx_dof::kMinFocusDistance, &focus)) return usage_error("--focus " + value + ": expected metres >= 0.001");
    } else if (arg == "--f-number") {
      if (!number(value, pfx_dof::kMinFNumber, &f_number)) return usage_error("--f-number " + value + ": expected >= 0.05");
    } else if (arg == "--sensor") {
      if (!number(value, 1, &sensor)) return usage_error("--sensor " + value + ": expected millimetres >= 1");
    } else if (arg == "--lens-samples") {
      if (!number(value, 1, &samples) || samples > 65536) return usage_error("--lens-samples " + value + ": expected 1..65536");
    } else if (arg == "--out") {
      out = value;
    } else {
      return usage_error("unknown option '" + arg + "'");
    }
  }
  if (!width || out.empty()) return usage_error("--size and --out are required");

  pfx_frame frame{};
  frame.struct_size = sizeof frame;
  frame.width = static_cast<uint32_t>(width);
  frame.height = static_cast<uint32_t>(height);
  frame.depth_encoding = PFX_DEPTH_LINEAR;
  frame.camera = pfx::app::make_camera(camera, width, height);
  pfx_dof::Settings settings;
  settings.f_number = f_number;
  settings.sensor_width = sensor;
  const pfx_dof::Lens lens = pfx_dof::make_lens(frame, settings, focus);

  const pfx_dof::SceneFrame pinhole = pfx_dof::render_pinhole(frame);
  pfx::app::Image image, truth, subject;
  image.width = truth.width = subject.width = width;
  image.height = truth.height = subject.height = height;
  // The renderer's rows are bottom first (as GL's); EXR rows are top first.
  auto top_first = [&](const std::vector<float>& data, int channels) {
    return pfx::app::flip_rows(data, width, height, channels);
  };
  image.rgba = top_first(pinhole.rgba, 4);
  image.depth = top_first(pinhole.depth, 1);
  std::fprintf(stderr, "pfx-dof-scene: %dx%d, aperture %.3f mm, focus %.3f m, %g lens samples...\n", width, height,
               lens.aperture_mm, lens.focus_distance_m, samples);
  truth.rgba = top_first(pfx_dof::render_lens_truth(frame, lens.aperture_mm / 1000.0, lens.focus_distance_m,
                                                     static_cast<int>(samples)),
                         4);
  std::vector<float> mask(pinhole.object.size() * 4, 0.0f);
  for (size_t i = 0; i < pinhole.object.size(); ++i) {
    const float v = pinhole.object[i] == pfx_dof::OBJECT_SUBJECT ? 1.0f : 0.0f;
    mask[i * 4] = mask[i * 4 + 1] = mask[i * 4 + 2] = v;
    mask[i * 4 + 3] = 1.0f;
  }
  subject.rgba = top_first(mask, 4);

  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) {
    std::fprintf(stderr, "pfx-dof-scene: cannot create %s: %s\n", out.c_str(), ec.message().c_str());
    return 1;
  }
  for (const auto& [name, img] : {std::pair<const char*, const pfx::app::Image*>{"frame.exr", &image},
                                  {"truth.exr", &truth}, {"subject.exr", &subject}})
    if (!pfx::app::write_exr(out + "/" + name, *img, pfx::app::ExrPixelType::Float, &error)) {
      std::fprintf(stderr, "pfx-dof-scene: %s\n", error.c_str());
      return 1;
    }
  std::fprintf(stderr, "pfx-dof-scene: wrote %s/frame.exr, truth.exr, subject.exr\n", out.c_str());
  return 0;
}
