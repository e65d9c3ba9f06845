// Material libraries: several per mtllib, names with spaces, every field pfx reads, map paths
// resolved against the .mtl file's folder, and the problems that are warnings.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "obj_chunk.hpp"
#include "obj_test_support.hpp"

namespace fs = std::filesystem;
using pfx_obj_test::import_text;

namespace {

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("pfx-obj-materials-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir / "sub"); }
  ~Scratch() { fs::remove_all(dir); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir / name, std::ios::binary) << text; }
};

const pfx_obj::Material* find(const pfx_obj::ObjMesh& mesh, const std::string& name) {
  for (const auto& m : mesh.materials)
    if (m.name == name) return &m;
  return nullptr;
}

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("obj materials: every field, several libraries, names with spaces", "[objimport][materials]") {
  Scratch scratch;
  scratch.write("a.mtl",
                "newmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nKe 0 0 0\nNs 32\nd 0.5\n"
                "map_Kd -s 1 1 1 -o 0.5 -clamp on textures/red wood.png\n"
                "newmtl glow\nKd 0.1\nKe 4 3 2\nTr 0.25\nmap_Ke ..\\shared\\glow.png\nillum 2\nKa 1 1 1\n");
  scratch.write("sub/my materials.mtl", "newmtl blue paint\nKd 0 0 1\nmap_Kd /abs/blue.png\n");
  auto r = import_text("mtllib a.mtl\nmtllib sub/my materials.mtl\n" + kTriangle +
                           "usemtl red\nf 1 2 3\nusemtl blue paint\nf 1 3 2\nusemtl glow\nf 2 1 3\n",
                       1, 0, scratch.dir.string());
  REQUIRE(r.ok);
  CHECK(r.mesh.warnings.empty());
  REQUIRE(r.mesh.materials.size() == 3);
  const auto* red = find(r.mesh, "red");
  REQUIRE(red);
  CHECK(red->diffuse[0] == 1);
  CHECK(red->diffuse[1] == 0);
  CHECK(red->specular[2] == 0.5f);
  CHECK(red->shininess == 32);
  CHECK(red->opacity == 0.5f);
  CHECK(red->diffuse_map == (scratch.dir / "textures/red wood.png").string());
  const auto* glow = find(r.mesh, "glow");
  REQUIRE(glow);
  CHECK(glow->diffuse[2] == 0.1f);
  CHECK(glow->emissive[0] == 4);
  CHECK(glow->emissive[2] == 2);
  CHECK(glow->opacity == 0.75f);
  CHECK(glow->emissive_map == (scratch.dir.parent_path() / "shared/glow.png").string());
  const auto* blue = find(r.mesh, "blue paint");
  REQUIRE(blue);
  CHECK(blue->diffuse_map == "/abs/blue.png");
  // Sub-meshes in order of first use, each with its material.
  REQUIRE(r.mesh.submeshes.size() == 3);
  CHECK(r.mesh.materials[r.mesh.submeshes[0].material].name == "red");
  CHECK(r.mesh.materials[r.mesh.submeshes[1].material].name == "blue paint");
  CHECK(r.mesh.materials[r.mesh.submeshes[2].material].name == "glow");

  // Cut-out, bump and normal maps (ABI 1.3), with options before the path as exporters write them.
  scratch.write("maps.mtl",
                "newmtl leaf\nmap_d -imfchan m leaf_alpha.png\nbump -bm 0.3 leaf_height.png\nnorm leaf_normal.png\n"
                "newmtl bark\nmap_Bump bark normal.png\n");
  auto maps = import_text("mtllib maps.mtl\n" + kTriangle + "usemtl leaf\nf 1 2 3\nusemtl bark\nf 1 3 2\n", 1, 0,
                          scratch.dir.string());
  REQUIRE(maps.ok);
  CHECK(maps.mesh.warnings.empty());
  const auto* leaf = find(maps.mesh, "leaf");
  REQUIRE(leaf);
  CHECK(leaf->alpha_map == (scratch.dir / "leaf_alpha.png").string());
  CHECK(leaf->bump_map == (scratch.dir / "leaf_height.png").string());
  CHECK(leaf->normal_map == (scratch.dir / "leaf_normal.png").string());
  CHECK(leaf->diffuse_map.empty());
  const auto* bark = find(maps.mesh, "bark");
  REQUIRE(bark);
  CHECK(bark->bump_map == (scratch.dir / "bark normal.png").string());
  CHECK(bark->alpha_map.empty());

  // Two files on one mtllib line.
  scratch.write("b.mtl", "newmtl green\nKd 0 1 0\n");
  auto two = import_text("mtllib a.mtl b.mtl\n" + kTriangle + "usemtl green\nf 1 2 3\n", 1, 0, scratch.dir.string());
  REQUIRE(two.ok);
  CHECK(two.mesh.materials.size() == 3);
  REQUIRE(find(two.mesh, "green"));
  CHECK(find(two.mesh, "green")->diffuse[1] == 1);
}

