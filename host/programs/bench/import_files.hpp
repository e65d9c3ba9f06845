// The OBJ files the import benchmark reads, generated at a requested size in one of several
// layouts, each the way some exporters write: a height field of N x N vertices (positions written
// to six decimals unless the layout says otherwise) and its grid cells as faces.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pfx::bench {

enum class ObjLayout {
  kPositionTriangles,  // "positions": v only, two `f a b c` per cell
  kTriangles,          // "triangles": v, vt, vn, two v/vt/vn triangles per cell
  kQuads,              // "quads": v, vt, vn, one `f a/a/a b/b/b c/c/c d/d/d` per cell
  kRelativeQuads,      // "relative-quads": the same with negative (relative) indices
  kObjects,            // "objects": quads in eight objects (`o`, `g`), three materials of an .mtl
  kLongNumbers,        // "long-numbers": triangles, numbers to nine decimals with exponents
  kShortNumbers,       // "short-numbers": triangles, numbers to two decimals
};

// Every layout, in the order above, and their names.
const std::vector<ObjLayout>& all_layouts();
const char* layout_name(ObjLayout layout);
bool layout_from_name(const std::string& name, ObjLayout* out);

struct GeneratedObj {
  std::string path;
  uint64_t bytes = 0;
  uint64_t grid = 0;       // N
  uint64_t triangles = 0;  // 2 (N - 1)^2
};

// Writes (or reuses, when a complete one is there) DIR/LAYOUT-SIZEmb.obj (and its .mtl), written
// under a temporary name and renamed when complete.
bool generate_obj(const std::string& directory, ObjLayout layout, double megabytes, GeneratedObj* out,
                  std::string* error);

}  // namespace pfx::bench
