// The OBJ grammar the importer accepts: every face form, relative indices, the statements it
// records or counts, and the ways text can be laid out (line ends, BOM, continuations, comments).
// Expected values are written out by hand from the file in each test.
#include <catch2/catch.hpp>

#include "obj_test_support.hpp"

using pfx_obj_test::import_text;
using pfx_obj_test::soup;

namespace {

const char* const kSquare =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\n";

std::vector<float> positions_of_corners(const pfx_obj::ObjMesh& mesh) {
  std::vector<float> out;
  for (uint32_t i : mesh.indices)
    for (int k = 0; k < 3; ++k) out.push_back(mesh.positions[3 * i + k]);
  return out;
}

}  // namespace

TEST_CASE("obj grammar: a triangle with v only", "[objimport][grammar]") {
  auto r = import_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  REQUIRE(r.ok);
  CHECK(r.mesh.vertex_count() == 3);
  CHECK(r.mesh.indices == std::vector<uint32_t>{0, 1, 2});
  CHECK(r.mesh.texcoords.empty());
  CHECK(r.mesh.colors.empty());
  CHECK(r.mesh.faces == 1);
  // Generated normal of a counter-clockwise triangle in the xy plane: +z.
  CHECK(r.mesh.normals == std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});
  CHECK(r.mesh.bounds_min[0] == 0);
  CHECK(r.mesh.bounds_max[1] == 1);
  CHECK(r.mesh.warnings.empty());
}

TEST_CASE("obj grammar: every face form v, v/vt, v//vn, v/vt/vn", "[objimport][grammar]") {
  auto vt = import_text(std::string(kSquare) + "f 1/1 2/2 3/3\n");
  REQUIRE(vt.ok);
  CHECK(vt.mesh.texcoords == std::vector<float>{0, 0, 1, 0, 1, 1});
  auto vn = import_text(std::string(kSquare) + "f 1//1 2//1 3//1\n");
  REQUIRE(vn.ok);
  CHECK(vn.mesh.texcoords.empty());
  CHECK(vn.mesh.normals == std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});
  auto all = import_text(std::string(kSquare) + "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
  REQUIRE(all.ok);
  CHECK(all.mesh.vertex_count() == 4);
  CHECK(all.mesh.indices.size() == 6);
  CHECK(all.mesh.texcoords == std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1});
  // Mixed forms within one face are accepted; a corner without vt gets (0, 0).
  auto mixed = import_text(std::string(kSquare) + "f 1/1/1 2//1 3/3\n");
  REQUIRE(mixed.ok);
  CHECK(mixed.mesh.texcoords == std::vector<float>{0, 0, 0, 0, 1, 1});
}

TEST_CASE("obj grammar: negative indices count back from the latest element", "[objimport][grammar]") {
  auto relative = import_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -3 -1\n");
  auto absolute = import_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 5 5 5\nf 1 2 4\n");
  REQUIRE(relative.ok);
  REQUIRE(absolute.ok);
  CHECK(positions_of_corners(relative.mesh) == positions_of_corners(absolute.mesh));
  CHECK(positions_of_corners(relative.mesh) == std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 5, 5});
  auto with_vt_vn = import_text(std::string(kSquare) + "f -4/-4/-1 -3/-3/-1 -2/-2/-1\n");
  REQUIRE(with_vt_vn.ok);
  CHECK(with_vt_vn.mesh.texcoords == std::vector<float>{0, 0, 1, 0, 1, 1});
}

