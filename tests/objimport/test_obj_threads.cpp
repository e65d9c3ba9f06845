// The parallel parse gives the same bytes for any thread count and any chunk size: a generated
// file using every statement (relative indices across chunk boundaries, material and smoothing
// changes, colours, polygons, line continuations, CRLF) is imported many ways and compared.
#include <catch2/catch.hpp>

#include "obj_test_support.hpp"

using pfx_obj_test::check_same;
using pfx_obj_test::import_text;
using pfx_obj_test::varied_file;


TEST_CASE("obj threads: the same output for any thread count and chunk size", "[objimport][threads]") {
  const std::string text = varied_file(20000, 99);
  auto reference = import_text(text, 1, size_t{1} << 30);  // one chunk, one thread: the sequential parse
  REQUIRE(reference.ok);
  REQUIRE(reference.mesh.submeshes.size() == 4);  // m0, m1, m2 and the faces before any usemtl
  REQUIRE_FALSE(reference.mesh.colors.empty());
  // Chunk by chunk (obj_streamed.cpp, the default) and through the staged pipeline.
  for (bool streamed : {true, false})
    for (unsigned threads : {1u, 2u, 3u, 4u, 7u})
      for (size_t chunk : {size_t{0}, size_t{97}, size_t{4096}, size_t{100000}}) {
        INFO((streamed ? "streamed" : "staged") << ", threads " << threads << ", chunk bytes " << chunk);
        auto r = import_text(text, threads, chunk, "", true, streamed);
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
  for (bool streamed : {true, false})
    for (unsigned threads : {2u, 5u})
      for (size_t chunk : {size_t{64}, size_t{5000}}) {
        auto r = import_text(text, threads, chunk, "", true, streamed);
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
  for (bool streamed : {true, false})
    for (size_t chunk : {size_t{1}, size_t{5}, size_t{11}}) {
      auto cut = import_text(text, 2, chunk, "", true, streamed);
      REQUIRE(cut.ok);
      CHECK(cut.mesh.normals == whole.mesh.normals);
    }
}
