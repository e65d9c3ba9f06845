// The OBJ files the import benchmark reads, generated at a requested size: a height field of
// N x N vertices, each with a position, a texture coordinate and a normal written to six decimals,
// and two v/vt/vn triangles per grid cell — the layout of a typical exported scan or terrain.
#pragma once

#include <cstdint>
#include <string>

namespace pfx::bench {

struct GeneratedObj {
  std::string path;
  uint64_t bytes = 0;
  uint64_t grid = 0;        // N
  uint64_t vertices = 0;    // N * N distinct corners
  uint64_t triangles = 0;   // 2 (N - 1)^2
};

// Writes (or reuses, when a complete one is there) DIR/grid-SIZEmb.obj, written under a temporary
// name and renamed when complete.
bool generate_obj(const std::string& directory, double megabytes, GeneratedObj* out, std::string* error);

}  // namespace pfx::bench
