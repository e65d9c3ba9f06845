// Generated normals: area-weighted, shared within a smoothing group, per face with smoothing off;
// expected values are the analytic normals of the shapes.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "obj_test_support.hpp"

using pfx_obj_test::import_text;

namespace {

const char* const kOctahedron =
    "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
    "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

}  // namespace

TEST_CASE("obj normals: a smooth octahedron gets the vertex directions", "[objimport][normals]") {
  auto r = import_text(std::string("s 1\n") + kOctahedron);
  REQUIRE(r.ok);
  REQUIRE(r.mesh.vertex_count() == 6);
  for (uint32_t i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k) CHECK(r.mesh.normals[3 * i + k] == Approx(r.mesh.positions[3 * i + k]).margin(1e-6));
  // No s statement at all: smoothed the same way (documented default).
  auto d = import_text(kOctahedron);
  REQUIRE(d.ok);
  CHECK(d.mesh.normals == r.mesh.normals);
}

TEST_CASE("obj normals: smoothing off gives each face its own vertices and normal", "[objimport][normals]") {
  auto r = import_text(std::string("s off\n") + kOctahedron);
  REQUIRE(r.ok);
  REQUIRE(r.mesh.vertex_count() == 24);
  const float k = static_cast<float>(1 / std::sqrt(3.0));
  for (size_t t = 0; t < r.mesh.indices.size(); t += 3) {
    // The face normal of an octahedron face is the sign pattern of its corners' sum.
    float sum[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 3; ++a) sum[a] += r.mesh.positions[3 * r.mesh.indices[t + c] + a];
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 3; ++a)
        CHECK(r.mesh.normals[3 * r.mesh.indices[t + c] + a] == Approx(sum[a] > 0 ? k : -k).margin(1e-6));
  }
  auto zero = import_text(std::string("s 0\n") + kOctahedron);
  REQUIRE(zero.ok);
  CHECK(zero.mesh.normals == r.mesh.normals);
}

TEST_CASE("obj normals: faces in different smoothing groups do not share", "[objimport][normals]") {
  // A roof: two triangles of equal area meeting at the ridge (edge 1-2) at a right angle.
  const std::string roof = "v 0 0 0\nv 1 0 0\nv 1 -1 -1\nv 0 -1 -1\nv 0 -1 1\nv 1 -1 1\n";
  auto split = import_text(roof + "s 1\nf 1 2 3\ns 2\nf 2 1 5\n");
  REQUIRE(split.ok);
  CHECK(split.mesh.vertex_count() == 6);
  auto shared = import_text(roof + "s 1\nf 1 2 3\nf 2 1 5\n");
  REQUIRE(shared.ok);
  CHECK(shared.mesh.vertex_count() == 4);
  // Ridge vertices: the two face normals (0,1,-1)/sqrt2 and (0,1,1)/sqrt2, equal areas: +y.
  for (uint32_t i = 0; i < shared.mesh.vertex_count(); ++i) {
    if (shared.mesh.positions[3 * i + 1] != 0) continue;
    CHECK(shared.mesh.normals[3 * i + 0] == Approx(0).margin(1e-6));
    CHECK(shared.mesh.normals[3 * i + 1] == Approx(1).margin(1e-6));
    CHECK(shared.mesh.normals[3 * i + 2] == Approx(0).margin(1e-6));
  }
}

TEST_CASE("obj normals: weighted by triangle area", "[objimport][normals]") {
  // Two triangles meeting at the origin: a large one in the xy plane (area 2, normal +z) and a
  // small one in the yz plane (area 0.5, normal +x). The shared corner's normal is
  // normalize(2 * z + 0.5 * x).
  auto r = import_text("v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 5\n");
  REQUIRE(r.ok);
  const double length = std::sqrt(2.0 * 2.0 + 0.5 * 0.5);
  REQUIRE(r.mesh.positions[0] == 0);
  CHECK(r.mesh.normals[0] == Approx(0.5 / length));
  CHECK(r.mesh.normals[1] == Approx(0).margin(1e-7));
  CHECK(r.mesh.normals[2] == Approx(2.0 / length));
}

TEST_CASE("obj normals: a UV seam keeps one normal per position and group", "[objimport][normals]") {
  auto r = import_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\n"
                       "f 1/1 2/2 3/3\nf 1/4 4/2 2/3\n");
  REQUIRE(r.ok);
  CHECK(r.mesh.vertex_count() == 6);
  std::map<std::array<float, 3>, std::array<float, 3>> normal_at;
  for (uint32_t i = 0; i < r.mesh.vertex_count(); ++i) {
    std::array<float, 3> p = {r.mesh.positions[3 * i], r.mesh.positions[3 * i + 1], r.mesh.positions[3 * i + 2]};
    std::array<float, 3> n = {r.mesh.normals[3 * i], r.mesh.normals[3 * i + 1], r.mesh.normals[3 * i + 2]};
    auto [it, fresh] = normal_at.emplace(p, n);
    if (!fresh) CHECK(it->second == n);
  }
}

TEST_CASE("obj normals: file normals are kept as written, degenerate faces get +z", "[objimport][normals]") {
  auto given = import_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n");
  REQUIRE(given.ok);
  CHECK(given.mesh.normals == std::vector<float>{0, 0, 2, 0, 0, 2, 0, 0, 2});
  auto degenerate = import_text("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  REQUIRE(degenerate.ok);
  CHECK(degenerate.mesh.normals == std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});
}
