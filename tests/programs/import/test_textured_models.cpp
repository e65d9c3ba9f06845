// Models as users bring them (tests/programs/import/models, written by make_textured_models.cpp): JPEG,
// TGA, BMP and PNG textures read and decoded from sRGB, one warning and the flat colour for a
// broken texture, and pfx-render --scene lighting the model into the display's mid-tones.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "import_scene.hpp"
#include "png_io.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kModels = PFX_TEST_MODELS;

std::unique_ptr<pfx::host::PluginRegistry> obj_registry() {
  auto registry = std::make_unique<pfx::host::PluginRegistry>([](const char*) { return pfx_gl_proc{nullptr}; },
                                                              nullptr, "test_textured_models");
  std::string error;
  REQUIRE(registry->load(PFX_OBJ_PLUGIN, &error));
  return registry;
}

// The sRGB decoding (IEC 61966-2-1), written out here independently of the loader.
double linear(double code) {
  const double c = code / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The swatches' mean in linear light: half the texels at code + 8, half at code - 8.
double swatch_mean(int code) { return 0.5 * (linear(code + 8) + linear(code - 8)); }

glm::dvec3 texture_mean(const pfx::app::Texture& t) {
  glm::dvec3 sum(0.0);
  const size_t n = static_cast<size_t>(t.width) * t.height;
  for (size_t i = 0; i < n; ++i) sum += glm::dvec3(t.rgba[i * 4], t.rgba[i * 4 + 1], t.rgba[i * 4 + 2]);
  return sum / double(n);
}

struct Loaded {
  pfx::app::Scene scene;
  std::vector<std::string> warnings;
};

Loaded load(const std::string& relative) {
  static auto registry = obj_registry();
  Loaded l;
  std::string error;
  INFO(relative);
  REQUIRE(pfx::import::load_scene_from_model(*registry, kModels + "/" + relative, {}, &l.scene, &l.warnings, &error));
  return l;
}

// The albedo map's mean of the mesh drawn with material `m` of the file (scene material m + 1).
glm::dvec3 albedo_map_mean(const pfx::app::Scene& scene, int m) {
  const pfx::app::Material& material = scene.materials.at(static_cast<size_t>(m) + 1);
  REQUIRE(material.albedo_texture >= 0);
  return texture_mean(scene.textures.at(static_cast<size_t>(material.albedo_texture)));
}

void check_colour(const glm::dvec3& got, int r, int g, int b, double tolerance) {
  CHECK(got.r == Approx(swatch_mean(r)).margin(tolerance));
  CHECK(got.g == Approx(swatch_mean(g)).margin(tolerance));
  CHECK(got.b == Approx(swatch_mean(b)).margin(tolerance));
}

// A data map keeps its codes as they are: the swatch's mean is code / 255.
void check_stored(const glm::dvec3& got, int r, int g, int b) {
  CHECK(got.r == Approx(r / 255.0).margin(1e-5));
  CHECK(got.g == Approx(g / 255.0).margin(1e-5));
  CHECK(got.b == Approx(b / 255.0).margin(1e-5));
}

struct Run {
  int exit_code = -1;
  std::string err;
};

Run pfx_render(const std::string& args) {
  const std::string err_path = (fs::temp_directory_path() / ("pfx-textured-" + std::to_string(::getpid()) + ".err")).string();
  const std::string command = std::string(PFX_RENDER) + " --plugins " PFX_PLUGIN_DIR " " + args + " > /dev/null 2> " + err_path;
  const int status = std::system(command.c_str());
  Run r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_path);
  std::stringstream text;
  text << in.rdbuf();
  r.err = text.str();
  fs::remove(err_path);
  return r;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Per third of the model's width in the picture (the three boxes stand left, middle, right, 1 m
// apart): the mean colour of the pixels that are not background, as display values 0..1.
struct Third {
  glm::dvec3 mean{0.0};
  double luma = 0;
  int pixels = 0;
};

std::vector<Third> thirds(const pfx::app::DisplayImage& img) {
  // The rig's background is about 0.03 linear (code ~48 after sRGB): anything brighter in some
  // channel by a margin is the model.
  auto model = [&](int x, int y) {
    const uint8_t* p = &img.pixels[(static_cast<size_t>(y) * img.width + x) * img.channels];
    return std::max({p[0], p[1], p[2]}) >= 70;
  };
  int left = img.width, right = -1;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (model(x, y)) {
        left = std::min(left, x);
        right = std::max(right, x);
      }
  std::vector<Third> out(3);
  REQUIRE(right > left);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (!model(x, y)) continue;
      const uint8_t* p = &img.pixels[(static_cast<size_t>(y) * img.width + x) * img.channels];
      Third& t = out[static_cast<size_t>(std::min(2, (x - left) * 3 / (right - left + 1)))];
      t.mean += glm::dvec3(p[0], p[1], p[2]) / 255.0;
      ++t.pixels;
    }
  for (Third& t : out)
    if (t.pixels) {
      t.mean /= t.pixels;
      t.luma = 0.2126 * t.mean.r + 0.7152 * t.mean.g + 0.0722 * t.mean.b;
    }
  return out;
}

