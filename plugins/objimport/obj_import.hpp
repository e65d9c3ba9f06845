// The OBJ importer as a C++ function, for the plugin's C entry point and for the tests: text in,
// one deduplicated, triangulated mesh out, the same for every thread count, or a message
// "FILE:LINE: reason". How: obj_stages.hpp.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <pfx/importer.h>
#include <pfx/services.h>

#include "obj_buffer.hpp"
#include "obj_mtl.hpp"

namespace pfx_obj {

struct ObjMesh {
  BigVector<float> positions;  // 3 per vertex
  BigVector<float> normals;    // 3 per vertex
  BigVector<float> texcoords;  // 2 per vertex, or empty when no corner has one
  BigVector<float> colors;     // 3 per vertex, or empty when no v has a colour
  BigVector<uint32_t> indices;
  std::vector<pfx_import_submesh> submeshes;  // material: index or kNoIndex (no usemtl)
  std::vector<Material> materials;
  float bounds_min[3] = {0, 0, 0}, bounds_max[3] = {0, 0, 0};
  uint64_t lines_skipped = 0, points_skipped = 0, faces = 0;
  std::vector<std::string> warnings;  // the first kMaxWarnings, in file order
  uint64_t warning_total = 0;
  uint32_t vertex_count() const { return static_cast<uint32_t>(positions.size() / 3); }
};

constexpr size_t kMaxWarnings = 100;

struct ImportOptions {
  // The host's thread pool (pfx/services.h), on which every parallel stage runs; null: the import
  // runs on the calling thread alone. The importer starts no thread of its own.
  const pfx_thread_pool* pool = nullptr;
  unsigned threads = 0;                  // at most this many tasks at once; 0: the pool's concurrency
  std::function<void(float)> progress;   // 0..1, on the calling thread
  size_t chunk_bytes = 0;                // 0: chosen from the size and thread count (tests set it)
};

// How many tasks run at once: the request's bound within what the pool offers; 1 without a pool.
inline unsigned worker_count(const pfx_thread_pool* pool, unsigned requested) {
  if (!pool) return 1;
  const unsigned offered = std::max(1u, pool->concurrency(pool->pool_data));
  return requested ? std::min(requested, offered) : offered;
}

// name: the file name in messages. directory: where mtllib files are looked for; empty means
// material libraries are not read (a warning says so).
bool import_obj_text(std::string_view text, const std::string& name, const std::string& directory,
                     const ImportOptions& options, ObjMesh* out, std::string* error);
bool import_obj_file(const std::string& path, const ImportOptions& options, ObjMesh* out, std::string* error);

}  // namespace pfx_obj
