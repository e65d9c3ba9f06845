// The OBJ statement grammar, one chunk at a time, in one pass and one reader for every line.
//
// Bounds: each scan stops at a line end (LF or CR), and the text a Reader reads always ends with a
// line end that does not continue its line — a chunk's text up to its last such line end, then
// (when the chunk does not end with one) its last statement copied with a line end added. So no
// loop checks for the end of the text except the one over statements; the first malformed
// statement stops the chunk with a message naming the line and the token.
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "obj_chunk.hpp"
#include "obj_text.hpp"

namespace pfx_obj {

namespace {

// Statements of OBJ's free-form geometry (curves, surfaces) and rendering attributes: valid OBJ we
// do not mesh. They are counted and reported once per keyword.
bool is_unsupported_obj_keyword(std::string_view k) {
  static const std::string_view kKnown = " vp cstype deg bmat step curv curv2 surf parm trim hole scrv sp end con mg bevel "
                                         "c_interp d_interp lod shadow_obj trace_obj ctech stech maplib usemap call csh ";
  return kKnown.find(" " + std::string(k) + " ") != kKnown.npos;  // (a keyword holds no blank)
}

// The first byte of the line end whose last byte is text[i] (a CRLF is one line end).
size_t line_end_start(std::string_view text, size_t i) {
  return text[i] == '\n' && i > 0 && text[i - 1] == '\r' ? i - 1 : i;
}
// Whether that line end continues its line (a backslash right before it).
bool continues_line(std::string_view text, size_t i) {
  const size_t start = line_end_start(text, i);
  return start > 0 && text[start - 1] == '\\';
}

// Where the text's unterminated last statement starts: after its last line end that does not
// continue its line (0 when there is none; text.size() when that is its last byte).
size_t unterminated_tail(std::string_view text) {
  for (size_t i = text.size(); i-- > 0;) {
    if (!is_line_end(text[i])) continue;
    if (!continues_line(text, i)) return i + 1;
    i = line_end_start(text, i);  // a continued line: the statement started before it
  }
  return 0;
}

}  // namespace

std::vector<std::string_view> split_at_line_ends(std::string_view text, size_t count) {
  std::vector<std::string_view> chunks;
  size_t begin = 0;
  for (size_t k = 1; k < count; ++k) {
    // After the first line end from the k-th share on that ends its statement (a CRLF whole).
    size_t i = std::max(begin, k * (text.size() / count));
    while (i < text.size() && (!is_line_end(text[i]) || continues_line(text, i) ||
                               (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n')))
      ++i;
    if (i + 1 >= text.size()) break;
    chunks.push_back(text.substr(begin, i + 1 - begin));
    begin = i + 1;
  }
  chunks.push_back(text.substr(begin));
  return chunks;
}

namespace {

class Reader : LineCursor {
 public:
  Reader(ChunkData* out, size_t reserve_bytes) : LineCursor{nullptr, nullptr}, out_(out) { reserve_upper_bounds(reserve_bytes); }

  // Reads [p, end); *(end - 1) is a line end that does not continue its line, and *end is readable
  // unless that line end is the last byte of the file. False on an error (recorded).
  bool read(const char* begin, const char* stop) {
    p = begin;
    end = stop;
    while (p < end) {
      line_ = line_ends;
      skip_blanks();
      if (!at_statement_end() && !keyword_statement(token())) return false;
      skip_statement();
    }
    return true;
  }

  void finish() {
    out_->positions.resize(static_cast<size_t>(position_at_ - out_->positions.data()));
    out_->texcoords.resize(static_cast<size_t>(texcoord_at_ - out_->texcoords.data()));
    out_->normals.resize(static_cast<size_t>(normal_at_ - out_->normals.data()));
    out_->corners.resize(static_cast<size_t>(corner_at_ - out_->corners.data()));
    out_->faces.resize(faces_so_far());
    out_->line_ends = line_ends;
  }

 private:
  // The most elements `bytes` of text can hold (the shortest statements: "v 0 0 0\n", "vt 0\n",
  // "vn 0 0 0\n", a corner "1 ", "f 1 2 3\n"), made room for up front without touching the memory
  // (BigVector leaves elements uninitialised; only pages written become resident): elements are
  // then written through pointers, with no capacity check per element, and trimmed at the end.
  void reserve_upper_bounds(size_t bytes) {
    out_->positions.resize(3 * (bytes / 8 + 1));
    out_->texcoords.resize(2 * (bytes / 5 + 1));
    out_->normals.resize(3 * (bytes / 9 + 1));
    out_->corners.resize(3 * (bytes / 2 + 1));
    out_->faces.resize(bytes / 8 + 1);
    position_at_ = out_->positions.data();
    texcoord_at_ = out_->texcoords.data();
    normal_at_ = out_->normals.data();
    corner_at_ = out_->corners.data();
    face_at_ = out_->faces.data();
  }

  uint32_t positions_so_far() const { return static_cast<uint32_t>((position_at_ - out_->positions.data()) / 3); }
  uint32_t texcoords_so_far() const { return static_cast<uint32_t>((texcoord_at_ - out_->texcoords.data()) / 2); }
  size_t faces_so_far() const { return static_cast<size_t>(face_at_ - out_->faces.data()); }
  uint32_t normals_so_far() const { return static_cast<uint32_t>((normal_at_ - out_->normals.data()) / 3); }

  std::string_view token_at(const char* start) { p = start; return token(); }
  bool fail(std::string text) { out_->error = {line_, std::move(text)}; return false; }

  // --- Statements ----------------------------------------------------------------------------
  bool keyword_statement(std::string_view keyword) {
    if (keyword == "f") return face();
    if (keyword == "v") return vertex();
    if (keyword == "vt") return texcoord();
    if (keyword == "vn") return normal();
    if (keyword == "usemtl") return use_material();
    if (keyword == "mtllib") return material_library();
    if (keyword == "s") return smoothing();
    if (keyword == "fo") return face();
    if (keyword == "l" || keyword == "p") {  // lines and points are counted, not meshed
      ++(keyword == "l" ? out_->lines_skipped : out_->points_skipped);
      return true;
    }
    return keyword == "o" || keyword == "g" || other(keyword);  // o, g: names only
  }

  bool other(std::string_view keyword) {
    const auto control = std::find_if(keyword.begin(), keyword.end(), [](char c) { return uint8_t(c) < 0x20 || c == 0x7f; });
    if (control != keyword.end()) {
      const unsigned byte = static_cast<unsigned char>(*control);
      return fail(std::string("binary data (byte 0x") + "0123456789abcdef"[byte >> 4] + "0123456789abcdef"[byte & 15] +
                  " in a keyword): not an OBJ text file");
    }
    IgnoredKeyword& ignored = out_->ignored[std::string(keyword.substr(0, 40))];
    if (ignored.count++ == 0) {
      ignored.first_line = line_;
      ignored.valid_obj = is_unsupported_obj_keyword(keyword);
    }
    return true;
  }

  // A number ending where its token ends, finite as a float.
  [[gnu::always_inline]] bool number(double* out) {
    const char* q = parse_number(p, out);
    if (!q || !token_end(q) || !std::isfinite(static_cast<float>(*out))) return false;
    p = q;
    return true;
  }

  // Up to `capacity` numbers to the end of the statement; false on a malformed one (recorded).
  [[gnu::always_inline]] bool numbers(const char* keyword, double* values, int capacity, int* count) {
    for (*count = 0;; ++*count) {
      skip_blanks();
      if (at_statement_end()) return true;
      const char* start = p;
      if (*count < capacity && number(&values[*count])) continue;
      return bad_number(keyword, start, *count == capacity ? capacity : -1);
    }
  }

  // The message for the token at start that is not a number (or one too many: capacity >= 0).
  [[gnu::cold, gnu::noinline]] bool bad_number(const char* keyword, const char* start, int capacity) {
    const std::string_view text = token_at(start);
    const std::string what = std::string(keyword) + ": ";
    double value;
    if (capacity >= 0) return fail(what + "too many numbers (at most " + std::to_string(capacity) + ")");
    if (is_non_finite_word(text)) return fail(what + "'" + printable(text) + "' is not a finite number");
    if (!parse_double(text, &value)) return fail(what + "malformed number '" + printable(text) + "'");
    return fail(what + "'" + printable(text) + "' is out of the 32-bit float range");
  }

  bool vertex() {
    double values[7];
    int count;
    if (!numbers("v", values, 7, &count)) return false;
    if (count != 3 && count != 4 && count != 6)
      return fail("v: expected x y z, x y z w or x y z r g b (got " + std::to_string(count) + " numbers)");
    for (int i = 0; i < 3; ++i) *position_at_++ = static_cast<float>(values[i]);
    if (count == 6) {
      // The chunk's first coloured v: the ones before it are white.
      if (out_->colors.empty()) out_->colors.assign(3 * size_t{positions_so_far() - 1}, 1.0f);
      for (int i = 3; i < 6; ++i) out_->colors.push_back(static_cast<float>(values[i]));
    } else if (!out_->colors.empty()) {
      out_->colors.insert(out_->colors.end(), 3, 1.0f);
    }
    return true;
  }

  bool texcoord() {
    double values[3];
    int count;
    if (!numbers("vt", values, 3, &count)) return false;
    if (count == 0) return fail("vt: expected u [v [w]] (got no number)");
    *texcoord_at_++ = static_cast<float>(values[0]);
    *texcoord_at_++ = count > 1 ? static_cast<float>(values[1]) : 0.0f;
    return true;
  }

  bool normal() {
    double values[3];
    int count;
    if (!numbers("vn", values, 3, &count)) return false;
    if (count != 3) return fail("vn: expected x y z (got " + std::to_string(count) + " numbers)");
    for (int i = 0; i < 3; ++i) *normal_at_++ = static_cast<float>(values[i]);
    return true;
  }

  // [+-]digits at the cursor; false when there are no digits. More than 18 digits: *too_long.
  bool read_index(int64_t* value, bool* too_long) {
    const char* q = p;
    const bool negative = *q == '-';
    if (*q == '-' || *q == '+') ++q;
    const char* digits = q;
    uint64_t n = 0;  // wraps past 19 digits, when it is not used
    uint32_t d;
    for (; digit(*q, &d); ++q) n = n * 10 + d;
    if (q == digits) return false;
    *too_long = q - digits > 18;
    *value = *too_long ? 0 : negative ? -static_cast<int64_t>(n) : static_cast<int64_t>(n);
    p = q;
    return true;
  }

  [[gnu::cold, gnu::noinline]] bool malformed_corner(const char* start) {
    return fail("f: malformed corner '" + printable(token_at(start)) + "' (expected v, v/vt, v//vn or v/vt/vn)");
  }

  // One index of a corner (kind 0, 1, 2: v, vt, vn) read from `field`; `count`: the chunk's
  // elements of its kind so far.
  bool store_index(int64_t value, bool too_long, const char* field, const char* corner, int kind, uint32_t count,
                   uint32_t* max_index) {
    if (value > 0 && !too_long && value <= kMaxWrittenIndex) {  // the common case
      max_index[kind] = std::max(max_index[kind], static_cast<uint32_t>(value));
      *corner_at_++ = static_cast<uint32_t>(value - 1);
      return true;
    }
    if (value < 0 && !too_long && value >= -kMaxWrittenIndex) {  // relative: see ChunkData::corners
      const size_t at = static_cast<size_t>(corner_at_ - out_->corners.data());
      if (out_->relative_fields.size() <= at / 64) out_->relative_fields.resize(at / 64 + 1 + at / 128, 0);
      out_->relative_fields[at / 64] |= uint64_t{1} << (at % 64);
      *corner_at_++ = static_cast<uint32_t>(int64_t{count} + value + 1);
      return true;
    }
    return bad_index(value == 0 && !too_long, field, corner, kind);
  }

  // The message for an index 0 (`zero`) or one too large.
  [[gnu::cold, gnu::noinline]] bool bad_index(bool zero, const char* field, const char* corner, int kind) {
    static const char* const kKinds[] = {"v", "vt", "vn"};
    if (zero)
      return fail("f: " + std::string(kKinds[kind]) + " index 0 in '" + printable(token_at(corner)) +
                  "' (OBJ indices start at 1)");
    return fail("f: index '" + printable({field, static_cast<size_t>(p - field)}) + "' is too large");
  }

  // v, v/vt, v//vn or v/vt/vn: each field checked and stored as it is read. max_index: the face's
  // own copy of the chunk's (a local: stores of corners cannot change it, so it stays in registers).
  bool corner(const uint32_t counts[3], uint32_t* max_index) {
    const char* start = p;
#pragma GCC unroll 3  // unrolled, each field's checks of `kind` fold away
    for (int kind = 0; kind < 3; ++kind) {
      if (kind > 0 && *p++ != '/') {  // v or v/vt: the rest are missing
        for (--p; kind < 3; ++kind) *corner_at_++ = kNoIndex;
        return true;
      }
      if (kind == 1 && *p == '/') {  // v//vn
        *corner_at_++ = kNoIndex;
        continue;
      }
      const char* field = p;
      int64_t value;
      bool too_long;
      if (!read_index(&value, &too_long) || (!(kind < 2 && *p == '/') && !token_end(p))) return malformed_corner(start);
      if (!store_index(value, too_long, field, start, kind, counts[kind], max_index)) return false;
    }
    return true;
  }

  bool face() {
    const uint32_t counts[3] = {positions_so_far(), texcoords_so_far(), normals_so_far()};
    uint32_t corners = 0, max_index[3] = {out_->max_index[0], out_->max_index[1], out_->max_index[2]};
    for (;; ++corners) {
      skip_blanks();
      if (at_statement_end()) break;
      if (!corner(counts, max_index)) return false;
    }
    std::copy(max_index, max_index + 3, out_->max_index);
    if (corners < 3) return fail("f: needs at least 3 corners (got " + std::to_string(corners) + ")");
    out_->triangles += corners - 2;
    *face_at_++ = {corners, static_cast<uint32_t>(line_)};
    return true;
  }

  bool use_material() {
    skip_blanks();
    std::string name = rest_of_line();
    if (name.empty()) return fail("usemtl: needs a material name");
    // A map, not a scan: some exporters write a usemtl before every face, over many materials.
    auto [it, fresh] = material_index_.emplace(name, static_cast<uint32_t>(out_->material_names.size()));
    if (fresh) out_->material_names.push_back({line_, std::move(name)});
    record_change(StateChange::kMaterial, it->second);
    return true;
  }

  bool material_library() {
    skip_blanks();
    std::string text = rest_of_line();
    if (text.empty()) return fail("mtllib: needs a file name");
    out_->material_libraries.push_back({line_, std::move(text)});
    return true;
  }

  bool smoothing() {
    skip_blanks();
    const char* start = p;
    const std::string_view token = this->token();
    p = start;  // the token again, as a number
    int64_t value = 0;
    bool too_long = false;
    const bool number = read_index(&value, &too_long) && p == start + token.size() && !too_long;
    uint32_t group;
    if (token == "off" || token == "Off" || token == "OFF") group = 0;
    else if (number && value >= 0 && value <= kMaxWrittenIndex) group = static_cast<uint32_t>(value);
    else if (token.empty()) return fail("s: needs a group number or off");
    else return fail("s: '" + printable(token) + "' is not a smoothing group (a number 0 to 2147483647, or off)");
    record_change(StateChange::kSmoothing, group);
    return true;
  }

  void record_change(StateChange::Kind kind, uint32_t value) {
    const uint32_t face = static_cast<uint32_t>(faces_so_far());
    // Two changes of one kind before the same face: the later one is in force.
    for (auto it = out_->changes.rbegin(); it != out_->changes.rend() && it->first_face == face; ++it)
      if (it->kind == kind) {
        it->value = value;
        return;
      }
    out_->changes.push_back({face, kind, value, out_->triangles});
  }

  ChunkData* out_;
  uint64_t line_ = 0;  // the statement's line (chunk-local)
  float* position_at_ = nullptr;       // where the next v, vt, vn and corner field go
  float* texcoord_at_ = nullptr;
  float* normal_at_ = nullptr;
  uint32_t* corner_at_ = nullptr;
  Face* face_at_ = nullptr;
  std::unordered_map<std::string, uint32_t> material_index_;  // usemtl name -> material_names index
};

}  // namespace

void parse_chunk(std::string_view text, bool first_in_file, ChunkData* out, size_t reserve_bytes) {
  if (first_in_file && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  out->error = {};
  Reader reader(out, std::max(reserve_bytes, text.size()));
  const size_t tail = unterminated_tail(text);
  if (reader.read(text.data(), text.data() + tail) && tail < text.size()) {
    // The last statement has no line end: read from a copy with one, and one more for the reads
    // just past a continuation that ends the file.
    const std::string last = std::string(text.substr(tail)) + "\n\n";
    reader.read(last.data(), last.data() + last.size() - 1);
  }
  reader.finish();
}

}  // namespace pfx_obj
