// read_exr checks a file in three steps before OpenEXR's C++ InputFile, which sizes its tables
// and attributes from the header as soon as it opens a file, ever sees it: what kind of file it
// is; the attribute sizes and the windows (against ExrLimits) with our own allocation-free scan;
// then the whole header with OpenEXR's C core, which validates what the C++ reader trusts.
#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <new>
#include <vector>

#include <sys/stat.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <openexr.h>

#include "exr_io.hpp"
#include "exr_header_scan.hpp"

namespace pfx::app {
namespace {

using Box = detail::ExrWindow;

struct HeaderInfo {
  Box display;
  Box data;
  bool grey = false;  // Y instead of R, G, B
  bool depth = false;
};

std::string describe(const Box& b) {
  return std::to_string(b.width()) + "x" + std::to_string(b.height());
}

// Distinguishes "not there" and "not an EXR" from "a damaged EXR", which users fix differently.
bool check_file_kind(const std::string& path, std::string* reason) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    *reason = errno == ENOENT ? std::string("no such file")
                              : std::string("cannot access: ") + std::strerror(errno);
    return false;
  }
  if (S_ISDIR(st.st_mode)) {
    *reason = "is a folder, not an OpenEXR file";
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    *reason = "is not a regular file";
    return false;
  }
  if (st.st_size == 0) {
    *reason = "empty file (0 bytes), not an OpenEXR image";
    return false;
  }
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    *reason = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  unsigned char magic[4] = {0, 0, 0, 0};
  const std::size_t got = std::fread(magic, 1, 4, f);
  std::fclose(f);
  static const unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
  if (got < 4) {
    *reason = "too short to be an OpenEXR file (" + std::to_string(got) + " bytes)";
    return false;
  }
  if (std::memcmp(magic, kMagic, 4) != 0) {
    *reason = "not an OpenEXR file (it does not start with the OpenEXR magic number)";
    return false;
  }
  return true;
}

// The core library reports details through a callback rather than a return value.
thread_local std::string t_core_message;

void capture_core_message(exr_const_context_t, exr_result_t code, const char* msg) {
  t_core_message = msg && *msg ? msg : exr_get_default_error_message(code);
}

bool check_window(const char* what, const Box& b, const ExrLimits& limits, std::string* reason) {
  if (b.width() <= 0 || b.height() <= 0) {
    *reason = std::string("damaged OpenEXR header: empty ") + what;
    return false;
  }
  if (b.width() > limits.max_dimension || b.height() > limits.max_dimension) {
    *reason = std::string(what) + " " + describe(b) + " exceeds the limit of " +
              std::to_string(limits.max_dimension) + " pixels per side";
    return false;
  }
  // Both sides are at most max_dimension here, so the product cannot overflow 64 bits for any
  // sane limit; the division form keeps it safe for insane ones too.
  if (b.width() > limits.max_pixels / b.height()) {
    *reason = std::string(what) + " " + describe(b) + " exceeds the limit of " +
              std::to_string(limits.max_pixels) + " pixels";
    return false;
  }
  return true;
}

bool choose_channels(const exr_attr_chlist_t* list, HeaderInfo* info, std::string* reason) {
  bool r = false, g = false, b = false, y = false, chroma = false;
  std::string names;
  for (int i = 0; list && i < list->num_channels; ++i) {
    const exr_attr_chlist_entry_t& e = list->entries[i];
    const std::string name(e.name.str ? e.name.str : "", e.name.str ? e.name.length : 0);
    names += (names.empty() ? "" : ", ") + name;
    const bool used = name == "R" || name == "G" || name == "B" || name == "A" ||
                      name == "Y" || name == "Z";
    if (used && (e.x_sampling != 1 || e.y_sampling != 1)) {
      *reason = "channel " + name + " is subsampled, which is not supported";
      return false;
    }
    r |= name == "R";
    g |= name == "G";
    b |= name == "B";
    y |= name == "Y";
    chroma |= name == "RY" || name == "BY";
    info->depth |= name == "Z";
  }
  if (r && g && b) return true;
  if (r || g || b) {
    *reason = "has only some of the R, G, B channels (channels: " + names + ")";
    return false;
  }
  if (y && chroma) {
    *reason = "luminance/chroma (Y, RY, BY) images are not supported; save it as RGB";
    return false;
  }
  if (y) {
    info->grey = true;
    return true;
  }
  *reason = "no R, G, B or Y channels to read (channels: " + (names.empty() ? "none" : names) + ")";
  return false;
}

