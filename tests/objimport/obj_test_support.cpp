#include "obj_test_support.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <memory>
#include <mutex>
#include <random>

#include <pfx/host/thread_pool.hpp>

namespace pfx_obj_test {

const pfx_thread_pool* test_pool(unsigned threads) {
  if (threads <= 1) return nullptr;
  static std::mutex mutex;
  static std::map<unsigned, std::unique_ptr<pfx::host::ThreadPool>> pools;
  std::lock_guard<std::mutex> lock(mutex);
  auto& pool = pools[threads];
  if (!pool) pool = std::make_unique<pfx::host::ThreadPool>(threads);
  return pool->service();
}

Imported import_text(const std::string& text, unsigned threads, size_t chunk_bytes, const std::string& directory) {
  Imported result;
  pfx_obj::ImportOptions options;
  options.pool = test_pool(threads);
  options.threads = threads;
  options.chunk_bytes = chunk_bytes;
  const std::string name = directory.empty() ? "test.obj" : directory + "/test.obj";
  result.ok = pfx_obj::import_obj_text(text, name, directory, options, &result.mesh, &result.error);
  return result;
}

std::vector<SoupCorner> soup(const pfx_obj::ObjMesh& mesh) {
  std::vector<SoupCorner> corners;
  for (uint32_t index : mesh.indices) {
    SoupCorner c;
    for (int k = 0; k < 3; ++k) c.position[k] = mesh.positions[3 * size_t{index} + k];
    for (int k = 0; k < 3; ++k) c.normal[k] = mesh.normals[3 * size_t{index} + k];
    if (!mesh.texcoords.empty())
      for (int k = 0; k < 2; ++k) c.texcoord[k] = mesh.texcoords[2 * size_t{index} + k];
    corners.push_back(c);
  }
  return corners;
}

std::string error_of(const std::string& text) {
  Imported result = import_text(text);
  CHECK_FALSE(result.ok);
  return result.error;
}

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

}  // namespace pfx_obj_test
