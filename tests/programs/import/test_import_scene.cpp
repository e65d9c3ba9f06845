// pfx-render --scene: a model through the importer into the scene model (sub-meshes, materials,
// the demo's lights, a camera framing the bounds), checked without GL; and the command end to end.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "import_scene.hpp"

namespace fs = std::filesystem;

namespace {

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("pfx-import-scene-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  }
};

const char* const kPyramid =
    "mtllib p.mtl\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 1.5 0\n"
    "usemtl floor\nf 1 4 3 2\nusemtl glow\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
const char* const kPyramidMtl = "newmtl floor\nKd 0.7 0.6 0.5\nnewmtl glow\nKd 0.2 0.5 0.9\nKe 3 1 0.25\n";

std::unique_ptr<pfx::host::PluginRegistry> obj_registry() {
  auto registry = std::make_unique<pfx::host::PluginRegistry>([](const char*) { return pfx_gl_proc{nullptr}; },
                                                              nullptr, "test_import_scene");
  std::string error;
  REQUIRE(registry->load(PFX_OBJ_PLUGIN, &error));
  return registry;
}

}  // namespace

TEST_CASE("import scene: sub-meshes, materials, lights and camera from a model", "[import][scene]") {
  Scratch scratch;
  scratch.write("p.mtl", kPyramidMtl);
  const std::string path = scratch.write("pyramid.obj", kPyramid);
  auto registry = obj_registry();
  pfx::app::Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  REQUIRE(pfx::import::load_scene_from_model(*registry, path, {}, &scene, &warnings, &error));
  CHECK(warnings.empty());
  REQUIRE(scene.meshes.size() == 2);
  CHECK(scene.meshes[0].positions.size() == 4);  // the floor quad's own vertices only
  CHECK(scene.meshes[0].indices.size() == 6);
  CHECK(scene.meshes[1].indices.size() == 12);
  REQUIRE(scene.materials.size() == 3);            // the default, then the file's two
  CHECK(scene.materials[scene.meshes[0].material].albedo == glm::vec3(0.7f, 0.6f, 0.5f));
  CHECK(scene.materials[scene.meshes[1].material].emissive == glm::vec3(3.0f, 1.0f, 0.25f));
  CHECK(scene.lights.size() == 400);
  const float radius = std::sqrt(2.0f * 2.0f * 2 + 1.5f * 1.5f) / 2;  // half the box's diagonal
  for (const auto& light : scene.lights) {
    // Over and around the model's box (x, z out to 1.3 half sizes, y from 0.3 half sizes below
    // its middle to 1.6 above), never inside it, reaching a fifth of the model's radius.
    const float x = light.position[0], y = light.position[1], z = light.position[2];
    CHECK(std::abs(x) <= 1.3f);
    CHECK(std::abs(z) <= 1.3f);
    CHECK(y >= 0.75f - 0.3f * 0.75f);
    CHECK(y <= 0.75f + 1.6f * 0.75f + 1e-5f);
    CHECK_FALSE((std::abs(x) < 1 && std::abs(z) < 1 && y > 0 && y < 1.5f));
    CHECK(light.range == Approx(0.2f * radius));
  }
  // The key light comes from above and the sky is brighter than the ground.
  CHECK(scene.key_light.direction.y > 0.5f);
  CHECK(scene.ambient.g > scene.ground_ambient.g);
  CHECK(scene.bounds_max.y == 1.5f);
  std::string why;
  CHECK(pfx::app::validate_scene(scene, &why));

  pfx::import::SceneImportOptions few;
  few.lights = 7;
  REQUIRE(pfx::import::load_scene_from_model(*registry, path, few, &scene, &warnings, &error));
  CHECK(scene.lights.size() == 7);
}

TEST_CASE("import scene: the camera frames the bounds from any box", "[import][scene]") {
  // Every corner of the box projects inside the image and between the clip planes, at 16:9.
  const float boxes[][2][3] = {{{-1, 0, -1}, {1, 1.5f, 1}}, {{100, 200, 300}, {100.01f, 200.5f, 300.02f}},
                               {{-500, -1, -2}, {500, 1, 2}}, {{0, 0, 0}, {0, 0, 0}}};
  for (const auto& box : boxes) {
    const pfx::app::Camera camera = pfx::import::frame_bounds(box[0], box[1], 45.0 * M_PI / 180.0);
    const glm::dmat4 view = glm::lookAt(camera.position, camera.target, camera.up);
    const glm::dmat4 projection = glm::perspective(camera.fovy_radians, 16.0 / 9.0, camera.near_plane, camera.far_plane);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec4 p(box[corner & 1][0], box[(corner >> 1) & 1][1], box[(corner >> 2) & 1][2], 1.0);
      const glm::dvec4 clip = projection * view * p;
      INFO("corner " << corner << " of a box from " << box[0][0]);
      REQUIRE(clip.w > 0);
      CHECK(std::fabs(clip.x / clip.w) <= 1.0);
      CHECK(std::fabs(clip.y / clip.w) <= 1.0);
      CHECK(clip.z / clip.w >= -1.0);
      CHECK(clip.z / clip.w <= 1.0);
    }
  }
}

TEST_CASE("import scene: a malformed model or a missing importer is an error naming the file", "[import][scene]") {
  Scratch scratch;
  auto registry = obj_registry();
  pfx::app::Scene scene;
  std::vector<std::string> warnings;
  std::string error;
  const std::string bad = scratch.write("bad.obj", "v 0 0 0\nf 1 2 3\n");
  CHECK_FALSE(pfx::import::load_scene_from_model(*registry, bad, {}, &scene, &warnings, &error));
  CHECK(error == bad + ":2: f: v index 2 is out of range (the file has 1 v)");
  const std::string fbx = scratch.write("x.fbx", "");
  CHECK_FALSE(pfx::import::load_scene_from_model(*registry, fbx, {}, &scene, &warnings, &error));
  CHECK(error == fbx + ": no importer plugin takes this file's extension");
}

TEST_CASE("pfx-render --scene renders a model with every effect", "[import][scene][gl]") {
  Scratch scratch;
  scratch.write("p.mtl", kPyramidMtl);
  const std::string path = scratch.write("pyramid.obj", kPyramid);
  const std::string out = (scratch.dir / "pyramid.png").string();
  const std::string json_path = (scratch.dir / "report.json").string();
  const std::string command = std::string(PFX_RENDER) + " --plugins " PFX_PLUGIN_DIR " --scene " + path +
                              " --size 96x64 --lights 16 --out " + out + " --json > " + json_path + " 2>/dev/null";
  REQUIRE(std::system(command.c_str()) == 0);
  std::ifstream in(json_path);
  nlohmann::json report = nlohmann::json::parse(in);
  CHECK(report["lights"] == 16);
  CHECK(report["output"]["nonfinite"] == 0);
  double brightest = 0;
  for (const auto& channel : report["output"]["max"]) brightest = std::max(brightest, channel.get<double>());
  CHECK(brightest > 0.5);  // the emissive sides show
  CHECK(fs::exists(out));
  const std::string bad = scratch.write("bad.obj", "f 1 2 3\n");
  const int status = std::system((std::string(PFX_RENDER) + " --plugins " PFX_PLUGIN_DIR " --scene " + bad +
                                  " --json > /dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(status) == 3);
}