TEST_CASE("obj materials: sub-meshes group faces by material in file order", "[objimport][materials]") {
  auto r = import_text(kTriangle + "f 1 2 3\nusemtl a\nf 1 2 3\nusemtl b\nf 2 3 1\nusemtl a\nf 3 1 2\n");
  REQUIRE(r.ok);
  REQUIRE(r.mesh.submeshes.size() == 3);
  CHECK(r.mesh.submeshes[0].material == pfx_obj::kNoIndex);
  CHECK(r.mesh.submeshes[0].first_index == 0);
  CHECK(r.mesh.submeshes[0].index_count == 3);
  CHECK(r.mesh.materials[r.mesh.submeshes[1].material].name == "a");
  CHECK(r.mesh.submeshes[1].first_index == 3);
  CHECK(r.mesh.submeshes[1].index_count == 6);
  CHECK(r.mesh.materials[r.mesh.submeshes[2].material].name == "b");
  CHECK(r.mesh.submeshes[2].first_index == 9);
  // Within "a": the face of line 5, then the face of line 9.
  CHECK(std::vector<uint32_t>(r.mesh.indices.begin() + 3, r.mesh.indices.begin() + 9) ==
        std::vector<uint32_t>{0, 1, 2, 2, 0, 1});
}

TEST_CASE("obj materials: a missing .mtl is a warning, not an error", "[objimport][materials]") {
  Scratch scratch;
  auto r = import_text("mtllib nowhere.mtl\n" + kTriangle + "usemtl x\nf 1 2 3\n", 1, 0, scratch.dir.string());
  REQUIRE(r.ok);
  REQUIRE(r.mesh.warnings.size() == 2);
  CHECK(r.mesh.warnings[0] == scratch.dir.string() + "/test.obj:1: mtllib: " + (scratch.dir / "nowhere.mtl").string() +
                                  ": no such file (materials keep their defaults)");
  CHECK(r.mesh.warnings[1].rfind(scratch.dir.string() + "/test.obj:5: usemtl x: no material", 0) == 0);
}

TEST_CASE("obj materials: bad lines in a library are warnings naming the .mtl line", "[objimport][materials]") {
  Scratch scratch;
  scratch.write("bad.mtl", "Kd 1 1 1\nnewmtl m\nKd 1 x 1\nNs nan\nKd spectral file.spd\nnewmtl m\n");
  auto r = import_text("mtllib bad.mtl\n" + kTriangle + "usemtl m\nf 1 2 3\n", 1, 0, scratch.dir.string());
  REQUIRE(r.ok);
  const std::string mtl = (scratch.dir / "bad.mtl").string();
  REQUIRE(r.mesh.warnings.size() == 5);
  CHECK(r.mesh.warnings[0] == scratch.dir.string() + "/test.obj:1: " + mtl + ":1: Kd before any newmtl: ignored");
  CHECK(r.mesh.warnings[1].find(mtl + ":3: Kd: 'x' is not a finite number: ignored") != std::string::npos);
  CHECK(r.mesh.warnings[2].find(mtl + ":4: Ns: 'nan' is not a finite number: ignored") != std::string::npos);
  CHECK(r.mesh.warnings[3].find(mtl + ":5: Kd spectral: not supported, ignored") != std::string::npos);
  CHECK(r.mesh.warnings[4].find(mtl + ":6: material 'm' defined again: the first definition is kept") != std::string::npos);
  CHECK(r.mesh.materials.size() == 1);
  CHECK(r.mesh.materials[0].diffuse[0] == 0.8f);
}

TEST_CASE("obj materials: a usemtl before every face, over 2000 materials", "[objimport][materials]") {
  // Some exporters write usemtl per face; each material's faces still form one sub-mesh, in
  // order of first use, and every unknown name is warned about once.
  std::string text = kTriangle;
  for (int f = 0; f < 20000; ++f) text += "usemtl m" + std::to_string((f * 7) % 2000) + "\nf 1 2 3\n";
  for (unsigned threads : {1u, 2u}) {
    auto r = import_text(text, threads, 4096);
    REQUIRE(r.ok);
    REQUIRE(r.mesh.submeshes.size() == 2000);
    CHECK(r.mesh.materials.size() == 2000);
    for (size_t s = 0; s < r.mesh.submeshes.size(); ++s) {
      CHECK(r.mesh.submeshes[s].index_count == 30);  // 10 faces each
      CHECK(r.mesh.materials[r.mesh.submeshes[s].material].name == "m" + std::to_string((s * 7) % 2000));
    }
    CHECK(r.mesh.warning_total == 2000);
  }
}
