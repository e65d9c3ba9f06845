// Bad input: every case the issue names gives a clear "FILE:LINE: reason" or a documented
// warning, never a crash or a read past the end (the ASan build of the fuzz target covers the
// latter on random input; these name the cases).
#include <catch2/catch.hpp>

#include <random>

#include "obj_test_support.hpp"

using pfx_obj_test::error_of;
using pfx_obj_test::import_text;

namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
const std::string kCornerHint = " (expected v, v/vt, v//vn or v/vt/vn)";

}  // namespace

TEST_CASE("obj malformed: index 0", "[objimport][malformed]") {
  CHECK(error_of(kTriangle + "f 0 1 2\n") == "test.obj:4: f: v index 0 in '0' (OBJ indices start at 1)");
  CHECK(error_of(kTriangle + "vt 0 0\nf 1/0 2/1 3/1\n") == "test.obj:5: f: vt index 0 in '1/0' (OBJ indices start at 1)");
  CHECK(error_of(kTriangle + "f 1//-0 2 3\n") == "test.obj:4: f: vn index 0 in '1//-0' (OBJ indices start at 1)");
}

TEST_CASE("obj malformed: indices out of range", "[objimport][malformed]") {
  CHECK(error_of(kTriangle + "f 1 2 4\n") == "test.obj:4: f: v index 4 is out of range (the file has 3 v)");
  CHECK(error_of(kTriangle + "f 1/1 2/1 3/1\n") == "test.obj:4: f: vt index 1 but the file has no vt");
  CHECK(error_of(kTriangle + "vn 0 0 1\nf 1//2 2//1 3//1\n") == "test.obj:5: f: vn index 2 is out of range (the file has 1 vn)");
  CHECK(error_of(kTriangle + "f -4 -2 -1\n") == "test.obj:4: f: relative v index reaches before the first v");
  CHECK(error_of(kTriangle + "f 1 2 99999999999\n") == "test.obj:4: f: index '99999999999' is too large");
  CHECK(error_of(kTriangle + "f 1 2 -2147483648\n") == "test.obj:4: f: index '-2147483648' is too large");
  CHECK(error_of(kTriangle + "f 1 2 1234567890123456789012\n") == "test.obj:4: f: index '1234567890123456789012' is too large");
}

TEST_CASE("obj malformed: malformed corner tokens", "[objimport][malformed]") {
  for (const char* corner : {"/", "//", "4?1", "1//2//3", "1/", "1/2/", "/1", "//1", "1///2", "a", "1.5", "1/x/2", "+", "-"}) {
    INFO(corner);
    CHECK(error_of(kTriangle + "f 1 2 " + corner + "\n") ==
          "test.obj:4: f: malformed corner '" + std::string(corner) + "'" + kCornerHint);
  }
  CHECK(error_of(kTriangle + "f 1 2\n") == "test.obj:4: f: needs at least 3 corners (got 2)");
  CHECK(error_of(kTriangle + "f\n") == "test.obj:4: f: needs at least 3 corners (got 0)");
}

TEST_CASE("obj malformed: nan and inf coordinates", "[objimport][malformed]") {
  CHECK(error_of("v nan 0 0\n") == "test.obj:1: v: 'nan' is not a finite number");
  CHECK(error_of("v 0 -INF 0\n") == "test.obj:1: v: '-INF' is not a finite number");
  CHECK(error_of("vn 0 0 infinity\n") == "test.obj:1: vn: 'infinity' is not a finite number");
  CHECK(error_of("vt NaN 0\n") == "test.obj:1: vt: 'NaN' is not a finite number");
  // Finite in the file, infinite as a float: refused too.
  CHECK(error_of("v 1e39 0 0\n") == "test.obj:1: v: '1e39' is out of the 32-bit float range");
  CHECK(error_of("v 1e999 0 0\n") == "test.obj:1: v: '1e999' is out of the 32-bit float range");
}

