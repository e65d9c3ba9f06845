// The OBJ statement grammar, one chunk at a time. Every read is bounded by the chunk's end; the
// first malformed statement stops the chunk with a message naming the line and the token.
#include "obj_chunk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "obj_plain_lines.hpp"
#include "obj_text.hpp"

namespace pfx_obj {

namespace {

constexpr size_t kMaxKeptWarnings = 100;

// Statements of OBJ's free-form geometry (curves, surfaces) and rendering attributes: valid OBJ
// we do not mesh. They are counted and reported once per keyword.
bool is_unsupported_obj_keyword(std::string_view k) {
  static const char* const kKnown[] = {"vp",   "cstype", "deg",     "bmat",     "step",     "curv",
                                       "curv2", "surf",  "parm",    "trim",     "hole",     "scrv",
                                       "sp",   "end",    "con",     "mg",       "bevel",    "c_interp",
                                       "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech",
                                       "maplib", "usemap", "call",  "csh"};
  for (const char* known : kKnown)
    if (k == known) return true;
  return false;
}

class ChunkParser {
 public:
  ChunkParser(std::string_view text, ChunkData* out, bool plain_lines, size_t reserve_bytes)
      : cursor_{text.data(), text.data() + text.size()}, out_(out), reserve_bytes_(std::max(reserve_bytes, text.size())) {
    // Plain lines are read by the fast readers up to kPlainLineMargin bytes before the end.
    if (plain_lines && text.size() > static_cast<size_t>(kPlainLineMargin)) plain_limit_ = cursor_.end - kPlainLineMargin;
  }

  void run(bool first_in_file) {
    if (first_in_file && cursor_.end - cursor_.p >= 3 && static_cast<unsigned char>(cursor_.p[0]) == 0xEF &&
        static_cast<unsigned char>(cursor_.p[1]) == 0xBB && static_cast<unsigned char>(cursor_.p[2]) == 0xBF)
      cursor_.p += 3;
    reserve_upper_bounds(reserve_bytes_);
    while (!cursor_.at_end()) {
      line_ = cursor_.line_ends;
      if (!statement()) {
        out_->failed = true;
        break;
      }
    }
    out_->positions.resize(static_cast<size_t>(position_at_ - out_->positions.data()));
    out_->texcoords.resize(static_cast<size_t>(texcoord_at_ - out_->texcoords.data()));
    out_->normals.resize(static_cast<size_t>(normal_at_ - out_->normals.data()));
    out_->corners.resize(static_cast<size_t>(corner_at_ - out_->corners.data()));
    out_->line_ends = cursor_.line_ends;
    out_->face_count = out_->faces.size();
  }

 private:
  // The most elements `bytes` of text can hold (the shortest statements: "v 0 0 0\n", "vt 0\n",
  // "vn 0 0 0\n", a corner "1 ", "f 1 2 3\n"), made room for up front: growing by copying cost
  // more than the parse. Vertex data and corners are written through pointers (no capacity check
  // per element) into arrays sized without touching them (BigVector does not initialise, and only
  // the pages written become resident), trimmed at the end.
  void reserve_upper_bounds(size_t bytes) {
    out_->positions.resize(3 * (bytes / 8 + 1));
    out_->texcoords.resize(2 * (bytes / 5 + 1));
    out_->normals.resize(3 * (bytes / 9 + 1));
    out_->corners.resize(3 * (bytes / 2 + 1));
    position_at_ = out_->positions.data();
    texcoord_at_ = out_->texcoords.data();
    normal_at_ = out_->normals.data();
    corner_at_ = out_->corners.data();
    out_->faces.clear();
    out_->faces.reserve(bytes / 8 + 1);
  }

  uint32_t positions_so_far() const { return static_cast<uint32_t>((position_at_ - out_->positions.data()) / 3); }
  uint32_t texcoords_so_far() const { return static_cast<uint32_t>((texcoord_at_ - out_->texcoords.data()) / 2); }
  uint32_t normals_so_far() const { return static_cast<uint32_t>((normal_at_ - out_->normals.data()) / 3); }

  bool fail(std::string text) {
    out_->error = {line_, std::move(text)};
    return false;
  }

  void warn(std::string text) {
    ++out_->warning_total;
    if (out_->warnings.size() < kMaxKeptWarnings) out_->warnings.push_back({line_, std::move(text)});
  }

