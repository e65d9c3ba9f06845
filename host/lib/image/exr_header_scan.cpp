#include "exr_header_scan.hpp"

#include <cstdio>
#include <memory>

#include <sys/stat.h>

namespace pfx::app::detail {
namespace {

// Far beyond any real header; bounds the work a looping or padded file can cause.
constexpr int kMaxAttributes = 100000;
constexpr std::uint32_t kMultiPartFlag = 0x1000;
// The longest name the format allows (with the long-names flag); shorter limits are the
// OpenEXR parser's business, not a safety question.
constexpr std::size_t kMaxNameLength = 255;

class Reader {
 public:
  Reader(std::FILE* f, std::int64_t size) : f_(f), size_(size) {}

  bool u32(std::uint32_t* v) {
    unsigned char b[4];
    if (std::fread(b, 1, 4, f_) != 4) return false;
    *v = b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<std::uint32_t>(b[3]) << 24);
    return true;
  }
  bool i32(std::int64_t* v) {
    std::uint32_t u = 0;
    if (!u32(&u)) return false;
    *v = static_cast<std::int32_t>(u);
    return true;
  }
  // A NUL-terminated name; false at end of file or past the longest legal name.
  bool name(std::string* out) {
    out->clear();
    for (;;) {
      const int c = std::fgetc(f_);
      if (c == EOF || (c != 0 && out->size() == kMaxNameLength)) return false;
      if (c == 0) return true;
      out->push_back(static_cast<char>(c));
    }
  }
  bool box(ExrWindow* w) { return i32(&w->x0) && i32(&w->y0) && i32(&w->x1) && i32(&w->y1); }
  std::int64_t position() const { return static_cast<std::int64_t>(std::ftell(f_)); }
  std::int64_t remaining() const { return size_ - position(); }
  bool skip(std::int64_t n) { return std::fseek(f_, static_cast<long>(n), SEEK_CUR) == 0; }
  bool seek(std::int64_t at) { return std::fseek(f_, static_cast<long>(at), SEEK_SET) == 0; }

 private:
  std::FILE* f_;
  std::int64_t size_;
};

// The value sizes of the attribute types OpenEXR's C++ reader knows and reads field by field,
// taking the type's own size whatever size the attribute declares (Imf::Header::readFrom).
struct FixedType {
  const char* name;
  std::int64_t size;
};
// clang-format off
constexpr FixedType kFixedTypes[] = {
    {"box2i", 16},    {"box2f", 16},   {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
    {"double", 8},    {"envmap", 1},   {"float", 4},           {"int", 4},         {"keycode", 28},
    {"lineOrder", 1}, {"m33d", 72},    {"m33f", 36},           {"m44d", 128},      {"m44f", 64},
    {"rational", 8},  {"tiledesc", 9}, {"timecode", 8},        {"v2d", 16},        {"v2f", 8},
    {"v2i", 8},       {"v3d", 24},     {"v3f", 12},            {"v3i", 12},
};
// clang-format on

// A channel list as OpenEXR reads it: entries (a name, then 16 bytes) until an empty name,
// whatever size the attribute declares. The bytes it takes, or -1 when the file ends first.
std::int64_t channel_list_size(Reader& in) {
  const std::int64_t start = in.position();
  std::string channel;
  for (;;) {
    if (!in.name(&channel)) return -1;
    if (channel.empty()) break;
    if (in.remaining() < 16 || !in.skip(16)) return -1;
  }
  const std::int64_t taken = in.position() - start;
  return in.seek(start) ? taken : -1;
}

// How many bytes OpenEXR's C++ reader takes for an attribute's value, from the type and the
// declared size (and, for a channel list, the value itself); -1 when the file ends first. The
// scan must step from attribute to attribute exactly as that reader does: where the two part,
// the reader goes on from a place the scan never checked, and reads whatever lies there as the
// next attribute's name, type and size (a v2f declaring 0 bytes once made it allocate 1.6 GB
// for an "attribute" made of the bytes after it).
std::int64_t openexr_value_size(Reader& in, const std::string& type, std::int64_t declared) {
  for (const FixedType& fixed : kFixedTypes)
    if (type == fixed.name) return fixed.size;
  if (type == "chlist") return channel_list_size(in);
  // Read as floats: a declared size that is not a multiple of 4 leaves its last bytes unread.
  if (type == "floatvector") return declared - declared % 4;
  // Read as an 8-byte uncompressed size, then the declared size less 4 (OpenEXR 3.1).
  if (type == "idmanifest" && declared >= 4) return declared + 4;
  // Strings, string vectors, previews and types OpenEXR does not know: the declared size (a
  // string vector or preview that does not fill it exactly is refused by the reader itself).
  return declared;
}

}  // namespace

bool scan_exr_header(const std::string& path, ExrHeaderScan* out, std::string* reason) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  struct stat st {};
  if (!f || ::fstat(::fileno(f.get()), &st) != 0) {
    *reason = "cannot open the file";
    return false;
  }
  Reader in(f.get(), st.st_size);
  const char* const truncated = "damaged or truncated OpenEXR header (it ends too early)";
  std::uint32_t magic = 0, version = 0;
  if (!in.u32(&magic) || !in.u32(&version)) {
    *reason = truncated;
    return false;
  }
  const bool multi_part = (version & kMultiPartFlag) != 0;

  std::string name, type;
  int attributes = 0;
  for (int part = 0;; ++part) {
    // Attributes until an empty name; a multi-part file has one header per part and ends the
    // list with an empty header.
    for (int in_part = 0;; ++in_part) {
      if (++attributes > kMaxAttributes) {
        *reason = "damaged OpenEXR header (too many attributes)";
        return false;
      }
      if (!in.name(&name)) {
        *reason = truncated;
        return false;
      }
      if (name.empty()) {
        if (in_part == 0 && part > 0) return true;  // the empty header after the last part
        break;
      }
      std::uint32_t size = 0;
      if (!in.name(&type) || !in.u32(&size)) {
        *reason = truncated;
        return false;
      }
      if (static_cast<std::int64_t>(size) > in.remaining()) {
        *reason = "damaged OpenEXR header: attribute '" + name + "' declares " +
                  std::to_string(size) + " bytes but only " + std::to_string(in.remaining()) +
                  " remain in the file";
        return false;
      }
      const std::int64_t taken = openexr_value_size(in, type, size);
      if (taken < 0) {
        *reason = truncated;
        return false;
      }
      if (taken != static_cast<std::int64_t>(size)) {
        *reason = "damaged OpenEXR header: attribute '" + name + "' of type " + type + " declares " +
                  std::to_string(size) + " bytes, but OpenEXR reads " + std::to_string(taken) + " for it";
        return false;
      }
      const bool box = part == 0 && type == "box2i" && size == 16;
      bool ok = true;
      if (box && name == "displayWindow") {
        ok = out->has_display = in.box(&out->display);
      } else if (box && name == "dataWindow") {
        ok = out->has_data = in.box(&out->data);
      } else {
        ok = in.skip(size);
      }
      if (!ok) {
        *reason = truncated;
        return false;
      }
    }
    if (!multi_part) return true;
  }
}

}  // namespace pfx::app::detail
