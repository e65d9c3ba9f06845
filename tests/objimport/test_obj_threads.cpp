// The parallel parse gives the same bytes for any thread count and any chunk size: a generated
// file using every statement (relative indices across chunk boundaries, material and smoothing
// changes, colours, polygons, line continuations, CRLF) is imported many ways and compared.
#include <catch2/catch.hpp>

#include <random>

#include "obj_test_support.hpp"

using pfx_obj_test::import_text;

namespace {

std::string varied_file(uint32_t faces, uint32_t seed) {
  std::mt19937 random(seed);
  auto coordinate = [&] { return std::to_string(static_cast<int>(random() % 2001) - 1000) + "." + std::to_string(random() % 1000); };
  std::string text = "# generated\n";
  uint32_t v = 0, vt = 0, vn = 0;
  const char* const endings[] = {"\n", "\r\n", "\n"};
  for (uint32_t f = 0; f < faces; ++f) {
    const char* end = endings[random() % 3];
    for (uint32_t k = 0, n = random() % 4; k < n || v < 3; ++k, ++v) {
      text += "v " + coordinate() + " " + coordinate() + " " + coordinate();
      if (random() % 5 == 0) text += " 0.5 0.25 1";
      text += end;
    }
    if (random() % 3 == 0) { text += "vt " + coordinate() + " " + coordinate() + end; ++vt; }
    if (random() % 3 == 0) { text += "vn 0 0 1" + std::string(end); ++vn; }
    switch (random() % 12) {
      case 0: text += "usemtl m" + std::to_string(random() % 3) + end; break;
      case 1: text += "s " + std::to_string(random() % 3) + end; break;
      case 2: text += "s off" + std::string(end); break;
      case 3: text += "g part" + std::to_string(f) + end; break;
      case 4: text += "l 1 2" + std::string(end); break;
      default: break;
    }
    const uint32_t corners = 3 + (random() % 4 == 0 ? random() % 4 : 0);
    text += "f";
    for (uint32_t c = 0; c < corners; ++c) {
      const uint32_t pick = 1 + random() % v;
      text += " " + (random() % 4 == 0 ? "-" + std::to_string(v - pick + 1) : std::to_string(pick));
      const bool with_vt = vt > 0 && random() % 2, with_vn = vn > 0 && random() % 2;
      if (with_vt || with_vn) text += "/";
      if (with_vt) text += std::to_string(1 + random() % vt);
      if (with_vn) text += "/" + std::to_string(1 + random() % vn);
      if (random() % 50 == 0) text += " \\" + std::string(end);
    }
    text += end;
  }
  return text;
}

void check_same(const pfx_obj::ObjMesh& a, const pfx_obj::ObjMesh& b) {
  CHECK(a.positions == b.positions);
  CHECK(a.normals == b.normals);
  CHECK(a.texcoords == b.texcoords);
  CHECK(a.colors == b.colors);
  CHECK(a.indices == b.indices);
  REQUIRE(a.submeshes.size() == b.submeshes.size());
  for (size_t s = 0; s < a.submeshes.size(); ++s) {
    CHECK(a.submeshes[s].first_index == b.submeshes[s].first_index);
    CHECK(a.submeshes[s].index_count == b.submeshes[s].index_count);
    CHECK(a.submeshes[s].material == b.submeshes[s].material);
  }
  REQUIRE(a.materials.size() == b.materials.size());
  for (size_t m = 0; m < a.materials.size(); ++m) CHECK(a.materials[m].name == b.materials[m].name);
  CHECK(a.warnings == b.warnings);
  CHECK(a.warning_total == b.warning_total);
  CHECK(a.lines_skipped == b.lines_skipped);
  CHECK(a.faces == b.faces);
  for (int k = 0; k < 3; ++k) {
    CHECK(a.bounds_min[k] == b.bounds_min[k]);
    CHECK(a.bounds_max[k] == b.bounds_max[k]);
  }
}

}  // namespace

TEST_CASE("obj threads: the same output for any thread count and chunk size", "[objimport][threads]") {
  const std::string text = varied_file(20000, 99);
  auto reference = import_text(text, 1, size_t{1} << 30);  // one chunk, one thread: the sequential parse
  REQUIRE(reference.ok);
  REQUIRE(reference.mesh.submeshes.size() == 4);  // m0, m1, m2 and the faces before any usemtl
  REQUIRE_FALSE(reference.mesh.colors.empty());
  for (unsigned threads : {1u, 2u, 3u, 4u, 7u})
    for (size_t chunk : {size_t{0}, size_t{97}, size_t{4096}, size_t{100000}}) {
      INFO("threads " << threads << ", chunk bytes " << chunk);
      auto r = import_text(text, threads, chunk);
      REQUIRE(r.ok);
      check_same(reference.mesh, r.mesh);
    }
}

TEST_CASE("obj threads: the first error in file order wins whatever the cut", "[objimport][threads]") {
  std::string text = varied_file(3000, 5);
  const size_t middle = text.find("\nf ", text.size() / 2);
  text.insert(middle + 1, "f 1 2 0\n");  // an error in the middle...
  text += "f 1 2 999999\n";              // ...and a later one of another stage
  auto reference = import_text(text, 1, size_t{1} << 30);
  REQUIRE_FALSE(reference.ok);
  CHECK(reference.error.find("index 0") != std::string::npos);
  for (unsigned threads : {2u, 5u})
    for (size_t chunk : {size_t{64}, size_t{5000}}) {
      auto r = import_text(text, threads, chunk);
      CHECK(r.error == reference.error);
    }
}

TEST_CASE("obj threads: a relative index reaching exactly one chunk back (found by the fuzzer)", "[objimport][threads]") {
  // With tiny chunks the face's chunk has no vn of its own, so "-1" is stored as position 0 of
  // that chunk — which once read as "no normal" and gave the corner a generated one.
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 -1 0\nf 1//-1 2//-1 3//-1\n";
  auto whole = import_text(text, 1, size_t{1} << 30);
  REQUIRE(whole.ok);
  CHECK(whole.mesh.normals == std::vector<float>{0, -1, 0, 0, -1, 0, 0, -1, 0});
  for (size_t chunk : {size_t{1}, size_t{5}, size_t{11}}) {
    auto cut = import_text(text, 2, chunk);
    REQUIRE(cut.ok);
    CHECK(cut.mesh.normals == whole.mesh.normals);
  }
}
