#include "lights_rig.hpp"

#include <catch2/catch.hpp>

#include <cmath>

#include <glad/gl.h>

#include "image_texture.hpp"
#include "shapes.hpp"

namespace lights_test {
namespace {

std::vector<float> read_texture(uint32_t texture, int width, int height, GLenum format, int channels) {
  std::vector<float> data(static_cast<size_t>(width) * height * channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(texture, 0, format, GL_FLOAT, static_cast<GLsizei>(data.size() * sizeof(float)), data.data());
  return data;
}

}  // namespace

Captured capture(const pfx::app::Scene& scene, int width, int height) {
  pfx::test::gl_context();
  Captured c;
  std::string error;
  c.renderer = pfx::app::SceneRenderer::create(scene, &error);
  INFO(error);
  REQUIRE(c.renderer);
  c.renderer->render(scene.camera, width, height);
  c.width = width;
  c.height = height;
  c.frame = pfx::app::make_scene_frame(scene, scene.camera, width, height);
  c.lights = scene.lights;
  c.frame.lights = c.lights.empty() ? nullptr : c.lights.data();
  c.textures = c.renderer->textures();
  c.color = read_texture(c.textures.color, width, height, GL_RGBA, 4);
  c.depth = read_texture(c.textures.depth, width, height, GL_RED, 1);
  c.normal = read_texture(c.textures.normal, width, height, GL_RGBA, 4);
  c.albedo = read_texture(c.textures.albedo, width, height, GL_RGBA, 4);
  c.emissive = read_texture(c.textures.emissive, width, height, GL_RGBA, 4);
  return c;
}

Rig::Rig() : registry_(pfx::test::make_registry(&log_)) {
  std::string error;
  INFO(error);
  REQUIRE(registry_->load(PFX_TILEDLIGHTS_PLUGIN, &error));
  const pfx::host::EffectInfo* info = registry_->find_effect("tiledlights");
  REQUIRE(info);
  references_ = info->plugin->references;
  REQUIRE(references_);
  chain_ = std::make_unique<pfx::host::Chain>(*registry_, params_);
  REQUIRE(chain_->add("tiledlights", &error));
}

void Rig::set(const std::string& assignment) {
  std::string error;
  INFO(assignment << ": " << error);
  REQUIRE(params_.set_assignment("tiledlights." + assignment, &error));
}

Rendered Rig::render(const Captured& captured) {
  const uint32_t output = pfx::app::create_color_texture(captured.width, captured.height);
  Rendered r;
  log_.lines.clear();
  if (chain_->render(captured.frame, captured.textures, output, &r.error)) {
    r.output = read_texture(output, captured.width, captured.height, GL_RGBA, 4);
    r.passes = chain_->report().passes.size();
    for (const auto& [effect, members] : chain_->report().effect_reports)
      if (effect == "tiledlights") r.report = nlohmann::json::parse("{" + members + "}");
  }
  pfx::app::delete_texture(output);
  r.log = log_.lines;
  return r;
}

std::vector<std::vector<float>> Rig::render_queued(const std::vector<Captured*>& frames) {
  std::vector<uint32_t> outputs;
  for (const Captured* c : frames) {
    outputs.push_back(pfx::app::create_color_texture(c->width, c->height));
    std::string error;
    INFO(error);
    REQUIRE(chain_->render(c->frame, c->textures, outputs.back(), &error));
  }
  std::vector<std::vector<float>> results;
  for (size_t i = 0; i < frames.size(); ++i) {
    results.push_back(read_texture(outputs[i], frames[i]->width, frames[i]->height, GL_RGBA, 4));
    pfx::app::delete_texture(outputs[i]);
  }
  return results;
}

std::vector<float> Rig::reference(const Captured& captured, pfx_reference_kind kind) {
  std::vector<float> out(captured.color.size());
  pfx_reference_request request{};
  request.struct_size = sizeof request;
  request.effect_id = "tiledlights";
  request.kind = kind;
  request.frame = &captured.frame;
  request.params = params_.values("tiledlights");
  request.color = captured.color.data();
  request.depth = captured.depth.data();
  request.normal = captured.normal.data();
  request.albedo = captured.albedo.data();
  request.emissive = captured.emissive.data();
  request.output = out.data();
  REQUIRE(references_->evaluate(&request) == PFX_OK);
  return out;
}

pfx::app::Scene floor_and_box() {
  using namespace pfx::app;
  Scene scene;
  Material floor, box;
  floor.albedo = glm::vec3(0.75f, 0.5f, 0.25f);
  box.albedo = glm::vec3(0.5f, 0.5f, 0.75f);
  box.emissive = glm::vec3(2.0f, 1.0f, 0.5f);
  scene.materials = {floor, box};
  scene.meshes.push_back(make_floor(glm::vec3(0), 20.0f, 1, 0));
  scene.meshes.push_back(make_box(glm::vec3(0, 0.5f, 0), glm::vec3(0.5f), 1));
  scene.camera.position = glm::dvec3(0, 3, 8);
  scene.camera.target = glm::dvec3(0, 0.5, 0);
  scene.camera.near_plane = 0.1;
  scene.camera.far_plane = 100;
  scene.ambient = glm::vec3(0.05f);
  update_bounds(&scene);
  return scene;
}

pfx_light point_light(float x, float y, float z, float r, float g, float b, float intensity, float range) {
  pfx_light light{};
  light.position[0] = x;
  light.position[1] = y;
  light.position[2] = z;
  light.color[0] = r;
  light.color[1] = g;
  light.color[2] = b;
  light.intensity = intensity;
  light.range = range;
  return light;
}

namespace {

// The GPU shades in float and stores RGBA16F; the reference works in double from the same
// G-buffer values. Every term is >= 0, so the sum is its own magnitude: half-float storage rounds
// by at most 2^-11 of it (2^-10 stated). Float arithmetic (the reconstructed position is good to a
// few 1e-7 of the distances; the window's slope is at most 6 / range) adds about 1e-5 of the
// sum; 1e-4 is stated. 1e-5 absolute covers sums near zero. The worst ratio seen on the tests'
// frames is about 0.3 of this tolerance; a 1% error in the light ranges exceeds it (a test).
double tolerance(float reference) { return (std::ldexp(1.0, -10) + 1e-4) * std::abs(reference) + 1e-5; }

}  // namespace

double worst_error_ratio(const std::vector<float>& gpu, const std::vector<float>& reference) {
  double worst = 0;
  for (size_t i = 0; i < gpu.size(); ++i)
    if (i % 4 != 3) worst = std::max(worst, std::abs(double(gpu[i]) - reference[i]) / tolerance(reference[i]));
  return worst;
}

void require_matches_reference(const Captured& captured, const std::vector<float>& gpu,
                               const std::vector<float>& reference) {
  REQUIRE(gpu.size() == reference.size());
  for (size_t i = 0; i < gpu.size(); ++i) {
    if (i % 4 == 3) continue;
    const size_t pixel = i / 4;
    INFO("pixel " << pixel % captured.width << "," << pixel / captured.width << " channel " << i % 4 << ": gpu "
                  << gpu[i] << ", reference " << reference[i]);
    REQUIRE(std::abs(double(gpu[i]) - reference[i]) <= tolerance(reference[i]));
  }
}

std::vector<float> check_modes(Rig& rig, const Captured& captured, bool against_reference) {
  rig.set("mode=brute");
  const Rendered brute = rig.render(captured);
  INFO(brute.error << (brute.log.empty() ? "" : "; " + brute.log.back()));
  REQUIRE(brute.error.empty());
  if (against_reference) require_matches_reference(captured, brute.output, rig.reference(captured, PFX_REFERENCE_MODEL));
  for (const char* mode : {"cpu8x4", "tiled", "clustered"}) {
    INFO("mode " << mode);
    rig.set(std::string("mode=") + mode);
    const Rendered culled = rig.render(captured);
    INFO(culled.error << (culled.log.empty() ? "" : "; " + culled.log.back()));
    REQUIRE(culled.error.empty());
    check_list_figures(culled.report);
    require_identical(culled.output, brute.output, captured.width);
  }
  return brute.output;
}

void check_list_figures(const nlohmann::json& report) {
  INFO(report.dump());
  CHECK(report["inconsistent_lists"] == 0);
  const uint64_t entries = report["list_entries"], lists = report["lists"], longest = report["list_max"];
  CHECK(report["list_mean"].get<double>() == Approx(lists ? double(entries) / double(lists) : 0.0).margin(5e-4));  // %.3f
  CHECK(longest <= entries);
  CHECK(longest <= report["lights_uploaded"].get<uint64_t>());
  if (report["mode"] == "tiled" || report["mode"] == "clustered") {
    // The CPU's bound sized the index buffer; the GPU's count is within it.
    CHECK(entries <= report["list_bound"].get<uint64_t>());
    CHECK(entries <= report["index_capacity"].get<uint64_t>());
    CHECK(report["list_readbacks"] == 0);
  }
}

void require_identical(const std::vector<float>& a, const std::vector<float>& b, int width) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    const size_t pixel = i / 4;
    INFO("pixel " << pixel % width << "," << pixel / width << " channel " << i % 4);
    REQUIRE(a[i] == b[i]);
  }
}

}  // namespace lights_test
