// The import runs chunk by chunk (obj_streamed.cpp) — on several threads, parsing ahead while one
// numbers in file order — and must give what the staged pipeline gives, byte for byte, whatever
// the cut and the thread count; files it cannot settle chunk by chunk (a face using positions
// defined further on, indices out of range) go to the staged pipeline, which the stage names show.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "obj_test_support.hpp"

using pfx_obj_test::check_same;
using pfx_obj_test::varied_file;

namespace {

struct Run {
  bool ok = false;
  pfx_obj::ObjMesh mesh;
  std::string error;
};

Run import_cut(const std::string& text, size_t chunk_bytes, bool streamed, unsigned threads = 1) {
  pfx_obj::ImportOptions options;
  options.pool = pfx_obj_test::test_pool(threads);
  options.threads = threads;
  options.chunk_bytes = chunk_bytes;
  options.streamed = streamed;
  Run run;
  run.ok = pfx_obj::import_obj_text(text, "test.obj", "", options, &run.mesh, &run.error);
  return run;
}

// Whether the chunk-by-chunk import finished the job (its own stage "triangles"), or handed it to
// the staged pipeline (whose walk is "dedup, triangles").
bool ran_streamed(const pfx_obj::ObjMesh& mesh) {
  return std::any_of(mesh.stages.begin(), mesh.stages.end(),
                     [](const pfx_obj::ImportStage& s) { return std::strcmp(s.name, "triangles") == 0; });
}

// The staged pipeline on one thread against the import chunk by chunk on one to three threads.
void check_streamed_like_staged(const std::string& text, size_t chunk_bytes) {
  INFO("chunk bytes " << chunk_bytes);
  const Run staged = import_cut(text, chunk_bytes, false);
  for (unsigned threads : {1u, 2u, 3u}) {
    INFO("threads " << threads);
    const Run streamed = import_cut(text, chunk_bytes, true, threads);
    REQUIRE(streamed.ok == staged.ok);
    CHECK(streamed.error == staged.error);
    if (staged.ok) check_same(staged.mesh, streamed.mesh);
  }
}

const char* kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("obj streamed: the same bytes as the staged pipeline for any cut", "[objimport][streamed]") {
  // Relative indices reaching back over chunks, usemtl and s changes, polygons, colours.
  const std::string text = varied_file(20000, 41);
  for (size_t chunk : {size_t{0}, size_t{61}, size_t{997}, size_t{65536}, size_t{1} << 30}) {
    check_streamed_like_staged(text, chunk);
    CHECK(ran_streamed(import_cut(text, chunk, true).mesh));
  }
}

TEST_CASE("obj streamed: triangles of one material become the index array as numbered", "[objimport][streamed]") {
  std::string text = kQuad;
  for (int i = 0; i < 300; ++i) text += i % 2 ? "f 1 2 3\n" : "f 1 3 4\n";
  for (size_t chunk : {size_t{0}, size_t{40}}) {
    const Run run = import_cut(text, chunk, true);
    REQUIRE(run.ok);
    CHECK(ran_streamed(run.mesh));
    REQUIRE(run.mesh.indices.size() == 900);
    CHECK(run.mesh.vertex_count() == 4);
    CHECK(std::vector<uint32_t>(run.mesh.indices.begin(), run.mesh.indices.begin() + 6) ==
          std::vector<uint32_t>{0, 1, 2, 0, 3, 1});
    check_streamed_like_staged(text, chunk);
  }
}

TEST_CASE("obj streamed: materials and smoothing that change across chunks", "[objimport][streamed]") {
  // Sub-meshes in order of first use, a material coming back in a later chunk, smoothing off
  // (each face its own normals) in force across a cut, quads and a concave hexagon.
  std::string text = std::string(kQuad) + "v 2 0 0\nv 2 1 0\nvt 0 0\n";
  for (int i = 0; i < 40; ++i) {
    text += i % 3 == 0 ? "usemtl b\n" : i % 3 == 1 ? "usemtl a\n" : "";
    text += i % 5 == 0 ? "s off\n" : i % 5 == 2 ? "s 3\n" : "";
    text += i % 4 == 0 ? "f 1 2 3 4\n" : i % 4 == 1 ? "f 1/1 2/1 5 6 3 4\n" : "f 2 5 6\n";
  }
  for (size_t chunk : {size_t{0}, size_t{23}, size_t{150}}) {
    check_streamed_like_staged(text, chunk);
    CHECK(ran_streamed(import_cut(text, chunk, true).mesh));
  }
}

TEST_CASE("obj streamed: a face using positions defined further on goes to the staged pipeline", "[objimport][streamed]") {
  // Valid OBJ: the face comes before its positions. Cut so the face's chunk has none of them.
  const std::string text = "f 1 2 3\n# " + std::string(100, '.') + "\n" + kQuad;
  for (size_t chunk : {size_t{16}, size_t{1} << 30}) {
    check_streamed_like_staged(text, chunk);
    const Run run = import_cut(text, chunk, true);
    REQUIRE(run.ok);
    CHECK(run.mesh.indices == std::vector<uint32_t>{0, 1, 2});
  }
  CHECK_FALSE(ran_streamed(import_cut(text, 16, true).mesh));
  CHECK(ran_streamed(import_cut(text, size_t{1} << 30, true).mesh));  // one chunk: all read
}

TEST_CASE("obj streamed: errors it leaves to the staged pipeline keep their lines", "[objimport][streamed]") {
  for (const std::string& tail : {std::string("f 1 2 99\n"), std::string("f 1/7 2 3\n"), std::string("f 1//7 2 3\n"),
                                  std::string("f -9 2 3\n"), std::string("f 1 2 x\n")}) {
    const std::string text = std::string(kQuad) + "f 1 2 3\n" + tail + "f 1 2 3\n";
    INFO(tail);
    const Run run = import_cut(text, 12, true);
    REQUIRE_FALSE(run.ok);
    CHECK(run.error.rfind("test.obj:6: ", 0) == 0);
    for (size_t chunk : {size_t{0}, size_t{12}, size_t{31}}) check_streamed_like_staged(text, chunk);
  }
}

TEST_CASE("obj streamed: an empty file, and a file without faces", "[objimport][streamed]") {
  for (const std::string& text : {std::string(), std::string(kQuad), std::string("# nothing\n")})
    for (size_t chunk : {size_t{0}, size_t{5}}) check_streamed_like_staged(text, chunk);
}

TEST_CASE("obj streamed: a file's pages dropped once parsed are read again when the staged pipeline starts over", "[objimport][streamed]") {
  // Importing a file, each chunk drops its whole pages of the file's mapping once parsed
  // (release_read_pages). A face using positions defined further on sends the import to the
  // staged pipeline after chunks were parsed, and it must read the same bytes again.
  namespace fs = std::filesystem;
  const fs::path path = fs::temp_directory_path() / ("pfx-obj-streamed-" + std::to_string(::getpid()) + ".obj");
  const std::string varied = varied_file(20000, 7);
  // The face's chunk ends with a long comment line, before any position.
  for (const std::string& text : {varied, "f 1 2 3\n# " + std::string(20000, '.') + "\n" + varied}) {
    std::ofstream(path, std::ios::binary) << text;
    // The reference: the same text from memory (nothing dropped), staged, in one chunk.
    pfx_obj::ImportOptions one_chunk;
    one_chunk.threads = 1;
    one_chunk.chunk_bytes = size_t{1} << 30;
    one_chunk.streamed = false;
    Run whole;
    whole.ok = pfx_obj::import_obj_text(text, path.string(), path.parent_path().string(), one_chunk, &whole.mesh,
                                        &whole.error);
    REQUIRE(whole.ok);
    for (unsigned threads : {1u, 2u, 3u}) {
      INFO("threads " << threads << ", forward face " << (text != varied));
      pfx_obj::ImportOptions options;
      options.pool = pfx_obj_test::test_pool(threads);
      options.threads = threads;
      options.chunk_bytes = 16384;  // chunks of several pages
      Run run;
      run.ok = pfx_obj::import_obj_file(path.string(), options, &run.mesh, &run.error);
      REQUIRE(run.ok);
      check_same(whole.mesh, run.mesh);
      CHECK(ran_streamed(run.mesh) == (text == varied));
    }
  }
  fs::remove(path);
}