// OpenEXR allocates one tile, and for a tiled file read by scanlines one row of tiles across the
// data window, at the tile size the header declares: a 4x17039360 tile on a 9x7 image once asked
// for 2.4 GB (found by fuzz.exr). Both are held to the limit on the image's pixels.
bool check_tiles(exr_const_context_t ctx, const Box& data, const ExrLimits& limits, std::string* reason) {
  std::uint32_t x_size = 0, y_size = 0;
  exr_tile_level_mode_t level{};
  exr_tile_round_mode_t round{};
  if (exr_get_tile_descriptor(ctx, 0, &x_size, &y_size, &level, &round) != EXR_ERR_SUCCESS ||
      x_size == 0 || y_size == 0) {
    *reason = "damaged OpenEXR header: a tiled image without a valid tile size";
    return false;
  }
  const std::int64_t x = x_size, y = y_size;
  if (x > limits.max_pixels / y || y > limits.max_pixels / data.width()) {
    *reason = "tile size " + std::to_string(x) + "x" + std::to_string(y) + " exceeds the limit of " +
              std::to_string(limits.max_pixels) + " pixels (per tile, or per row of tiles across the " +
              std::to_string(data.width()) + " pixel wide data window)";
    return false;
  }
  return true;
}

bool read_header(const std::string& path, const ExrLimits& limits, HeaderInfo* info,
                 std::string* reason) {
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = &capture_core_message;
  t_core_message.clear();
  exr_context_t ctx = nullptr;
  const exr_result_t started = exr_start_read(&ctx, path.c_str(), &init);
  if (started != EXR_ERR_SUCCESS) {
    *reason = "damaged or unsupported OpenEXR header: " +
              (t_core_message.empty() ? std::string(exr_get_default_error_message(started))
                                      : t_core_message);
    exr_finish(&ctx);
    return false;
  }
  bool ok = false;
  exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
  exr_attr_box2i_t disp{}, data{};
  const exr_attr_chlist_t* channels = nullptr;
  if (exr_get_storage(ctx, 0, &storage) != EXR_ERR_SUCCESS ||
      exr_get_display_window(ctx, 0, &disp) != EXR_ERR_SUCCESS ||
      exr_get_data_window(ctx, 0, &data) != EXR_ERR_SUCCESS ||
      exr_get_channels(ctx, 0, &channels) != EXR_ERR_SUCCESS) {
    *reason = "damaged OpenEXR header: " +
              (t_core_message.empty() ? std::string("missing required attributes") : t_core_message);
  } else if (storage == EXR_STORAGE_DEEP_SCANLINE || storage == EXR_STORAGE_DEEP_TILED) {
    *reason = "deep OpenEXR images are not supported";
  } else {
    info->display = Box{disp.min.x, disp.min.y, disp.max.x, disp.max.y};
    info->data = Box{data.min.x, data.min.y, data.max.x, data.max.y};
    ok = check_window("display window", info->display, limits, reason) &&
         check_window("data window", info->data, limits, reason) &&
         (storage != EXR_STORAGE_TILED || check_tiles(ctx, info->data, limits, reason)) &&
         choose_channels(channels, info, reason);
  }
  exr_finish(&ctx);
  return ok;
}

// Rows are decoded a strip at a time into scratch memory bounded whatever the data window.
// Strips are powers of two up to 256 rows, so they stay multiples of the compression schemes'
// block heights (16, 32, 256 rows) and no block is decoded twice, except for absurdly wide
// images where the memory bound wins.
constexpr std::int64_t kMaxStripRows = 256;
constexpr std::size_t kMaxStripBytes = std::size_t{64} << 20;
constexpr int kScratchChannels = 5;  // R G B A Z

