// The import pipeline's state, shared by the files that run its stages:
//
//   obj_import.cpp    the pipeline in order, and parse: chunks in parallel (obj_chunk.cpp)
//   obj_plan.cpp      plan, serial: the first parse error, where each chunk's lines, elements and
//                     faces start, the material libraries, the material and smoothing group in
//                     force at each chunk's start
//   obj_resolve.cpp   resolve, chunks in parallel: relative indices made final, range checks,
//                     triangle counts per material; each face's material and normal group
//   obj_assemble.cpp  vertex data kept where the chunks wrote it, the index array laid out, each
//                     corner numbered (obj_dedup.cpp) and written there in the same walk,
//                     vertex arrays and bounds, normals (obj_normals.cpp), warnings
//   obj_streamed.cpp  the default: each chunk parsed, its corners numbered in file order while
//                     later chunks are parsed, then the stages above from plan on, the index
//                     array written from the numbers
//
// Nothing in the output depends on how the text was cut: vertices are numbered by first use,
// sub-meshes follow the first use of their material, triangles keep file order within one.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "obj_buffer.hpp"
#include "obj_chunk.hpp"
#include "obj_chunked_elements.hpp"
#include "obj_dedup.hpp"
#include "obj_face_states.hpp"
#include "obj_import.hpp"
#include "obj_stages.hpp"
#include "obj_triangulate.hpp"

namespace pfx_obj {

struct Located {
  uint64_t line;  // 1-based, in the OBJ file
  std::string text;
};

// "FILE:LINE: text"
inline std::string at(const std::string& name, uint64_t line, const std::string& text) {
  return name + ":" + std::to_string(line) + ": " + text;
}

// What the serial plan knows of one chunk before the parallel stages use it.
struct ChunkPlan {
  uint64_t first_line = 1;
  uint32_t position_base = 0, texcoord_base = 0, normal_base = 0;
  uint64_t face_base = 0;
  uint32_t start_material = kNoIndex;  // material slot in force at the chunk's start
  uint32_t start_smoothing = kDefaultSmoothing;
  std::vector<uint32_t> material_slots;  // chunk material name index -> material slot
  uint32_t start_slot = 0;  // start_material, or the no-material slot (set by the resolve stage)
};

// What the resolve stage makes of one chunk.
struct ChunkFaces {
  std::vector<uint64_t> triangle_counts;  // per material slot
  std::vector<uint64_t> first_use;        // per material slot: the file ordinal of its first face
  bool failed = false;
  Located error;
  std::vector<Located> warnings;
  uint64_t warning_total = 0;
};

class Importer {
 public:
  // text_is_file_mapping: the text to import is a FileBytes mapping, whose pages each chunk drops
  // once parsed (release_read_pages).
  Importer(const std::string& name, const std::string& directory, const ImportOptions& options,
           bool text_is_file_mapping)
      : name_(name), directory_(directory), options_(options), release_text_(text_is_file_mapping) {
    threads_ = worker_count(options.pool, options.threads);
  }

  // The staged pipeline, on any number of threads.
  bool run(std::string_view text, ObjMesh* out, std::string* error);

  // Chunk by chunk (obj_streamed.cpp). kUseStages: the file needs what only the staged
  // pipeline does (an index the chunks read so far cannot settle); *out is then to be discarded.
  enum class Outcome { kDone, kFailed, kUseStages };
  Outcome run_streamed(std::string_view text, ObjMesh* out, std::string* error);

 private:
  void report(float fraction) {
    if (options_.progress) options_.progress(fraction);
  }
  void warn(uint64_t line, std::string text) { warnings_.push_back({line, std::move(text)}); }

  // obj_import.cpp
  size_t chunk_count(size_t bytes) const;
  void parse(std::string_view text);
  void parse_one(size_t c, size_t reserve_bytes);
  void assemble(StageClock* clock);

  // obj_plan.cpp
  bool plan(std::string* error);
  void load_material_library(uint64_t line, const std::string& text);
  uint32_t material_slot(const std::string& name, uint64_t line);

  // obj_resolve.cpp
  void resolve_all(unsigned threads);
  void resolve(size_t c, size_t slots);
  bool first_resolve_error(std::string* error);
  FaceStates face_states(size_t c) const;

  // obj_assemble.cpp
  void gather();
  void layout_triangles();
  void number_and_triangulate(StageClock* clock);
  void triangulate_chunk(size_t c, VertexNumbering* numbering);
  struct PolygonScratch {
    TriangulationScratch triangulation;
    std::vector<uint32_t> polygon;
  };
  void write_polygon(size_t c, size_t f, uint32_t n, const uint32_t* corner_ids, const float* const* corner_positions,
                     uint64_t* cursor, PolygonScratch* scratch);
  void free_corners(size_t c);
  void end_chunks();
  void fill_vertices();
  void finish();

  // obj_streamed.cpp
  // The file up to the last chunk numbered, chunk by chunk.
  struct StreamedSoFar {
    uint64_t positions = 0, texcoords = 0, normals = 0, faces = 0, corners = 0, bytes = 0;
    uint32_t smoothing = kDefaultSmoothing;
  };
  enum class Taken { kNumbered, kStop, kUseStages };
  Taken take_streamed_chunk(size_t c, uint64_t text_bytes, StreamedSoFar* so_far, VertexNumbering* numbering);
  bool number_streamed_chunk(size_t c, const uint32_t bases[3], uint32_t start_smoothing, uint64_t face_base,
                             VertexNumbering* numbering, uint32_t* ids);
  void write_streamed_triangles();

  const std::string& name_;
  const std::string& directory_;
  const ImportOptions& options_;
  unsigned threads_ = 1;
  bool release_text_ = false;
  ObjMesh* out_ = nullptr;
  std::vector<std::string_view> texts_;
  std::vector<ChunkData> chunks_;
  std::vector<ChunkPlan> plans_;
  std::vector<ChunkFaces> faces_;
  uint32_t totals_[3] = {0, 0, 0};
  bool any_colors_ = false;
  std::vector<Located> warnings_;
  uint64_t extra_warnings_ = 0;  // warnings the chunks counted but did not keep
  std::map<std::string, IgnoredKeyword> ignored_;
  std::unordered_map<std::string, uint32_t> material_index_;  // material name -> index in out_->materials
  // Each kind of vertex data, read where the chunks wrote it (their arrays kept in vertex_data_).
  ChunkedElements all_positions_{3}, all_texcoords_{2}, all_normals_{3}, all_colors_{3};
  std::vector<BigVector<float>> vertex_data_;
  BigVector<VertexKey> keys_;
  std::vector<std::vector<uint64_t>> write_at_;  // per chunk and material slot: its first index
  uint64_t index_total_ = 0;                     // the index array's length
  // Chunk by chunk (obj_streamed.cpp): every corner's vertex number in file order, where each chunk's
  // start, and which chunks kept their faces (those with polygons or a usemtl).
  BigVector<uint32_t> streamed_ids_;
  std::vector<uint64_t> id_begin_;
  std::vector<bool> faces_kept_;
};

}  // namespace pfx_obj
