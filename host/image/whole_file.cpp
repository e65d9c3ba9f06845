#include "whole_file.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>

#include <openexr.h>

#include "exr_header_scan.hpp"
#include "exr_io.hpp"

namespace pfx::app {
namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// The IEND chunk: its length (0), its type, and the CRC of its type.
constexpr unsigned char kPngEnd[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};

bool png_is_whole(std::ifstream& file, std::streamoff size) {
  unsigned char head[sizeof kPngSignature], tail[sizeof kPngEnd];
  if (size < static_cast<std::streamoff>(sizeof head + sizeof tail)) return false;
  file.read(reinterpret_cast<char*>(head), sizeof head);
  file.seekg(size - static_cast<std::streamoff>(sizeof tail));
  file.read(reinterpret_cast<char*>(tail), sizeof tail);
  return file && std::memcmp(head, kPngSignature, sizeof head) == 0 && std::memcmp(tail, kPngEnd, sizeof tail) == 0;
}

bool is_png_name(const std::string& path) { return path.size() >= 4 && path.compare(path.size() - 4, 4, ".png") == 0; }

void ignore_core_message(exr_const_context_t, exr_result_t, const char*) {}

// Every chunk of a scanline part lies inside the file.
bool scanline_chunks_inside(exr_const_context_t ctx, int part, uint64_t size) {
  exr_attr_box2i_t data{};
  int32_t lines = 0, chunks = 0;
  if (exr_get_data_window(ctx, part, &data) != EXR_ERR_SUCCESS ||
      exr_get_scanlines_per_chunk(ctx, part, &lines) != EXR_ERR_SUCCESS ||
      exr_get_chunk_count(ctx, part, &chunks) != EXR_ERR_SUCCESS || lines < 1)
    return false;
  for (int32_t chunk = 0; chunk < chunks; ++chunk) {
    exr_chunk_info_t info{};
    if (exr_read_scanline_chunk_info(ctx, part, data.min.y + chunk * lines, &info) != EXR_ERR_SUCCESS ||
        info.data_offset > size || info.packed_size > size - info.data_offset)
      return false;
  }
  return true;
}

bool exr_is_whole(const std::string& path, uint64_t size) {
  // The hand-written scan first: it refuses headers whose sizes would make the core library
  // allocate what the file cannot hold.
  detail::ExrHeaderScan scan;
  std::string reason;
  if (!detail::scan_exr_header(path, &scan, &reason)) return false;
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = &ignore_core_message;
  exr_context_t ctx = nullptr;
  bool whole = exr_start_read(&ctx, path.c_str(), &init) == EXR_ERR_SUCCESS;
  bool decode = false;
  int parts = 0;
  whole = whole && exr_get_count(ctx, &parts) == EXR_ERR_SUCCESS && parts > 0;
  for (int part = 0; whole && !decode && part < parts; ++part) {
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    whole = exr_get_storage(ctx, part, &storage) == EXR_ERR_SUCCESS;
    if (whole && storage != EXR_STORAGE_SCANLINE) decode = true;
    else whole = whole && scanline_chunks_inside(ctx, part, size);
  }
  exr_finish(&ctx);
  if (whole && decode) {
    Image image;
    return read_exr(path, &image, &reason);
  }
  return whole;
}

}  // namespace

bool image_file_is_whole(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) return false;
  const std::streamoff size = file.tellg();
  file.seekg(0);
  if (is_png_name(path)) return png_is_whole(file, size);
  return size > 0 && exr_is_whole(path, static_cast<uint64_t>(size));
}

}  // namespace pfx::app
