// Internal to read_exr: walks an OpenEXR file's header(s) with reads and seeks, allocating
// nothing that the file's numbers decide. It finds the display and data windows, so absurd
// sizes are reported as what they are ("exceeds the limit"), and it refuses any attribute
// whose declared size runs past the end of the file: OpenEXR's C++ reader allocates such sizes
// (up to 2 GiB for one string) before noticing the file is too short. It also refuses any
// attribute whose declared size differs from the bytes that reader takes for it (a v2f is 8
// bytes to it, whatever the file says), since the reader would go on from elsewhere than the
// scan did and size its next "attribute" from bytes nobody checked.
#pragma once

#include <cstdint>
#include <string>

namespace pfx::app::detail {

struct ExrWindow {
  std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive, as EXR writes them
  std::int64_t width() const { return x1 - x0 + 1; }
  std::int64_t height() const { return y1 - y0 + 1; }
};

struct ExrHeaderScan {
  ExrWindow display;  // of the first part
  ExrWindow data;
  bool has_display = false;
  bool has_data = false;
};

// False, with *reason, when the header is cut short or an attribute cannot fit in the file.
// A header that parses but lacks windows is left for the OpenEXR parser to diagnose.
bool scan_exr_header(const std::string& path, ExrHeaderScan* out, std::string* reason);

}  // namespace pfx::app::detail
