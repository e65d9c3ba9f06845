// One chunk of an OBJ file, parsed on its own: the chunks of a file are cut at line ends
// (obj_split.hpp) and parsed in parallel, then merged in file order (obj_import.cpp). A chunk
// cannot know what came before it, so everything that depends on earlier text is recorded in a
// form the merge can finish: relative indices, the material and smoothing group in force at the
// chunk's start, and line numbers counted from the chunk's first line.
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

// A message at a line counted from the chunk's first line (0-based), merged later into
// "FILE:LINE: text".
struct LocalMessage {
  uint64_t line = 0;
  std::string text;
};

struct Face {
  uint32_t corner_count;
  uint32_t line;  // chunk-local, 0-based
};

// A statement that changes what later faces use, recorded at the face it applies from.
struct StateChange {
  enum Kind : uint32_t { kMaterial = 0, kSmoothing = 1 };
  uint32_t first_face;  // chunk-local index of the first face it applies to
  Kind kind;
  uint32_t value;  // kMaterial: index into ChunkData::material_names; kSmoothing: group, 0 = off
};

// Statements counted and skipped with one warning per keyword (free-form geometry, unknown ones).
struct IgnoredKeyword {
  uint64_t first_line = 0;  // chunk-local
  uint64_t count = 0;
  bool valid_obj = false;   // a statement of the OBJ format pfx does not mesh, not an unknown one
};

struct ChunkData {
  uint64_t line_ends = 0;  // physical line ends in the chunk: the next chunk's first line follows

  // Vertex data in file order within the chunk.
  BigVector<float> positions;  // x y z per v
  BigVector<float> colors;     // r g b per v, or empty while no v of the chunk has a colour
  BigVector<float> texcoords;  // u v per vt
  BigVector<float> normals;    // x y z per vn
  uint32_t position_count() const { return static_cast<uint32_t>(positions.size() / 3); }

  // Face corners, three fields each (v, vt, vn): a positive index as written minus one (0-based,
  // final), kNoIndex for a missing vt or vn, or for a relative (negative) index the 1-based
  // position it denotes counted from the chunk's first element — which may be zero or negative
  // (stored two's complement), when it reaches back into earlier chunks. relative_fields marks
  // those, one bit per field; the resolve stage makes them final.
  BigVector<uint32_t> corners;
  std::vector<uint64_t> relative_fields;
  bool is_relative(uint64_t field) const {
    return field / 64 < relative_fields.size() && (relative_fields[field / 64] >> (field % 64) & 1);
  }
  uint32_t max_index[3] = {0, 0, 0};  // the largest positive v, vt, vn index written (1-based)
  BigVector<Face> faces;
  uint64_t face_count = 0;  // faces.size() once parsed (the import chunk by chunk may hand faces on)
  // Per material of the chunk — 0: the one in force at the chunk's start, i + 1: material_names[i]
  // — the triangles its faces make, and its first face (chunk-local), or kNoFace.
  static constexpr uint64_t kNoFace = ~uint64_t{0};
  std::vector<uint64_t> triangles_by_material{0};
  std::vector<uint64_t> first_face_by_material{kNoFace};
  std::vector<StateChange> changes;
  std::vector<std::string> material_names;  // usemtl names, in order of first use in the chunk
  std::vector<uint64_t> material_name_lines;  // the chunk-local line of each name's first usemtl

  struct MaterialLibrary {
    uint64_t line;
    std::string text;  // the rest of the mtllib line: one name, or several separated by blanks
  };
  std::vector<MaterialLibrary> material_libraries;

  uint64_t lines_skipped = 0;   // `l` statements
  uint64_t points_skipped = 0;  // `p` statements
  std::map<std::string, IgnoredKeyword> ignored;

  std::vector<LocalMessage> warnings;  // at most the first kMaxKeptWarnings
  uint64_t warning_total = 0;
  bool failed = false;
  LocalMessage error;  // the first error; parsing stops there
};

// Parses the chunk's text. `first_in_file` lets a UTF-8 byte-order mark be skipped. `plain_lines`:
// read the common line forms with the fast readers (obj_plain_lines.hpp); false only in tests that
// check both ways give the same result. The arrays are sized for the most `reserve_bytes` (at least
// the text's size) could hold, so that chunks parsed in turn into the same corner and face arrays
// (obj_streamed.cpp) all fit the first one's; *out's arrays are kept if large enough.
void parse_chunk(std::string_view text, bool first_in_file, bool plain_lines, ChunkData* out, size_t reserve_bytes = 0);

}  // namespace pfx_obj