TEST_CASE("obj malformed: wrong number counts and malformed numbers", "[objimport][malformed]") {
  CHECK(error_of("v 1 2\n") == "test.obj:1: v: expected x y z, x y z w or x y z r g b (got 2 numbers)");
  CHECK(error_of("v 1 2 3 4 5\n") == "test.obj:1: v: expected x y z, x y z w or x y z r g b (got 5 numbers)");
  CHECK(error_of("v 1 2 3 4 5 6 7 8\n") == "test.obj:1: v: too many numbers (at most 7)");
  CHECK(error_of("vn 1 2\n") == "test.obj:1: vn: expected x y z (got 2 numbers)");
  CHECK(error_of("vt\n") == "test.obj:1: vt: expected u [v [w]] (got no number)");
  CHECK(error_of("v 1 2 3,5\n") == "test.obj:1: v: malformed number '3,5'");
  CHECK(error_of("v 1 2 0x10\n") == "test.obj:1: v: malformed number '0x10'");
  CHECK(error_of("s maybe\n") == "test.obj:1: s: 'maybe' is not a smoothing group (a number 0 to 2147483647, or off)");
  CHECK(error_of("s\n") == "test.obj:1: s: needs a group number or off");
  CHECK(error_of("usemtl\n") == "test.obj:1: usemtl: needs a material name");
  CHECK(error_of("mtllib   \n") == "test.obj:1: mtllib: needs a file name");
}

TEST_CASE("obj malformed: an empty file imports as an empty mesh with a warning", "[objimport][malformed]") {
  for (const std::string& text : {std::string(), std::string("\n\n"), std::string("# only a comment"),
                                  std::string("\xEF\xBB\xBF")}) {
    auto r = import_text(text);
    REQUIRE(r.ok);
    CHECK(r.mesh.vertex_count() == 0);
    CHECK(r.mesh.indices.empty());
    CHECK(r.mesh.bounds_min[0] == 0);
    REQUIRE(r.mesh.warnings.size() == 1);
    CHECK(r.mesh.warnings[0].find("no faces: the mesh is empty") != std::string::npos);
  }
}

TEST_CASE("obj malformed: a binary file is refused at its first bad byte", "[objimport][malformed]") {
  std::string binary = std::string("\x7f" "ELF\x02\x01\x01", 7) + std::string(20, '\0');
  CHECK(error_of(binary) == "test.obj:1: binary data (byte 0x7f in a keyword): not an OBJ text file");
  // Random bytes: always an error or a mesh, never a crash.
  std::mt19937 random(7);
  for (int round = 0; round < 200; ++round) {
    std::string bytes(1 + random() % 4096, '\0');
    for (char& c : bytes) c = static_cast<char>(random());
    auto r = import_text(bytes, 1 + round % 3, 64);
    if (!r.ok) CHECK(r.error.rfind("test.obj:", 0) == 0);
  }
}

TEST_CASE("obj malformed: a 10 MB line", "[objimport][malformed]") {
  // A comment, a face and a vertex, each one line of 10 MB.
  const size_t size = 10u << 20;
  std::string comment = "# " + std::string(size, 'x') + "\n" + kTriangle + "f 1 2 3\n";
  auto c = import_text(comment, 2, 1 << 20);
  REQUIRE(c.ok);
  CHECK(c.mesh.indices.size() == 3);

  std::string face = kTriangle + "f";
  while (face.size() < size) face += " 1 2 3";
  face += "\n";
  auto f = import_text(face, 2, 1 << 20);
  REQUIRE(f.ok);
  CHECK(f.mesh.warnings.size() == 1);
  CHECK(f.mesh.warnings[0].find("test.obj:4: f: polygon of ") == 0);
  CHECK(f.mesh.warnings[0].find("corners is too large for ear clipping (over 4096 corners): triangulated as a fan") !=
        std::string::npos);

  std::string vertex = "v";
  while (vertex.size() < size) vertex += " 1.25";
  CHECK(error_of(vertex + "\n") == "test.obj:1: v: too many numbers (at most 7)");
  std::string token = "v 1 2 " + std::string(size, '7') + "\n";
  auto t = import_text(token);
  REQUIRE_FALSE(t.ok);
  CHECK(t.error.rfind("test.obj:1: v: '777777", 0) == 0);
  CHECK(t.error.find("...' is out of the 32-bit float range") != std::string::npos);
}

TEST_CASE("obj malformed: a usemtl without a material library is a warning", "[objimport][malformed]") {
  auto r = import_text(kTriangle + "usemtl red\nf 1 2 3\n");
  REQUIRE(r.ok);
  REQUIRE(r.mesh.materials.size() == 1);
  CHECK(r.mesh.materials[0].name == "red");
  CHECK(r.mesh.materials[0].diffuse[0] == 0.8f);
  REQUIRE(r.mesh.warnings.size() == 1);
  CHECK(r.mesh.warnings[0] == "test.obj:4: usemtl red: no material of that name in the material libraries (defaults used)");
}
