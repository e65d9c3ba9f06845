// The importer's stages and what passes between them. import_obj_text (obj_import.cpp) runs them
// in this order, each taking the types of the stages before it and returning its own:
//
//   1. cut       text -> chunks' texts, cut at line ends (split_at_line_ends, obj_chunk.hpp)
//   2. number    chunks' texts -> NumberedFile (obj_numbering.cpp): each chunk read on any worker
//                into a ChunkData (obj_reader.cpp), then numbered in file order as soon as it and
//                every chunk before it are read: its vertex data appended to the file's, each
//                corner numbered against one vertex numbering for the whole file (obj_dedup.hpp),
//                relative indices made final, its faces written as triangles, polygons ear-clipped
//                (obj_triangulate.cpp). The workers read later chunks while one numbers
//                (obj_parallel.hpp), so the numbers never depend on the thread count.
//   3. check     NumberedFile -> nothing, or an ImportError naming the first bad index; then the
//                polygons that reached past the positions read so far clipped (obj_numbering.cpp)
//   4. materials FileStatements -> MaterialTable: the material libraries read (obj_mtl.cpp)
//   5. index     triangles, by material -> TriangleIndex: sub-meshes (obj_import.cpp)
//   6. vertices  keys and FileVertices -> MeshVertices, and the bounds (obj_import.cpp)
//   7. normals   where the file gives none (obj_normals.hpp)
//   8. warnings  every stage's, in line order (obj_import.cpp)
//
// Large arrays are obj_buffer.hpp's; the parallel stages run on the host's thread pool
// (obj_parallel.hpp), or without one on the calling thread.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <pfx/importer.h>
#include <pfx/services.h>

#include "obj_buffer.hpp"
#include "obj_chunk.hpp"
#include "obj_dedup.hpp"
#include "obj_file.hpp"
#include "obj_mtl.hpp"

namespace pfx_obj {

// "NAME:LINE: text", as every message about a line of the file reads.
inline std::string at_line(const std::string& name, uint64_t line, const std::string& text) {
  return name + ":" + std::to_string(line) + ": " + text;
}

// Why an import failed, the message whole: "FILE:LINE: reason" (at_line) or "FILE: reason". Every
// stage fails by throwing one (or std::bad_alloc); the public functions turn it into a message.
struct ImportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What the stages of one import share besides their inputs: where the text came from, where they run.
struct ImportContext {
  const std::string& name;       // the file name in messages
  const std::string& directory;  // where mtllib files are looked for; empty: not at all
  const FileBytes* file;         // the text's mapping, whose pages are dropped as chunks are read; or null
  const pfx_thread_pool* pool;   // null: every stage on the calling thread
  unsigned threads;              // workers at once
};

// The file up to a chunk boundary: what came before it, and the state in force there.
struct FileSoFar {
  uint64_t line = 1;               // the first line after the boundary
  uint32_t bases[3] = {0, 0, 0};   // v, vt and vn before it (what relative indices count back from)
  uint64_t faces = 0;
  uint64_t triangles = 0;          // also where the next chunk's triangles start in NumberedFile::triangles
  uint32_t material = kNoIndex;    // the usemtl name in force (index into FileStatements::material_names), or none
  uint32_t smoothing = kDefaultSmoothing;
};

// A chunk once numbered: what the later stages need of it.
struct NumberedChunk {
  FileSoFar start, end;
  uint32_t max_index[3] = {0, 0, 0};  // its largest positive v, vt, vn index (1-based)
  bool suspect = false;  // it may hold an index the file cannot satisfy; then no later chunk is numbered
  std::vector<StateChange> changes;  // a usemtl's value: an index into FileStatements::material_names
};

// The file's statements that make no geometry, gathered in file order (lines: the file's).
struct FileStatements {
  std::vector<LocalMessage> material_names;      // usemtl names in order of first use, at that line
  std::vector<LocalMessage> material_libraries;  // the rest of each mtllib line
  std::map<std::string, IgnoredKeyword> ignored;
  uint64_t lines_skipped = 0, points_skipped = 0;
};

// The file's vertex data as written: x y z per v, u v per vt, x y z per vn, and r g b per v (white
// for a v without one) or none when no v has a colour.
struct FileVertices { BigVector<float> positions, texcoords, normals, colors; };

// A polygon with a corner whose position comes later in the file: cut as a fan at `at` (its first
// triangle's place in NumberedFile::triangles) until the positions are read.
struct DeferredPolygon { uint64_t at; uint32_t corners; uint64_t line; };

// Stage 2's output.
struct NumberedFile {
  std::vector<NumberedChunk> chunks;  // one per text, in file order
  FileVertices vertices;
  BigVector<VertexKey> keys;          // one per vertex: its distinct corner, in order of first use
  BigVector<uint32_t> triangles;      // three vertex numbers per triangle, in file order
  std::vector<DeferredPolygon> deferred;
  FileStatements statements;
  std::vector<LocalMessage> warnings;  // polygons cut as fans
  const FileSoFar& totals() const { return chunks.back().end; }
};

// numbered: the fraction of the text numbered so far, on the calling thread.
NumberedFile number_chunks(const std::vector<std::string_view>& texts, const ImportContext& context,
                           const std::function<void(double)>& numbered);

// Stage 3: throws an ImportError at the first index, in file order, outside the file's totals.
// The chunks that may hold one are read again from their texts (an error path only).
void check_indices(const std::vector<std::string_view>& texts, const NumberedFile& file, const ImportContext& context);

// The deferred polygons' fans replaced by their ear-clipped triangles (warnings to file->warnings).
void clip_deferred_polygons(NumberedFile* file);

// Stage 4's output.
struct MaterialTable {
  std::vector<Material> materials;    // the libraries', then a default one per unknown usemtl name
  std::vector<uint32_t> of_name;      // per usemtl name (FileStatements::material_names): its material
  std::vector<LocalMessage> warnings;
};

// directory: where the libraries are looked for; empty: none is read (a warning says so).
MaterialTable load_materials(const FileStatements& statements, const std::string& directory);

// Stage 5's output.
struct TriangleIndex {
  BigVector<uint32_t> indices;
  std::vector<pfx_import_submesh> submeshes;  // in order of their material's first triangle
};

// Each material's triangles together, taken from `triangles` (file order).
TriangleIndex index_by_material(const std::vector<NumberedChunk>& chunks, const MaterialTable& materials,
                                BigVector<uint32_t> triangles);

// Stage 6's output.
struct MeshVertices {
  BigVector<float> positions, normals, texcoords, colors;  // texcoords, colors: empty when none given
  float bounds_min[3] = {0, 0, 0}, bounds_max[3] = {0, 0, 0};
};

// Each vertex's data gathered by its key (normals: zero where the file gives none), each kind of
// `file` freed as soon as it is gathered.
MeshVertices gather_vertices(const BigVector<VertexKey>& keys, FileVertices file, const ImportContext& context);

}  // namespace pfx_obj