pfx::app::DisplayImage render_model(const std::string& relative, const std::string& chain, Run* run) {
  const std::string out = (fs::temp_directory_path() / ("pfx-textured-" + std::to_string(::getpid()) + ".png")).string();
  *run = pfx_render("--scene " + kModels + "/" + relative + " --size 192x108 --chain " + chain + " --out " + out);
  pfx::app::DisplayImage img;
  std::string error;
  INFO(run->err);
  REQUIRE(run->exit_code == 0);
  REQUIRE(pfx::app::read_png(out, &img, &error));
  fs::remove(out);
  return img;
}

}  // namespace

TEST_CASE("textured models: JPEG maps (assimp style) are read, decoded from sRGB, without warnings",
          "[import][textures]") {
  const Loaded l = load("assimp_style/crates.obj");
  INFO(l.warnings.size() << " warnings, first: " << (l.warnings.empty() ? "" : l.warnings[0]));
  CHECK(l.warnings.empty());
  // JPEG keeps the mean of an 8-texel checker to about a code.
  check_colour(albedo_map_mean(l.scene, 0), 190, 60, 40, 0.01);
  check_colour(albedo_map_mean(l.scene, 1), 60, 170, 70, 0.01);  // named .JPG
  // The grey glow map multiplies Ke.
  const pfx::app::Material& lamp = l.scene.materials.at(3);
  REQUIRE(lamp.emissive_texture >= 0);
  check_colour(texture_mean(l.scene.textures.at(static_cast<size_t>(lamp.emissive_texture))), 230, 230, 230, 0.01);
  CHECK(lamp.emissive == glm::vec3(4, 3, 1));
}

TEST_CASE("textured models: TGA, PNG and BMP maps (tinyobjloader style) are read without warnings",
          "[import][textures]") {
  const Loaded l = load("tinyobj_style/cubes.obj");
  CHECK(l.warnings.empty());
  // Lossless formats: the decoded mean is the swatch's exactly (to float rounding).
  check_colour(albedo_map_mean(l.scene, 0), 50, 80, 200, 1e-5);    // RLE TGA
  check_colour(albedo_map_mean(l.scene, 1), 210, 190, 50, 1e-5);   // PNG
  check_colour(albedo_map_mean(l.scene, 2), 150, 60, 170, 1e-5);   // BMP
}

TEST_CASE("textured models: a truncated or corrupt JPEG or TGA gives one warning and the flat colour",
          "[import][textures][hard]") {
  const Loaded l = load("broken/broken.obj");
  REQUIRE(l.warnings.size() == 3);
  CHECK(l.warnings[0].find("truncated.jpg") != std::string::npos);
  CHECK(l.warnings[1].find("truncated.tga") != std::string::npos);
  CHECK(l.warnings[2].find("corrupt.jpg") != std::string::npos);
  for (int m = 1; m <= 3; ++m) CHECK(l.scene.materials.at(static_cast<size_t>(m)).albedo_texture == -1);
  CHECK(l.scene.materials.at(1).albedo == glm::vec3(0.5f, 0.1f, 0.1f));
  CHECK(l.scene.textures.empty());
}