  // One logical line. Returns false on an error (already recorded).
  bool statement() {
    if (cursor_.p < plain_limit_ && plain_statement()) return true;
    cursor_.skip_blanks();
    if (cursor_.at_statement_end()) {
      cursor_.skip_statement();
      return true;
    }
    std::string_view keyword = cursor_.token();
    bool ok;
    if (keyword == "v") ok = vertex();
    else if (keyword == "vt") ok = texcoord();
    else if (keyword == "vn") ok = normal();
    else if (keyword == "f" || keyword == "fo") ok = face();
    else if (keyword == "usemtl") ok = use_material();
    else if (keyword == "mtllib") ok = material_library();
    else if (keyword == "s") ok = smoothing();
    else if (keyword == "o" || keyword == "g") ok = true;  // names only; sub-meshes follow materials
    else if (keyword == "l") { ++out_->lines_skipped; ok = true; }
    else if (keyword == "p") { ++out_->points_skipped; ok = true; }
    else ok = other(keyword);
    if (!ok) return false;
    cursor_.skip_statement();
    return true;
  }

  // The common forms (obj_plain_lines.hpp); false when the line is left to the general grammar,
  // with nothing recorded.
  bool plain_statement() {
    const char* p = cursor_.p;
    const char* next = nullptr;
    if (p[0] == 'f' && plain::blank(p[1])) {
      uint32_t corners;
      if (!(next = read_plain_face(p + 2, plain_limit_, corner_at_, &corners, out_->max_index))) return false;
      corner_at_ += 3 * corners;
      add_face(corners);
    } else if (p[0] == 'v') {
      double values[7];
      int count;
      if (plain::blank(p[1])) {
        if (!(next = read_plain_numbers(p + 2, plain_limit_, values, 7, &count)) || !vertex_count_ok(count)) return false;
        store_vertex(values, count);
      } else if (p[1] == 't' && plain::blank(p[2])) {
        if (!(next = read_plain_numbers(p + 3, plain_limit_, values, 3, &count)) || count == 0) return false;
        store_texcoord(values, count);
      } else if (p[1] == 'n' && plain::blank(p[2])) {
        if (!(next = read_plain_numbers(p + 3, plain_limit_, values, 3, &count)) || count != 3) return false;
        store_normal(values);
      } else {
        return false;
      }
    } else {
      return false;
    }
    cursor_.p = next;
    ++cursor_.line_ends;
    return true;
  }

  bool other(std::string_view keyword) {
    for (char c : keyword) {
      unsigned char byte = static_cast<unsigned char>(c);
      if (byte < 0x20 || byte == 0x7f)
        return fail("binary data (byte 0x" + hex(byte) + " in a keyword): not an OBJ text file");
    }
    std::string key(keyword.substr(0, 40));
    IgnoredKeyword& ignored = out_->ignored[key];
    if (ignored.count++ == 0) {
      ignored.first_line = line_;
      ignored.valid_obj = is_unsupported_obj_keyword(keyword);
    }
    return true;
  }

  static std::string hex(unsigned char byte) {
    const char* digits = "0123456789abcdef";
    return {digits[byte >> 4], digits[byte & 15]};
  }

  // Reads up to `capacity` numbers to the end of the statement; false on a malformed one.
  bool numbers(const char* keyword, double* values, int capacity, int* count) {
    *count = 0;
    for (;;) {
      cursor_.skip_blanks();
      if (cursor_.at_statement_end()) return true;
      double value;
      if (*count < capacity) {
        // The common case in one pass: a number ending where its token ends.
        const char* after = parse_number_prefix(cursor_.p, cursor_.end, &value);
        if (after) {
          const char* save = cursor_.p;
          cursor_.p = after;
          if (cursor_.at_token_end() && std::isfinite(static_cast<float>(value))) {
            values[(*count)++] = value;
            continue;
          }
          cursor_.p = save;
        }
      }
      std::string_view token = cursor_.token();
      if (*count == capacity) return fail(std::string(keyword) + ": too many numbers (at most " +
                                          std::to_string(capacity) + ")");
      if (!parse_double(token, &value)) {
        if (is_non_finite_word(token))
          return fail(std::string(keyword) + ": '" + printable(token) + "' is not a finite number");
        return fail(std::string(keyword) + ": malformed number '" + printable(token) + "'");
      }
      if (!std::isfinite(static_cast<float>(value)))
        return fail(std::string(keyword) + ": '" + printable(token) + "' is out of the 32-bit float range");
      values[(*count)++] = value;
    }
  }

  static bool vertex_count_ok(int count) { return count == 3 || count == 4 || count == 6; }

  bool vertex() {
    double values[7];
    int count;
    if (!numbers("v", values, 7, &count)) return false;
    if (!vertex_count_ok(count))
      return fail("v: expected x y z, x y z w or x y z r g b (got " + std::to_string(count) + " numbers)");
    store_vertex(values, count);
    return true;
  }

