// What the OBJ importer tests share: importing text in one call, and a mesh seen as a triangle
// soup (each corner's position, texture coordinate and normal), which compares two meshes
// independently of how their vertices are numbered.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "obj_import.hpp"

namespace pfx_obj {

// The importer's arrays compared element-wise with plain vectors (found by argument-dependent
// lookup through the arrays' allocator, which is pfx_obj's).
template <typename T>
bool operator==(const BigVector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}
template <typename T>
bool operator==(const std::vector<T>& a, const BigVector<T>& b) {
  return b == a;
}

}  // namespace pfx_obj

namespace pfx_obj_test {

struct Imported {
  bool ok = false;
  pfx_obj::ObjMesh mesh;
  std::string error;
};

// A thread pool of `threads` (libpfxhost's, as a host offers it), kept for the whole test run;
// null for one thread: the importer then runs without a pool, as under a host that offers none.
const pfx_thread_pool* test_pool(unsigned threads);

// Imports `text` as the file "test.obj" (no material libraries read) or, with `directory`, as a
// file in that folder, on test_pool(threads).
Imported import_text(const std::string& text, unsigned threads = 1, size_t chunk_bytes = 0,
                     const std::string& directory = "");

struct SoupCorner {
  std::array<float, 3> position{};
  std::array<float, 2> texcoord{};
  std::array<float, 3> normal{};
  bool operator==(const SoupCorner& o) const {
    return position == o.position && texcoord == o.texcoord && normal == o.normal;
  }
};
// Three corners per triangle, in index order.
std::vector<SoupCorner> soup(const pfx_obj::ObjMesh& mesh);

// A generated file using every statement: relative indices, material and smoothing changes,
// colours, polygons, line continuations, CRLF.
std::string varied_file(uint32_t faces, uint32_t seed);

// Checks (Catch CHECKs) that two imports gave the same mesh, bit for bit.
void check_same(const pfx_obj::ObjMesh& a, const pfx_obj::ObjMesh& b);

// The error of a failed import (the test fails if it succeeded).
std::string error_of(const std::string& text);

}  // namespace pfx_obj_test
