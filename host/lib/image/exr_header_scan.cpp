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
  std::int64_t remaining() const { return size_ - static_cast<std::int64_t>(std::ftell(f_)); }
  bool skip(std::int64_t n) { return std::fseek(f_, static_cast<long>(n), SEEK_CUR) == 0; }

 private:
  std::FILE* f_;
  std::int64_t size_;
};

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