void read_pixels(Imf::InputFile& file, const HeaderInfo& info, Image* img) {
  const Box& dw = info.data;
  const Box& disp = info.display;
  const std::size_t row_floats = static_cast<std::size_t>(dw.width()) * kScratchChannels;
  std::int64_t strip_rows = kMaxStripRows;
  while (strip_rows > 1 && strip_rows * row_floats * sizeof(float) > kMaxStripBytes) {
    strip_rows /= 2;
  }
  strip_rows = std::min(strip_rows, dw.height());
  std::vector<float> strip(row_floats * static_cast<std::size_t>(strip_rows));
  const std::size_t xs = kScratchChannels * sizeof(float);
  const std::size_t ys = row_floats * sizeof(float);

  // Only the columns and rows inside the display window are copied out.
  const std::int64_t cx0 = std::max(dw.x0, disp.x0), cx1 = std::min(dw.x1, disp.x1);

  for (std::int64_t y0 = dw.y0; y0 <= dw.y1; y0 += strip_rows) {
    const std::int64_t y1 = std::min(y0 + strip_rows - 1, dw.y1);
    const Imath::V2i origin(static_cast<int>(dw.x0), static_cast<int>(y0));
    const std::int64_t w = dw.width(), h = y1 - y0 + 1;
    auto slice = [&](int channel, double fill) {
      return Imf::Slice::Make(Imf::FLOAT, strip.data() + channel, origin, w, h, xs, ys, 1, 1,
                              fill);
    };
    Imf::FrameBuffer fb;
    if (info.grey) {
      fb.insert("Y", slice(0, 0.0));
    } else {
      fb.insert("R", slice(0, 0.0));
      fb.insert("G", slice(1, 0.0));
      fb.insert("B", slice(2, 0.0));
    }
    fb.insert("A", slice(3, 1.0));  // OpenEXR fills a channel the file lacks with this value
    if (info.depth) fb.insert("Z", slice(4, 0.0));
    file.setFrameBuffer(fb);
    file.readPixels(static_cast<int>(y0), static_cast<int>(y1));

    if (cx0 > cx1) continue;
    for (std::int64_t y = std::max(y0, disp.y0); y <= std::min(y1, disp.y1); ++y) {
      const float* src = strip.data() + static_cast<std::size_t>(y - y0) * row_floats +
                         static_cast<std::size_t>(cx0 - dw.x0) * kScratchChannels;
      const std::size_t dst_px = static_cast<std::size_t>(y - disp.y0) * img->width +
                                 static_cast<std::size_t>(cx0 - disp.x0);
      const std::size_t n = static_cast<std::size_t>(cx1 - cx0 + 1);
      float* dst = img->rgba.data() + dst_px * 4;
      for (std::size_t i = 0; i < n; ++i) {
        const float* s = src + i * kScratchChannels;
        dst[i * 4 + 0] = s[0];
        dst[i * 4 + 1] = info.grey ? s[0] : s[1];
        dst[i * 4 + 2] = info.grey ? s[0] : s[2];
        dst[i * 4 + 3] = s[3];
        if (info.depth) img->depth[dst_px + i] = s[4];
      }
    }
  }
}

bool same_window(const Imath::Box2i& a, const Box& b) {
  return a.min.x == b.x0 && a.min.y == b.y0 && a.max.x == b.x1 && a.max.y == b.y1;
}

}  // namespace

bool read_exr(const std::string& path, Image* out, std::string* error, const ExrLimits& limits) {
  std::string reason;
  HeaderInfo info;
  auto fail = [&](const std::string& why) {
    if (error) *error = path + ": " + why;
    return false;
  };
  if (!check_file_kind(path, &reason)) return fail(reason);
  detail::ExrHeaderScan scan;
  if (!detail::scan_exr_header(path, &scan, &reason)) return fail(reason);
  if (scan.has_display && !check_window("display window", scan.display, limits, &reason)) {
    return fail(reason);
  }
  if (scan.has_data && !check_window("data window", scan.data, limits, &reason)) {
    return fail(reason);
  }
  if (!read_header(path, limits, &info, &reason)) return fail(reason);

  try {
    Imf::InputFile file(path.c_str());
    // The file was opened twice; if it changed in between, the checked header no longer holds.
    if (!same_window(file.header().dataWindow(), info.data) ||
        !same_window(file.header().displayWindow(), info.display)) {
      return fail("the file changed while it was being read");
    }
    Image img;
    img.width = static_cast<int>(info.display.width());
    img.height = static_cast<int>(info.display.height());
    img.rgba.assign(img.pixel_count() * 4, 0.0f);
    if (info.depth) img.depth.assign(img.pixel_count(), std::numeric_limits<float>::infinity());
    read_pixels(file, info, &img);
    *out = std::move(img);
    return true;
  } catch (const std::bad_alloc&) {
    return fail("out of memory while reading the pixels");
  } catch (const std::exception& e) {
    return fail(std::string("damaged or truncated OpenEXR file: ") + e.what());
  } catch (...) {
    return fail("damaged or truncated OpenEXR file");
  }
}

}  // namespace pfx::app
