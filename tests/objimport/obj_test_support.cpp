#include "obj_test_support.hpp"

#include <catch2/catch.hpp>

namespace pfx_obj_test {

Imported import_text(const std::string& text, unsigned threads, size_t chunk_bytes, const std::string& directory) {
  Imported result;
  pfx_obj::ImportOptions options;
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

}  // namespace pfx_obj_test
