// read_exr checks a file in three steps before OpenEXR's C++ reader, which sizes its tables
// and attributes from the header as soon as it opens a file, ever sees it: what kind of file it
// is; the attribute sizes and the windows (against ExrLimits) with our own allocation-free scan;
// then every part's header with OpenEXR's C core, which validates what the C++ reader trusts.
// The channels to read are then chosen from the names alone (exr_channels.cpp) and decoded
// (exr_pixels.cpp).
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

#include <ImfHeader.h>
#include <ImfInputPart.h>
#include <ImfMultiPartInputFile.h>
#include <ImfRgbaYca.h>
#include <ImfStandardAttributes.h>
#include <openexr.h>

#include "exr_channels.hpp"
#include "exr_header_scan.hpp"
#include "exr_io.hpp"
#include "exr_pixels.hpp"

namespace pfx::app {
namespace {

using Box = detail::ExrWindow;

struct PartWindows {
  Box display;
  Box data;
};

struct HeaderInfo {
  std::vector<detail::ExrPartInfo> parts;
  std::vector<PartWindows> windows;  // one per part
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

// The channels of every part: the choice among them is exr_channels.cpp's.
bool collect_channels(const exr_attr_chlist_t* list, detail::ExrPartInfo* part, std::string* reason) {
  for (int i = 0; list && i < list->num_channels; ++i) {
    const exr_attr_chlist_entry_t& e = list->entries[i];
    detail::ExrChannelInfo channel;
    channel.name.assign(e.name.str ? e.name.str : "", e.name.str ? static_cast<std::size_t>(e.name.length) : 0);
    channel.x_sampling = e.x_sampling;
    channel.y_sampling = e.y_sampling;
    if (channel.x_sampling < 1 || channel.y_sampling < 1) {
      *reason = "damaged OpenEXR header: channel " + channel.name + " has a sampling rate below 1";
      return false;
    }
    part->channels.push_back(std::move(channel));
  }
  return true;
}

// A subsampled channel's samples lie on multiples of its sampling rate; a data window that does not
// start on one leaves the reader nothing to align them with.
bool check_sampling(const detail::ExrChannelPlan& plan, const Box& data, std::string* reason) {
  for (const auto& source : plan.sources) {
    if (data.x0 % source.x_sampling != 0 || data.y0 % source.y_sampling != 0) {
      *reason = "damaged OpenEXR header: channel " + source.channel + " is sampled every " +
                std::to_string(source.x_sampling) + "x" + std::to_string(source.y_sampling) +
                " pixels, which the data window's corner is not a multiple of";
      return false;
    }
  }
  return true;
}

// OpenEXR allocates one tile, and for a tiled file read by scanlines one row of tiles across the
// data window, at the tile size the header declares: a 4x17039360 tile on a 9x7 image once asked
// for 2.4 GB (found by fuzz.exr). Both are held to the limit on the image's pixels.
bool check_tiles(exr_const_context_t ctx, int part, const Box& data, const ExrLimits& limits,
                 std::string* reason) {
  std::uint32_t x_size = 0, y_size = 0;
  exr_tile_level_mode_t level{};
  exr_tile_round_mode_t round{};
  if (exr_get_tile_descriptor(ctx, part, &x_size, &y_size, &level, &round) != EXR_ERR_SUCCESS ||
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

// Every part's header is checked, not only the one read: OpenEXR's C++ reader sets up all the
// parts of a file (their tables included) when it opens it.
bool check_part(exr_const_context_t ctx, int index, const ExrLimits& limits, PartWindows* windows,
                detail::ExrPartInfo* part, std::string* reason) {
  exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
  exr_attr_box2i_t disp{}, data{};
  const exr_attr_chlist_t* channels = nullptr;
  const char* name = nullptr;
  if (exr_get_storage(ctx, index, &storage) != EXR_ERR_SUCCESS ||
      exr_get_display_window(ctx, index, &disp) != EXR_ERR_SUCCESS ||
      exr_get_data_window(ctx, index, &data) != EXR_ERR_SUCCESS ||
      exr_get_channels(ctx, index, &channels) != EXR_ERR_SUCCESS) {
    *reason = "damaged OpenEXR header: " +
              (t_core_message.empty() ? std::string("missing required attributes") : t_core_message);
    return false;
  }
  if (exr_get_name(ctx, index, &name) == EXR_ERR_SUCCESS && name) part->name = name;
  part->deep = storage == EXR_STORAGE_DEEP_SCANLINE || storage == EXR_STORAGE_DEEP_TILED;
  windows->display = Box{disp.min.x, disp.min.y, disp.max.x, disp.max.y};
  windows->data = Box{data.min.x, data.min.y, data.max.x, data.max.y};
  return check_window("display window", windows->display, limits, reason) &&
         check_window("data window", windows->data, limits, reason) &&
         (storage != EXR_STORAGE_TILED || check_tiles(ctx, index, windows->data, limits, reason)) &&
         collect_channels(channels, part, reason);
}

bool read_header(const std::string& path, const ExrLimits& limits, HeaderInfo* info, std::string* reason) {
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
  int count = 0;
  bool ok = exr_get_count(ctx, &count) == EXR_ERR_SUCCESS && count > 0;
  if (!ok) *reason = "damaged OpenEXR header: no parts";
  for (int i = 0; ok && i < count; ++i) {
    info->parts.emplace_back();
    info->windows.emplace_back();
    ok = check_part(ctx, i, limits, &info->windows.back(), &info->parts.back(), reason);
  }
  exr_finish(&ctx);
  return ok;
}

bool same_window(const Imath::Box2i& a, const Box& b) {
  return a.min.x == b.x0 && a.min.y == b.y0 && a.max.x == b.x1 && a.max.y == b.y1;
}

Imath::V3f luminance_weights(const Imf::Header& header) {
  return Imf::RgbaYca::computeYw(Imf::hasChromaticities(header) ? Imf::chromaticities(header) : Imf::Chromaticities());
}

}  // namespace

bool read_exr(const std::string& path, Image* out, std::string* error, const ExrRequest& request, std::string* used) {
  std::string reason;
  HeaderInfo info;
  auto fail = [&](const std::string& why) {
    if (error) *error = path + ": " + why;
    return false;
  };
  const ExrLimits& limits = request.limits;
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
  detail::ExrChannelPlan plan;
  const bool planned = request.role == ExrRequest::Role::Depth
                           ? detail::plan_depth_channel(info.parts, &plan, &reason)
                           : detail::plan_color_channels(info.parts, request.layer, &plan, &reason);
  if (!planned) return fail(reason);
  const PartWindows& windows = info.windows[static_cast<std::size_t>(plan.part)];
  if (!check_sampling(plan, windows.data, &reason)) return fail(reason);

  try {
    Imf::MultiPartInputFile file(path.c_str());
    // The file was opened twice; if it changed in between, the checked header no longer holds.
    if (file.parts() != static_cast<int>(info.parts.size())) return fail("the file changed while it was being read");
    Imf::InputPart part(file, plan.part);
    if (!same_window(part.header().dataWindow(), windows.data) ||
        !same_window(part.header().displayWindow(), windows.display)) {
      return fail("the file changed while it was being read");
    }
    Image img;
    img.width = static_cast<int>(windows.display.width());
    img.height = static_cast<int>(windows.display.height());
    if (plan.color != detail::ExrColorMode::None) img.rgba.assign(img.pixel_count() * 4, 0.0f);
    if (plan.depth) img.depth.assign(img.pixel_count(), std::numeric_limits<float>::infinity());
    detail::read_planned_pixels(part, windows.data, windows.display, plan, luminance_weights(part.header()), &img);
    *out = std::move(img);
    if (used) *used = plan.description;
    return true;
  } catch (const std::bad_alloc&) {
    return fail("out of memory while reading the pixels");
  } catch (const std::exception& e) {
    return fail(std::string("damaged or truncated OpenEXR file: ") + e.what());
  } catch (...) {
    return fail("damaged or truncated OpenEXR file");
  }
}

bool read_exr(const std::string& path, Image* out, std::string* error, const ExrLimits& limits) {
  ExrRequest request;
  request.limits = limits;
  return read_exr(path, out, error, request, nullptr);
}

}  // namespace pfx::app
