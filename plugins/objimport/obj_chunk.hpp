// One chunk of an OBJ file, read on its own (obj_reader.cpp), in parallel with the others. A chunk
// cannot know what came before it, so what depends on earlier text is kept in a form the in-order
// numbering (obj_import.cpp) can finish: relative indices, the material and smoothing changes, and
// lines counted from the chunk's first line.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "obj_buffer.hpp"

namespace pfx_obj {

// An index field a corner lacks (no vt, no vn); also "none" wherever an index may be missing.
constexpr uint32_t kNoIndex = 0xFFFFFFFFu;
// OBJ indices as written must fit in 31 bits (a file with 2^31 vertices would be over 16 GB).
constexpr int64_t kMaxWrittenIndex = 0x7FFFFFFF;

// A text at a line: counted from the chunk's first line (0-based) in a chunk's data, from the
// file's (1-based) after.
struct LocalMessage {
  uint64_t line = 0;
  std::string text;
};

struct Face {
  uint32_t corner_count;
  uint32_t line;  // chunk-local, 0-based
};

// A usemtl or s statement, recorded at the first face it applies to.
struct StateChange {
  enum Kind : uint32_t { kMaterial = 0, kSmoothing = 1 };
  uint32_t first_face;  // chunk-local
  Kind kind;
  uint32_t value;  // kMaterial: index into ChunkData::material_names (the file's, once numbered);
                   // kSmoothing: group, 0 = off
  uint64_t first_triangle;  // chunk-local: the triangles its faces before it make
};

// Statements counted and skipped with one warning per keyword.
struct IgnoredKeyword {
  uint64_t first_line = 0;  // chunk-local
  uint64_t count = 0;
  bool valid_obj = false;  // OBJ that pfx does not mesh (free-form geometry), not an unknown word
};

struct ChunkData {
  uint64_t line_ends = 0;  // physical line ends in the chunk: the next chunk's first line follows

  BigVector<float> positions;  // x y z per v
  BigVector<float> colors;     // r g b per v, or empty while no v of the chunk has a colour
  BigVector<float> texcoords;  // u v per vt
  BigVector<float> normals;    // x y z per vn

  // Three fields per corner (v, vt, vn): a positive index minus one (final), kNoIndex for a missing
  // vt or vn, or — for a relative (negative) index — the 1-based element it denotes counted from the
  // chunk's first element, which is zero or negative (two's complement) when it reaches into earlier
  // chunks. relative_fields marks those, a bit per field; the merge makes them final.
  BigVector<uint32_t> corners;
  std::vector<uint64_t> relative_fields;
  bool is_relative(uint64_t field) const {
    return field / 64 < relative_fields.size() && (relative_fields[field / 64] >> (field % 64) & 1);
  }
  uint32_t max_index[3] = {0, 0, 0};  // the largest positive v, vt, vn index written (1-based)
  BigVector<Face> faces;
  uint64_t triangles = 0;  // the n - 2 triangles of each face of n corners
  std::vector<StateChange> changes;
  std::vector<LocalMessage> material_names;   // usemtl names in order of first use, at that line
  std::vector<LocalMessage> material_libraries;  // the rest of each mtllib line

  uint64_t lines_skipped = 0;   // `l` statements
  uint64_t points_skipped = 0;  // `p` statements
  std::map<std::string, IgnoredKeyword> ignored;
  LocalMessage error;  // the first error, if any (a text): reading stops there
};

// The text cut into about `count` chunks of similar size (fewer when it has fewer line ends), each
// cut right after a line end that does not continue its line, so no statement is split.
std::vector<std::string_view> split_at_line_ends(std::string_view text, size_t count);

// Reads the chunk's text into *out. `first_in_file` lets a UTF-8 byte-order mark be skipped. The
// arrays are sized for the most `reserve_bytes` (at least the text's size) could hold, so chunks
// read in turn into one chunk's arrays all fit; arrays already that large are reused.
void parse_chunk(std::string_view text, bool first_in_file, ChunkData* out, size_t reserve_bytes = 0);

}  // namespace pfx_obj
