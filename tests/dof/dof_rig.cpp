#include "dof_rig.hpp"

#include <catch2/catch.hpp>

#include <cmath>

#include <glad/gl.h>

#include "camera_options.hpp"
#include "image_texture.hpp"

namespace dof_test {

Frame::Frame(int w, int h)
    : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, 0.0f), depth(static_cast<size_t>(w) * h, 20.0f) {
  for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 1.0f;
}

pfx_frame Frame::frame() const {
  pfx::app::CameraOptions options;
  options.fovy_degrees = fovy_degrees;
  options.near_plane = near_plane;
  options.far_plane = far_plane;
  pfx_frame f{};
  f.struct_size = sizeof f;
  f.width = static_cast<uint32_t>(width);
  f.height = static_cast<uint32_t>(height);
  f.inputs = PFX_INPUT_COLOR | PFX_INPUT_DEPTH;
  f.depth_encoding = encoding;
  f.camera = pfx::app::make_camera(options, width, height);
  f.light_struct_size = sizeof(pfx_light);
  return f;
}

Frame scene(int width, int height, double focus_hint) {
  Frame f(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* c = f.at(x, y);
      // Multiples of 1/64 below 1: exact in half.
      c[0] = float((x * 5 + y * 3) % 48) / 64.0f;
      c[1] = float((x * 2 + y * 7) % 40) / 64.0f;
      c[2] = float((x + y) % 56) / 64.0f;
      f.z(x, y) = 20.0f;
      if (x > width / 8 && x < width / 2 && y > height / 4 && y < 3 * height / 4) {  // near square
        c[0] = 0.875f, c[1] = 0.25f, c[2] = 0.125f;
        f.z(x, y) = 1.5f;
      } else if (x >= width / 2 && x < width / 2 + std::max(2, width / 6)) {  // the in-focus strip
        c[0] = (y % 4 < 2) ? 1.0f : 0.0625f, c[1] = c[0], c[2] = c[0];
        f.z(x, y) = static_cast<float>(focus_hint);
      }
    }
  const int points[][2] = {{width * 3 / 4, height / 3}, {width / 4, height / 2}, {width - 1, height - 1}};
  const float brightness[] = {40.0f, 12.0f, 6.0f};
  for (int i = 0; i < 3; ++i) {
    float* c = f.at(std::min(points[i][0], width - 1), std::min(points[i][1], height - 1));
    c[0] = brightness[i], c[1] = brightness[i] * 0.75f, c[2] = brightness[i] * 0.5f;
  }
  return f;
}

Rig::Rig() : registry_(pfx::test::make_registry(&log_)) {
  std::string error;
  const bool loaded = registry_->load(PFX_DOF_PLUGIN, &error);
  INFO(error);
  REQUIRE(loaded);
  const pfx::host::EffectInfo* info = registry_->find_effect("dof");
  REQUIRE(info);
  references_ = info->plugin->references;
  REQUIRE(references_);
  chain_ = std::make_unique<pfx::host::Chain>(*registry_, params_);
  REQUIRE(chain_->add("dof", &error));
}

void Rig::set(const std::string& assignment) {
  std::string error;
  const bool ok = params_.set_assignment(assignment, &error);
  INFO(assignment << ": " << error);
  REQUIRE(ok);
}

namespace {

uint32_t upload_depth(const Frame& frame, DepthTexture kind) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  const bool depth_format = kind == DepthTexture::DEPTH_COMPONENT32F;
  glTextureStorage2D(texture, 1, depth_format ? GL_DEPTH_COMPONENT32F : GL_R32F, frame.width, frame.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(texture, 0, 0, 0, frame.width, frame.height, depth_format ? GL_DEPTH_COMPONENT : GL_RED,
                      GL_FLOAT, frame.depth.data());
  return texture;
}

uint32_t upload_color(const Frame& frame) {
  pfx::app::Image img;
  img.width = frame.width;
  img.height = frame.height;
  img.rgba = pfx::app::flip_rows(frame.rgba, frame.width, frame.height, 4);  // Image rows are top first
  return pfx::app::upload_color_texture(img);
}

std::vector<float> download(uint32_t texture, int w, int h) {
  return pfx::app::flip_rows(pfx::app::download_color_texture(texture, w, h).rgba, w, h, 4);
}

}  // namespace

bool Rig::try_render(const Frame& frame, std::string* error, bool with_depth) {
  pfx::host::FrameTextures textures;
  textures.color = upload_color(frame);
  if (with_depth) textures.depth = upload_depth(frame, DepthTexture::R32F);
  const uint32_t output = pfx::app::create_color_texture(frame.width, frame.height);
  pfx_frame f = frame.frame();
  if (!with_depth) {
    f.inputs &= ~static_cast<uint32_t>(PFX_INPUT_DEPTH);
    f.depth_encoding = PFX_DEPTH_NONE;
  }
  const bool ok = chain_->render(f, textures, output, error);
  pfx::app::delete_texture(textures.color);
  pfx::app::delete_texture(textures.depth);
  pfx::app::delete_texture(output);
  return ok;
}

Rendered Rig::render(const Frame& frame, DepthTexture depth_texture) {
  pfx::host::FrameTextures textures;
  textures.color = upload_color(frame);
  textures.depth = upload_depth(frame, depth_texture);
  const uint32_t output = pfx::app::create_color_texture(frame.width, frame.height);
  const pfx_frame f = frame.frame();
  std::string error;
  const bool ok = chain_->render(f, textures, output, &error);
  INFO(error);
  REQUIRE(ok);
  Rendered r;
  r.input = frame;
  r.input.rgba = download(textures.color, frame.width, frame.height);
  r.output = download(output, frame.width, frame.height);
  r.passes = chain_->report().passes.size();
  pfx::app::delete_texture(textures.color);
  pfx::app::delete_texture(textures.depth);
  pfx::app::delete_texture(output);
  if (references_->has_reference("dof", PFX_REFERENCE_MODEL)) r.model = reference(*this, r.input, PFX_REFERENCE_MODEL);
  return r;
}

Rig& shared_rig(const std::string& mode) {
  static Rig* rig = nullptr;
  if (!rig) rig = new Rig;
  for (const char* assignment : {"dof.focus_distance=5", "dof.f_number=0.1", "dof.max_coc=32", "dof.autofocus=off",
                                 "dof.focus_point=0.5,0.5", "dof.sensor_width=36", "dof.samples=32",
                                 "dof.resolution=half", "dof.nonfinite=zero"})
    rig->set(assignment);
  rig->set("dof.mode=" + mode);
  return *rig;
}

std::vector<float> reference(const Rig& rig, const Frame& frame, pfx_reference_kind kind) {
  const pfx_frame f = frame.frame();
  std::vector<float> out(frame.rgba.size());
  pfx_reference_request request{};
  request.struct_size = sizeof request;
  request.effect_id = "dof";
  request.kind = kind;
  request.frame = &f;
  request.params = rig.values();
  request.color = frame.rgba.data();
  request.depth = frame.depth.data();
  request.output = out.data();
  REQUIRE(rig.references()->evaluate(&request) == PFX_OK);
  return out;
}

bool all_finite(const std::vector<float>& rgba) {
  for (float v : rgba)
    if (!std::isfinite(v)) return false;
  return true;
}

double max_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (i % 4 != 3) worst = std::fmax(worst, std::fabs(double(a[i]) - double(b[i])));
  return worst;
}

}  // namespace dof_test