  void store_vertex(const double* values, int count) {
    for (int i = 0; i < 3; ++i) *position_at_++ = static_cast<float>(values[i]);
    if (count == 6) {
      // The first coloured v of the chunk: earlier ones are white.
      if (out_->colors.empty()) out_->colors.assign(3 * size_t{positions_so_far() - 1}, 1.0f);
      for (int i = 3; i < 6; ++i) out_->colors.push_back(static_cast<float>(values[i]));
    } else if (!out_->colors.empty()) {
      out_->colors.insert(out_->colors.end(), 3, 1.0f);
    }
  }

  bool texcoord() {
    double values[3];
    int count;
    if (!numbers("vt", values, 3, &count)) return false;
    if (count == 0) return fail("vt: expected u [v [w]] (got no number)");
    store_texcoord(values, count);
    return true;
  }

  void store_texcoord(const double* values, int count) {
    *texcoord_at_++ = static_cast<float>(values[0]);
    *texcoord_at_++ = count > 1 ? static_cast<float>(values[1]) : 0.0f;
  }

  bool normal() {
    double values[3];
    int count;
    if (!numbers("vn", values, 3, &count)) return false;
    if (count != 3) return fail("vn: expected x y z (got " + std::to_string(count) + " numbers)");
    store_normal(values);
    return true;
  }

  void store_normal(const double* values) {
    for (int i = 0; i < 3; ++i) *normal_at_++ = static_cast<float>(values[i]);
  }

  void mark_relative(size_t field) {
    size_t word = field / 64;
    if (out_->relative_fields.size() <= word) out_->relative_fields.resize(word + 1 + word / 2, 0);
    out_->relative_fields[word] |= uint64_t{1} << (field % 64);
  }

  // Reads [+-]digits at the cursor into *value; false when there are no digits. More than 18
  // digits set *too_long (the value is then meaningless).
  bool read_index(int64_t* value, bool* too_long) {
    const char* p = cursor_.p;
    const char* end = cursor_.end;
    bool negative = false;
    if (p < end && (*p == '+' || *p == '-')) negative = *p++ == '-';
    const char* digits = p;
    int64_t n = 0;
    // 18 digits fit in an int64: a bound computed once, not checked per digit.
    const char* fits = p + std::min<std::ptrdiff_t>(end - p, 18);
    while (p < fits && static_cast<unsigned char>(*p - '0') < 10) n = n * 10 + (*p++ - '0');
    while (p < end && static_cast<unsigned char>(*p - '0') < 10) ++p;
    if (p == digits) return false;
    *too_long = p - digits > 18;
    *value = negative ? -n : n;
    cursor_.p = p;
    return true;
  }

  // The whole corner token starting at `start`, for messages.
  std::string_view corner_text(const char* start) {
    cursor_.p = start;
    return cursor_.token();
  }

  bool malformed_corner(const char* start) {
    return fail("f: malformed corner '" + printable(corner_text(start)) + "' (expected v, v/vt, v//vn or v/vt/vn)");
  }

  // Stores one index of a corner (kind 0, 1, 2: v, vt, vn); `count` is how many elements of its kind
  // the chunk has so far.
  bool store_index(int64_t value, bool too_long, const char* field_start, const char* corner_start, int kind,
                   uint64_t count) {
    static const char* const kKinds[] = {"v", "vt", "vn"};
    if (too_long || value > kMaxWrittenIndex || value < -kMaxWrittenIndex) {
      const std::string_view field(field_start, static_cast<size_t>(cursor_.p - field_start));
      return fail("f: index '" + printable(field) + "' is too large");
    }
    if (value == 0)
      return fail("f: " + std::string(kKinds[kind]) + " index 0 in '" + printable(corner_text(corner_start)) +
                  "' (OBJ indices start at 1)");
    if (value > 0) {
      out_->max_index[kind] = std::max(out_->max_index[kind], static_cast<uint32_t>(value));
      *corner_at_++ = static_cast<uint32_t>(value - 1);
    } else {
      mark_relative(static_cast<size_t>(corner_at_ - out_->corners.data()));
      *corner_at_++ = static_cast<uint32_t>(static_cast<int64_t>(count) + value + 1);
    }
    return true;
  }

