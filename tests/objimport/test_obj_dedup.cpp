// Deduplication on full 32-bit indices. The two named cases are a common loader's shortcuts: a
// 21-bit packing of (v, vt, vn) into one 64-bit key merges distinct corners once an index passes
// 2^21, and its 16-bit indices wrap past 65,535 vertices. The files are made here; every corner is
// checked against the values written into the file.
#include <catch2/catch.hpp>

#include <set>

#include "obj_test_support.hpp"

using pfx_obj_test::import_text;

TEST_CASE("obj dedup: one vertex per distinct (v, vt, vn)", "[objimport][dedup]") {
  auto quad = import_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
  REQUIRE(quad.ok);
  CHECK(quad.mesh.vertex_count() == 4);
  CHECK(quad.mesh.indices == std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
  auto seam = import_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 3/1 2/1\n");
  REQUIRE(seam.ok);
  CHECK(seam.mesh.vertex_count() == 4);  // v1 with vt1 and with vt2
  auto normals = import_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 -1\nf 1//1 2//1 3//1\nf 1//2 3//2 2//2\n");
  REQUIRE(normals.ok);
  CHECK(normals.mesh.vertex_count() == 6);
}

TEST_CASE("obj dedup: more than 2^21 distinct triples (21-bit key packing collides)", "[objimport][dedup][large]") {
  // vt k holds u = k. Face j uses v 1, 2, 3 with vt 3j+1, 3j+2, 3j+3, so every corner is a
  // distinct triple and there are `count` of them, past 2^21.
  const uint32_t count = (1u << 21) + 1 + 3 * 1000;
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  text.reserve(64u * count);
  for (uint32_t k = 1; k <= count; ++k) text += "vt " + std::to_string(k) + " 0\n";
  for (uint32_t k = 1; k <= count; k += 3)
    text += "f 1/" + std::to_string(k) + " 2/" + std::to_string(k + 1) + " 3/" + std::to_string(k + 2) + "\n";

  // The packed key, (v << 42) + (vt << 21) + vn, does merge distinct triples of this file:
  // (v 2, vt 5) and (v 1, vt 2^21 + 5) give the same key.
  std::set<uint64_t> packed;
  for (uint32_t k = 1; k <= count; ++k) packed.insert((uint64_t{(k - 1) % 3 + 1} << 42) + (uint64_t{k} << 21));
  REQUIRE(packed.size() < count);

  auto r = import_text(text, 2);
  REQUIRE(r.ok);
  CHECK(r.mesh.vertex_count() == count);
  REQUIRE(r.mesh.indices.size() == count);
  const float expected_position[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  uint32_t wrong = 0;
  for (uint32_t corner = 0; corner < count; ++corner) {
    const uint32_t i = r.mesh.indices[corner];
    const uint32_t v = corner % 3;
    wrong += r.mesh.texcoords[2 * size_t{i}] != static_cast<float>(corner + 1);
    for (int k = 0; k < 3; ++k) wrong += r.mesh.positions[3 * size_t{i} + k] != expected_position[v][k];
  }
  CHECK(wrong == 0);
}

TEST_CASE("obj dedup: more than 65,535 vertices (16-bit indices wrap)", "[objimport][dedup]") {
  const uint32_t count = 70002;
  std::string text;
  for (uint32_t k = 1; k <= count; ++k) text += "v " + std::to_string(k) + " " + std::to_string(k % 7) + " 0\n";
  for (uint32_t k = 1; k + 2 <= count; ++k)
    text += "f " + std::to_string(k) + " " + std::to_string(k + 1) + " " + std::to_string(k + 2) + "\n";
  auto r = import_text(text, 2);
  REQUIRE(r.ok);
  CHECK(r.mesh.vertex_count() == count);
  REQUIRE(r.mesh.indices.size() == 3 * size_t{count - 2});
  uint32_t wrong = 0, above_16_bits = 0;
  for (uint32_t t = 0; t + 2 < count; ++t)
    for (uint32_t c = 0; c < 3; ++c) {
      const uint32_t i = r.mesh.indices[3 * t + c];
      above_16_bits += i > 65535;
      wrong += r.mesh.positions[3 * size_t{i}] != static_cast<float>(t + c + 1);
    }
  CHECK(wrong == 0);
  CHECK(above_16_bits > 0);
  CHECK(r.mesh.bounds_max[0] == static_cast<float>(count));
}

TEST_CASE("obj dedup: a position with hundreds of texture coordinates", "[objimport][dedup]") {
  // Position 1 appears with 300 different vt (past the per-position chain, into the overflow
  // table), repeated twice: 300 + 2 distinct vertices, each corner keeping its own vt.
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int k = 1; k <= 300; ++k) text += "vt " + std::to_string(k) + " 0\n";
  for (int round = 0; round < 2; ++round)
    for (int k = 1; k <= 300; ++k) text += "f 1/" + std::to_string(k) + " 2/1 3/1\n";
  for (unsigned threads : {1u, 3u}) {
    auto r = import_text(text, threads, 500);
    REQUIRE(r.ok);
    CHECK(r.mesh.vertex_count() == 302);
    uint32_t wrong = 0;
    for (size_t t = 0; t < r.mesh.indices.size() / 3; ++t)
      wrong += r.mesh.texcoords[2 * size_t{r.mesh.indices[3 * t]}] != static_cast<float>(t % 300 + 1);
    CHECK(wrong == 0);
  }
}
