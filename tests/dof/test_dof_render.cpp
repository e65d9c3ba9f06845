// Real input through pfx-render as a user runs it: a multi-channel EXR (RGBA, Z and channels pfx
// does not use) whose data window is offset inside its display window, blurred by
// `--chain dof` with the camera from --camera, against the CPU model of the same frame.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include "camera_options.hpp"
#include "dof_params.hpp"
#include "exr_io.hpp"
#include "image_texture.hpp"
#include "reference/dof_gather_model.hpp"

namespace fs = std::filesystem;

namespace {

// 64x48 display window; data in (5,3)-(58,40). A subject at 5 m in front of a wall at 30 m, plus
// normals and an object id the effect must ignore.
void write_multichannel(const std::string& path) {
  const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(63, 47)), data(Imath::V2i(5, 3), Imath::V2i(58, 40));
  const int w = data.max.x - data.min.x + 1, h = data.max.y - data.min.y + 1;
  const char* names[] = {"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "objectId"};
  std::vector<std::vector<float>> planes(9, std::vector<float>(static_cast<size_t>(w) * h, 0.0f));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const bool subject = x > 20 && x < 34 && y > 10 && y < 30;
      planes[0][i] = subject ? 1.0f : float((x / 3 + y / 5) % 4) * 0.125f;
      planes[1][i] = subject ? 0.875f : 0.25f;
      planes[2][i] = subject ? 0.5f : float(x % 7) * 0.0625f;
      planes[3][i] = 1.0f;
      planes[4][i] = subject ? 5.0f : 30.0f;
      planes[5][i] = 0.0f;
      planes[6][i] = 0.0f;
      planes[7][i] = 1.0f;
      planes[8][i] = subject ? 7.0f : 1.0f;
    }
  Imf::Header header(display, data);
  Imf::FrameBuffer fb;
  for (int c = 0; c < 9; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, planes[c].data(), data));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(fb);
  file.writePixels(h);
}

}  // namespace

TEST_CASE("pfx-render --input multi-channel EXR with an offset data window --chain dof", "[dof][render]") {
  const fs::path dir = fs::temp_directory_path() / ("pfx-dof-render-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string input = (dir / "in.exr").string(), output = (dir / "out.exr").string();
  write_multichannel(input);
  const std::string command = std::string(PFX_RENDER) + " --plugins " PFX_DOF_PLUGIN_DIR " --input " + input +
                              " --chain dof --camera fovy=40,near=0.1,far=500 --set dof.focus_distance=5"
                              " --set dof.f_number=0.1 --set dof.resolution=full --out " + output + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);

  pfx::app::Image in, out;
  std::string error;
  REQUIRE(pfx::app::read_exr(input, &in, &error));
  REQUIRE(pfx::app::read_exr(output, &out, &error));
  REQUIRE(out.width == 64);
  REQUIRE(out.height == 48);
  // The model of what pfx-render ran: the frame as read (outside the data window: black at infinity).
  pfx::app::CameraOptions camera;
  camera.fovy_degrees = 40;
  camera.far_plane = 500;
  pfx_frame frame{};
  frame.struct_size = sizeof frame;
  frame.width = 64;
  frame.height = 48;
  frame.inputs = PFX_INPUT_COLOR | PFX_INPUT_DEPTH;
  frame.depth_encoding = PFX_DEPTH_LINEAR;
  frame.camera = pfx::app::make_camera(camera, 64, 48);
  pfx_value values[pfx_dof::PARAM_COUNT];
  for (uint32_t i = 0; i < pfx_dof::PARAM_COUNT; ++i) values[i] = pfx_dof::kParams[i].default_value;
  pfx_dof::Settings s = pfx_dof::settings_from(values);
  s.focus_distance = 5;
  s.f_number = 0.1;
  s.resolution = pfx_dof::RESOLUTION_FULL;
  std::vector<float> color_gl = pfx::app::flip_rows(in.rgba, 64, 48, 4);
  std::vector<float> depth_gl = pfx::app::flip_rows(in.depth, 64, 48, 1);
  std::vector<float> model(color_gl.size());
  pfx_dof::evaluate_gather_model(s, frame, color_gl.data(), depth_gl.data(), model.data());
  model = pfx::app::flip_rows(model, 64, 48, 4);
  int blurred = 0;
  for (size_t i = 0; i < model.size(); ++i) {
    if (i % 4 == 3) continue;
    INFO("value " << i);
    // Half-float storage (texture and file) and float arithmetic: within 1%, and 0.002 near black.
    REQUIRE(std::fabs(out.rgba[i] - model[i]) <= 0.01 * std::fabs(model[i]) + 0.002);
    blurred += std::fabs(out.rgba[i] - in.rgba[i]) > 0.01;
  }
  CHECK(blurred > 1000);
  // The subject (in focus, away from the wall's blur) is reproduced exactly.
  const size_t centre = (static_cast<size_t>(3 + 20) * 64 + (5 + 27)) * 4;
  CHECK(out.rgba[centre] == in.rgba[centre]);
  fs::remove_all(dir);
}