  // v, v/vt, v//vn or v/vt/vn, read in one pass.
  bool corner(uint32_t texcoord_count, uint32_t normal_count) {
    const char* start = cursor_.p;
    int64_t value;
    bool too_long;
    const char* field = cursor_.p;
    if (!read_index(&value, &too_long)) return malformed_corner(start);
    if (!cursor_.at_token_end() && *cursor_.p != '/') return malformed_corner(start);
    if (!store_index(value, too_long, field, start, 0, positions_so_far())) return false;
    bool has_vt = false, has_vn = false;
    if (!cursor_.at_token_end()) {  // at the first '/'
      ++cursor_.p;
      field = cursor_.p;
      if (cursor_.p < cursor_.end && *cursor_.p == '/') {  // v//vn
        ++cursor_.p;
        field = cursor_.p;
        if (!read_index(&value, &too_long) || !cursor_.at_token_end()) return malformed_corner(start);
        *corner_at_++ = kNoIndex;
        if (!store_index(value, too_long, field, start, 2, normal_count)) return false;
        return true;
      }
      if (!read_index(&value, &too_long)) return malformed_corner(start);
      if (!cursor_.at_token_end() && *cursor_.p != '/') return malformed_corner(start);
      if (!store_index(value, too_long, field, start, 1, texcoord_count)) return false;
      has_vt = true;
      if (!cursor_.at_token_end()) {  // at the second '/'
        ++cursor_.p;
        field = cursor_.p;
        if (!read_index(&value, &too_long) || !cursor_.at_token_end()) return malformed_corner(start);
        if (!store_index(value, too_long, field, start, 2, normal_count)) return false;
        has_vn = true;
      }
    }
    if (!has_vt) *corner_at_++ = kNoIndex;
    if (!has_vn) *corner_at_++ = kNoIndex;
    return true;
  }

  bool face() {
    const uint32_t texcoord_count = texcoords_so_far();
    const uint32_t normal_count = normals_so_far();
    uint32_t corners = 0;
    for (;;) {
      cursor_.skip_blanks();
      if (cursor_.at_statement_end()) break;
      if (!corner(texcoord_count, normal_count)) return false;
      ++corners;
    }
    if (corners < 3) return fail("f: needs at least 3 corners (got " + std::to_string(corners) + ")");
    add_face(corners);
    return true;
  }

  void add_face(uint32_t corners) {
    out_->triangles_by_material[material_] += corners - 2;
    if (out_->first_face_by_material[material_] == ChunkData::kNoFace) out_->first_face_by_material[material_] = out_->faces.size();
    out_->faces.push_back({corners, static_cast<uint32_t>(line_)});
  }

  bool use_material() {
    cursor_.skip_blanks();
    std::string name = cursor_.rest_of_line();
    if (name.empty()) return fail("usemtl: needs a material name");
    // A map, not a scan: some exporters write a usemtl before every face, over many materials.
    auto [it, fresh] = material_index_.emplace(name, static_cast<uint32_t>(out_->material_names.size()));
    if (fresh) {
      out_->material_names.push_back(name);
      out_->material_name_lines.push_back(line_);
      out_->triangles_by_material.push_back(0);
      out_->first_face_by_material.push_back(ChunkData::kNoFace);
    }
    material_ = it->second + 1;
    record_change(StateChange::kMaterial, it->second);
    return true;
  }

  bool material_library() {
    cursor_.skip_blanks();
    std::string text = cursor_.rest_of_line();
    if (text.empty()) return fail("mtllib: needs a file name");
    out_->material_libraries.push_back({line_, std::move(text)});
    return true;
  }

  bool smoothing() {
    cursor_.skip_blanks();
    std::string_view token = cursor_.token();
    uint32_t group;
    int64_t value;
    if (token == "off" || token == "Off" || token == "OFF") group = 0;
    else if (parse_integer(token, &value) && value >= 0 && value <= kMaxWrittenIndex) group = static_cast<uint32_t>(value);
    else if (token.empty()) return fail("s: needs a group number or off");
    else return fail("s: '" + printable(token) + "' is not a smoothing group (a number 0 to 2147483647, or off)");
    record_change(StateChange::kSmoothing, group);
    return true;
  }

  void record_change(StateChange::Kind kind, uint32_t value) {
    const uint32_t face = static_cast<uint32_t>(out_->faces.size());
    // Two changes of one kind before the same face: the later one is the one in force.
    for (auto it = out_->changes.rbegin(); it != out_->changes.rend() && it->first_face == face; ++it)
      if (it->kind == kind) {
        it->value = value;
        return;
      }
    out_->changes.push_back({face, kind, value});
  }

  Cursor cursor_;
  ChunkData* out_;
  size_t reserve_bytes_;
  uint64_t line_ = 0;
  float* position_at_ = nullptr;  // where the next v, vt, vn, corner field goes in out_'s arrays
  float* texcoord_at_ = nullptr;
  float* normal_at_ = nullptr;
  uint32_t* corner_at_ = nullptr;
  uint32_t material_ = 0;  // the material of the next face: 0, or 1 + its index in material_names
  const char* plain_limit_ = nullptr;  // plain lines start before this (null: the general grammar only)
  std::unordered_map<std::string, uint32_t> material_index_;  // usemtl name -> material_names index
};

}  // namespace

void parse_chunk(std::string_view text, bool first_in_file, bool plain_lines, ChunkData* out, size_t reserve_bytes) {
  ChunkParser(text, out, plain_lines, reserve_bytes).run(first_in_file);
}

}  // namespace pfx_obj
