// What a chunk read in parallel cannot know and the merge settles (obj_chunk.hpp): faces using
// positions written further on, relative indices, smoothing and materials in force across a cut,
// errors found only against the whole file, a last line without a line end. Each case is checked
// against values worked out by hand, at cuts that split it many ways and on one and two threads.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "obj_test_support.hpp"

using pfx_obj_test::import_text;

namespace {

const std::string kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
const size_t kCuts[] = {0, 1, 7, 12, 31, 64, size_t{1} << 30};

// Imports `text` on one and two threads at every cut and hands each result to check().
template <typename Check>
void each_way(const std::string& text, Check check) {
  for (unsigned threads : {1u, 2u})
    for (size_t chunk : kCuts) {
      INFO("threads " << threads << ", chunk bytes " << chunk);
      check(import_text(text, threads, chunk));
    }
}

}  // namespace

TEST_CASE("obj chunks: triangles of one material keep file order and first-use numbering", "[objimport][chunks]") {
  std::string text = kQuad;
  for (int i = 0; i < 300; ++i) text += i % 2 ? "f 1 2 3\n" : "f 1 3 4\n";
  each_way(text, [](const pfx_obj_test::Imported& r) {
    REQUIRE(r.ok);
    REQUIRE(r.mesh.indices.size() == 900);
    CHECK(r.mesh.vertex_count() == 4);
    CHECK(std::vector<uint32_t>(r.mesh.indices.begin(), r.mesh.indices.begin() + 6) == std::vector<uint32_t>{0, 1, 2, 0, 3, 1});
    CHECK(r.mesh.positions == std::vector<float>{0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0});
  });
}

TEST_CASE("obj chunks: a face using positions written further on", "[objimport][chunks]") {
  const std::string text = "f 1 2 3\n# " + std::string(100, '.') + "\n" + kQuad;
  each_way(text, [](const pfx_obj_test::Imported& r) {
    REQUIRE(r.ok);
    CHECK(r.mesh.indices == std::vector<uint32_t>{0, 1, 2});
    CHECK(r.mesh.positions == std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0});
  });
}

TEST_CASE("obj chunks: relative and absolute indices to one element make one vertex", "[objimport][chunks]") {
  // Faces 2 and 3 name the same corners as face 1, relatively, from further and further on.
  const std::string text = kQuad + "f 1 2 3\nf -4 -3 -2\nv 5 5 5\nf -5 -4 -3\n";
  each_way(text, [](const pfx_obj_test::Imported& r) {
    REQUIRE(r.ok);
    CHECK(r.mesh.vertex_count() == 3);
    CHECK(r.mesh.indices == std::vector<uint32_t>{0, 1, 2, 0, 1, 2, 0, 1, 2});
  });
}

TEST_CASE("obj chunks: smoothing off carried into later chunks gives every face its own vertices", "[objimport][chunks]") {
  std::string off = kQuad + "s off\n", on = kQuad + "s 1\n";
  for (int i = 0; i < 20; ++i) {
    off += "f 1 2 3\n";
    on += "f 1 2 3\n";
  }
  for (unsigned threads : {1u, 2u})
    for (size_t chunk : kCuts) {
      INFO("threads " << threads << ", chunk bytes " << chunk);
      auto flat = import_text(off, threads, chunk);
      REQUIRE(flat.ok);
      CHECK(flat.mesh.vertex_count() == 60);  // each face its own three
      auto smooth = import_text(on, threads, chunk);
      REQUIRE(smooth.ok);
      CHECK(smooth.mesh.vertex_count() == 3);  // one group: shared
      for (size_t i = 0; i < flat.mesh.normals.size(); i += 3)
        CHECK(std::vector<float>(flat.mesh.normals.begin() + i, flat.mesh.normals.begin() + i + 3) == std::vector<float>{0, 0, 1});
    }
}

TEST_CASE("obj chunks: materials in force across a cut, sub-meshes by first use", "[objimport][chunks]") {
  // b first, then a, then b again; faces before any usemtl come first.
  const std::string text = kQuad + "f 1 2 3\nusemtl b\nf 1 2 3\nf 1 3 4\nusemtl a\nf 2 3 4\nusemtl b\nf 1 2 4\n";
  each_way(text, [](const pfx_obj_test::Imported& r) {
    REQUIRE(r.ok);
    REQUIRE(r.mesh.submeshes.size() == 3);
    REQUIRE(r.mesh.materials.size() == 2);
    CHECK(r.mesh.materials[r.mesh.submeshes[1].material].name == "b");
    CHECK(r.mesh.materials[r.mesh.submeshes[2].material].name == "a");
    CHECK(r.mesh.submeshes[0].index_count == 3);
    CHECK(r.mesh.submeshes[1].index_count == 9);
    CHECK(r.mesh.submeshes[2].index_count == 3);
    // b's triangles in file order: 1 2 3, 1 3 4, 1 2 4 (vertices numbered 0 1 2, then 3 for v4)
    CHECK(std::vector<uint32_t>(r.mesh.indices.begin() + 3, r.mesh.indices.begin() + 12) ==
          std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 1, 3});
  });
}

TEST_CASE("obj chunks: errors found against the whole file keep their lines", "[objimport][chunks]") {
  const std::pair<const char*, const char*> cases[] = {
      {"f 1 2 99\n", "test.obj:6: f: v index 99 is out of range (the file has 4 v)"},
      {"f 1/7 2 3\n", "test.obj:6: f: vt index 7 but the file has no vt"},
      {"f 1//7 2 3\n", "test.obj:6: f: vn index 7 but the file has no vn"},
      {"f -9 2 3\n", "test.obj:6: f: relative v index reaches before the first v"},
      {"f 1 2 x\n", "test.obj:6: f: malformed corner 'x' (expected v, v/vt, v//vn or v/vt/vn)"}};
  for (const auto& [line, message] : cases)
    for (unsigned threads : {1u, 2u})
      for (size_t chunk : kCuts) {
        INFO(line << "threads " << threads << ", chunk bytes " << chunk);
        auto r = import_text(kQuad + "f 1 2 3\n" + line + "f 1 2 3\n", threads, chunk);
        REQUIRE_FALSE(r.ok);
        CHECK(r.error == message);
      }
}

TEST_CASE("obj chunks: a last line without a line end", "[objimport][chunks]") {
  for (const std::string& end : {std::string("f 1 2 3"), std::string("f 1 2 3\r"), std::string("f 1 2 \\\n3")})
    for (size_t chunk : kCuts) {
      INFO(end << ", chunk bytes " << chunk);
      auto r = import_text(kQuad + end, 2, chunk);
      REQUIRE(r.ok);
      CHECK(r.mesh.indices == std::vector<uint32_t>{0, 1, 2});
      auto bad = import_text(kQuad + "f 1 2 3\nv 1 2", 2, chunk);
      CHECK(bad.error == "test.obj:6: v: expected x y z, x y z w or x y z r g b (got 2 numbers)");
    }
}