TEST_CASE("pfx-render --scene: each material shows its texture's colour, mid-tones in range, no warning",
          "[import][textures][gl]") {
  Run run;
  // Without effects the picture is the G-buffer's colour: the key light, sky and ground.
  const auto tiny = thirds(render_model("tinyobj_style/cubes.obj", "''", &run));
  CHECK(count(run.err, "warning") == 0);
  for (const Third& t : tiny) CHECK(t.pixels > 100);
  // Blue, yellow, purple: each third's dominant channels are its texture's.
  CHECK(tiny[0].mean.b > tiny[0].mean.r + 0.2);
  CHECK(tiny[0].mean.b > tiny[0].mean.g + 0.1);
  CHECK(tiny[1].mean.r > tiny[1].mean.b + 0.3);
  CHECK(tiny[1].mean.g > tiny[1].mean.b + 0.3);
  CHECK(tiny[2].mean.r > tiny[2].mean.g + 0.2);
  CHECK(tiny[2].mean.b > tiny[2].mean.g + 0.2);
  // The documented range (docs/scenes.md): the model's mean display luma 0.3..0.7 at exposure 0.
  const double mean_luma = (tiny[0].luma + tiny[1].luma + tiny[2].luma) / 3;
  CHECK(mean_luma > 0.3);
  CHECK(mean_luma < 0.7);

  // With the point lights the textures still read, and the result stays in range.
  const auto crates = thirds(render_model("assimp_style/crates.obj", "tiledlights", &run));
  CHECK(count(run.err, "warning") == 0);
  CHECK(crates[0].mean.r > crates[0].mean.g + 0.2);  // brick red
  CHECK(crates[1].mean.g > crates[1].mean.r + 0.2);  // moss green
  const double crates_luma = (crates[0].luma + crates[1].luma) / 2;
  CHECK(crates_luma > 0.3);
  CHECK(crates_luma < 0.75);
}

TEST_CASE("pfx-render --scene: broken textures warn once each and render their flat colours",
          "[import][textures][gl][hard]") {
  Run run;
  const auto broken = thirds(render_model("broken/broken.obj", "''", &run));
  CHECK(count(run.err, "warning") == 3);
  CHECK(broken[0].mean.r > broken[0].mean.g + 0.2);  // Kd 0.5 0.1 0.1
  CHECK(broken[1].mean.g > broken[1].mean.r + 0.2);  // Kd 0.1 0.5 0.1
  CHECK(broken[2].mean.b > broken[2].mean.r + 0.2);  // Kd 0.1 0.1 0.5
}

TEST_CASE("textured models: map_d, norm and bump from the .mtl become the cut-out and normal maps, kept linear",
          "[import][textures]") {
  // The tinyobjloader-style model again, its materials given a cut-out, a normal map and a bump
  // map made of its own colour swatches.
  const fs::path dir = fs::temp_directory_path() / ("pfx-data-maps-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::copy(kModels + "/tinyobj_style", dir);
  {
    std::ofstream mtl(dir / "cubes.mtl", std::ios::app);
    mtl << "\nnewmtl cutout\nKd 1 1 1\nmap_d yellow.png\n"
        << "newmtl normal\nKd 1 1 1\nnorm purple.bmp\nbump blue.tga\n"
        << "newmtl bumped\nKd 1 1 1\nmap_Bump -bm 0.5 blue.tga\n";
    std::ofstream obj(dir / "cubes.obj", std::ios::app);
    obj << "\nusemtl cutout\nf 1/1 2/2 4/3\nusemtl normal\nf 1/1 2/2 4/3\nusemtl bumped\nf 1/1 2/2 4/3\n";
  }
  static auto registry = obj_registry();
  Loaded l;
  std::string error;
  REQUIRE(pfx::import::load_scene_from_model(*registry, (dir / "cubes.obj").string(), {}, &l.scene, &l.warnings, &error));
  fs::remove_all(dir);
  CHECK(l.warnings.empty());
  REQUIRE(l.scene.materials.size() == 7);  // the default, the file's three, the three above
  const pfx::app::Material& cutout = l.scene.materials[4];
  const pfx::app::Material& normal = l.scene.materials[5];
  const pfx::app::Material& bumped = l.scene.materials[6];
  CHECK(cutout.alpha_texture >= 0);
  CHECK(cutout.normal_texture < 0);
  // norm wins over bump; a coloured map is taken as stored, not decoded from sRGB.
  REQUIRE(normal.normal_texture >= 0);
  check_stored(texture_mean(l.scene.textures.at(static_cast<size_t>(normal.normal_texture))), 150, 60, 170);
  REQUIRE(bumped.normal_texture >= 0);
  check_stored(texture_mean(l.scene.textures.at(static_cast<size_t>(bumped.normal_texture))), 50, 80, 200);
  CHECK(bumped.alpha_texture < 0);
}