TEST_CASE("obj grammar: forward references resolve against the whole file", "[objimport][grammar]") {
  auto r = import_text("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  REQUIRE(r.ok);
  CHECK(positions_of_corners(r.mesh) == std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  // Polygons before their positions are cut where they would be after them: a dart whose first
  // corner is its reflex one's neighbour (a fan from it would cover the notch), and one with no area.
  const std::string dart = "v 2 1 0\nv 0.5 0.5 0\nv 1 2 0\nv 0 0 0\n", faces = "f 1 2 3 4\nf 1 3 1 3\n";
  // (Chunks of a line each: a polygon numbered before the chunk with its positions is read.)
  auto later = import_text(faces + dart, 1, 8), earlier = import_text(dart + faces);
  REQUIRE(later.ok);
  REQUIRE(earlier.ok);
  const std::vector<float> fan = {2, 1, 0, 0.5f, 0.5f, 0, 1, 2, 0, 2, 1, 0, 1, 2, 0, 0, 0, 0};
  const std::vector<float> clipped = positions_of_corners(earlier.mesh);
  CHECK(std::vector<float>(clipped.begin(), clipped.begin() + 18) != fan);
  CHECK(positions_of_corners(later.mesh) == clipped);
  CHECK(later.mesh.warnings == std::vector<std::string>{"test.obj:2: f: polygon of 4 corners has no area: triangulated as a fan"});
}

TEST_CASE("obj grammar: v with w, with a colour, vt with one or three numbers", "[objimport][grammar]") {
  auto r = import_text("v 0 0 0 1\nv 1 0 0 0.5 0.25 0.125\nv 0 1 0\nvt 0.5\nvt 0.25 0.75 1\n"
                       "f 1/1 2/2 3/1\n");
  REQUIRE(r.ok);
  // w is read and dropped; vertices without a colour are white.
  CHECK(r.mesh.positions == std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  CHECK(r.mesh.colors == std::vector<float>{1, 1, 1, 0.5f, 0.25f, 0.125f, 1, 1, 1});
  CHECK(r.mesh.texcoords == std::vector<float>{0.5f, 0, 0.25f, 0.75f, 0.5f, 0});
}

TEST_CASE("obj grammar: o, g, s, l, p, comments and unknown statements", "[objimport][grammar]") {
  auto r = import_text(
      "# a comment\n"
      "o thing one\ng group a b\nv 0 0 0 # trailing comment\nv 1 0 0\nv 0 1 0\n"
      "l 1 2\nl 2 3 1\np 1\ns 1\nf 1 2 3 # the face\ns off\ncurv 0 1 1 2\nfrobnicate 1\nfrobnicate 2\n");
  REQUIRE(r.ok);
  CHECK(r.mesh.lines_skipped == 2);
  CHECK(r.mesh.points_skipped == 1);
  CHECK(r.mesh.indices.size() == 3);
  REQUIRE(r.mesh.warnings.size() == 2);
  CHECK(r.mesh.warnings[0] == "test.obj:13: 'curv' statements are not supported: 1 ignored");
  CHECK(r.mesh.warnings[1] == "test.obj:14: unknown statement 'frobnicate': 2 ignored");
}

TEST_CASE("obj grammar: CRLF, bare CR, no final newline and a byte-order mark give the same mesh", "[objimport][grammar]") {
  const std::string lf = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
  auto reference = import_text(lf);
  REQUIRE(reference.ok);
  auto replace_all = [](std::string text, const std::string& with) {
    std::string out;
    for (char c : text) out += c == '\n' ? with : std::string(1, c);
    return out;
  };
  for (const std::string& variant :
       {replace_all(lf, "\r\n"), replace_all(lf, "\r"), lf.substr(0, lf.size() - 1), "\xEF\xBB\xBF" + lf,
        "\xEF\xBB\xBF" + replace_all(lf, "\r\n").substr(0, replace_all(lf, "\r\n").size() - 2)}) {
    auto r = import_text(variant);
    REQUIRE(r.ok);
    CHECK(r.mesh.indices == reference.mesh.indices);
    CHECK(r.mesh.positions == reference.mesh.positions);
  }
  // Line numbers count every kind of line end once.
  CHECK(pfx_obj_test::error_of("v 0 0 0\r\nv 1 0 0\rv 0 1 0\nf 1 2 x\n") ==
        "test.obj:4: f: malformed corner 'x' (expected v, v/vt, v//vn or v/vt/vn)");
}

TEST_CASE("obj grammar: a backslash continues a statement on the next line", "[objimport][grammar]") {
  auto r = import_text("v 0 0 0\nv 1 \\\n 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 \\\r\n 4 \\\r 3\nf 1 2 x\n");
  REQUIRE_FALSE(r.ok);
  // The statement after the continued lines keeps its own physical line number.
  CHECK(r.error == "test.obj:9: f: malformed corner 'x' (expected v, v/vt, v//vn or v/vt/vn)");
  auto ok = import_text("v 0 0 0\nv 1 \\\n 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 \\\r\n 4 \\\r 3\n");
  REQUIRE(ok.ok);
  CHECK(ok.mesh.positions == std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  CHECK(ok.mesh.indices.size() == 6);
}

TEST_CASE("obj grammar: numbers like .5, 1., +1, 1e-5 and -0 in coordinates", "[objimport][grammar]") {
  auto r = import_text("v .5 1. +1\nv 1e-5 -0 0\nv 0 1 0\nf 1 2 3\n");
  REQUIRE(r.ok);
  CHECK(r.mesh.positions[0] == 0.5f);
  CHECK(r.mesh.positions[1] == 1.0f);
  CHECK(r.mesh.positions[2] == 1.0f);
  CHECK(r.mesh.positions[3] == 1e-5f);
  CHECK(r.mesh.positions[4] == 0.0f);
  CHECK(std::signbit(r.mesh.positions[4]));
}

TEST_CASE("obj grammar: tabs and repeated blanks separate tokens", "[objimport][grammar]") {
  auto r = import_text("v\t0  0\t\t0\n  v 1 0 0\nv 0 1 0   \n\tf  1\t2 3  \n");
  REQUIRE(r.ok);
  CHECK(r.mesh.indices.size() == 3);
}
