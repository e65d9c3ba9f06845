// The OBJ statement grammar, one chunk at a time. Every read is bounded by the chunk's end; the
// first malformed statement stops the chunk with a message naming the line and the token.
#include "obj_chunk.hpp"

#include <cmath>
#include <limits>

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
  ChunkParser(std::string_view text, ChunkData* out) : cursor_{text.data(), text.data() + text.size()}, out_(out) {}

  void run(bool first_in_file) {
    if (first_in_file && cursor_.end - cursor_.p >= 3 && static_cast<unsigned char>(cursor_.p[0]) == 0xEF &&
        static_cast<unsigned char>(cursor_.p[1]) == 0xBB && static_cast<unsigned char>(cursor_.p[2]) == 0xBF)
      cursor_.p += 3;
    while (!cursor_.at_end()) {
      line_ = cursor_.line_ends;
      if (!statement()) {
        out_->failed = true;
        return;
      }
    }
    out_->line_ends = cursor_.line_ends;
  }

 private:
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
      std::string_view token = cursor_.token();
      if (*count == capacity) return fail(std::string(keyword) + ": too many numbers (at most " +
                                          std::to_string(capacity) + ")");
      double value;
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

  bool vertex() {
    double values[7];
    int count;
    if (!numbers("v", values, 7, &count)) return false;
    if (count != 3 && count != 4 && count != 6)
      return fail("v: expected x y z, x y z w or x y z r g b (got " + std::to_string(count) + " numbers)");
    for (int i = 0; i < 3; ++i) out_->positions.push_back(static_cast<float>(values[i]));
    if (count == 6) {
      // The first coloured v of the chunk: earlier ones are white.
      if (out_->colors.empty()) out_->colors.assign(out_->positions.size() - 3, 1.0f);
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
    out_->texcoords.push_back(static_cast<float>(values[0]));
    out_->texcoords.push_back(count > 1 ? static_cast<float>(values[1]) : 0.0f);
    return true;
  }

  bool normal() {
    double values[3];
    int count;
    if (!numbers("vn", values, 3, &count)) return false;
    if (count != 3) return fail("vn: expected x y z (got " + std::to_string(count) + " numbers)");
    for (int i = 0; i < 3; ++i) out_->normals.push_back(static_cast<float>(values[i]));
    return true;
  }

  void mark_relative(size_t field) {
    size_t word = field / 64;
    if (out_->relative_fields.size() <= word) out_->relative_fields.resize(word + 1 + word / 2, 0);
    out_->relative_fields[word] |= uint64_t{1} << (field % 64);
  }

  // One index of a corner; `count` is how many elements of its kind the chunk has so far.
  bool index(std::string_view text, std::string_view corner, const char* what, uint64_t count) {
    int64_t value;
    if (!parse_integer(text, &value)) {
      if (text.size() > 1 && text.find_first_not_of("+-0123456789") == std::string_view::npos)
        return fail("f: index '" + printable(text) + "' is too large");
      return fail("f: malformed corner '" + printable(corner) + "' (expected v, v/vt, v//vn or v/vt/vn)");
    }
    if (value == 0) return fail("f: " + std::string(what) + " index 0 in '" + printable(corner) + "' (OBJ indices start at 1)");
    if (value > kMaxWrittenIndex || value < -kMaxWrittenIndex)
      return fail("f: index '" + printable(text) + "' is too large");
    if (value > 0) {
      out_->corners.push_back(static_cast<uint32_t>(value));
    } else {
      mark_relative(out_->corners.size());
      out_->corners.push_back(static_cast<uint32_t>(static_cast<int64_t>(count) + value + 1));
    }
    return true;
  }

  bool face() {
    const uint32_t texcoord_count = static_cast<uint32_t>(out_->texcoords.size() / 2);
    const uint32_t normal_count = static_cast<uint32_t>(out_->normals.size() / 3);
    uint32_t corners = 0;
    for (;;) {
      cursor_.skip_blanks();
      if (cursor_.at_statement_end()) break;
      std::string_view corner = cursor_.token();
      // Split at '/': v, v/vt, v//vn or v/vt/vn; anything else is malformed.
      size_t first = corner.find('/');
      std::string_view v = corner.substr(0, first), vt, vn;
      bool malformed = v.empty();
      if (first != std::string_view::npos) {
        size_t second = corner.find('/', first + 1);
        vt = corner.substr(first + 1, second == std::string_view::npos ? std::string_view::npos : second - first - 1);
        if (second == std::string_view::npos) malformed |= vt.empty();
        else {
          vn = corner.substr(second + 1);
          malformed |= vn.empty() || vn.find('/') != std::string_view::npos;
        }
      }
      if (malformed)
        return fail("f: malformed corner '" + printable(corner) + "' (expected v, v/vt, v//vn or v/vt/vn)");
      if (!index(v, corner, "v", out_->position_count())) return false;
      if (vt.empty()) out_->corners.push_back(kAbsent);
      else if (!index(vt, corner, "vt", texcoord_count)) return false;
      if (vn.empty()) out_->corners.push_back(kAbsent);
      else if (!index(vn, corner, "vn", normal_count)) return false;
      ++corners;
    }
    if (corners < 3) return fail("f: needs at least 3 corners (got " + std::to_string(corners) + ")");
    out_->faces.push_back({corners, static_cast<uint32_t>(line_)});
    return true;
  }

  bool use_material() {
    cursor_.skip_blanks();
    std::string name = cursor_.rest_of_line();
    if (name.empty()) return fail("usemtl: needs a material name");
    uint32_t index = 0;
    while (index < out_->material_names.size() && out_->material_names[index] != name) ++index;
    if (index == out_->material_names.size()) {
      out_->material_names.push_back(name);
      out_->material_name_lines.push_back(line_);
    }
    record_change(StateChange::kMaterial, index);
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
  uint64_t line_ = 0;
};

}  // namespace

void parse_chunk(std::string_view text, bool first_in_file, ChunkData* out) {
  ChunkParser(text, out).run(first_in_file);
}

}  // namespace pfx_obj
