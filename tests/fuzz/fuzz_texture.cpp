// libFuzzer target for the texture path (map_Kd and the other maps of a model): any bytes as a
// JPEG, BMP or TGA (decode_texture_bytes, once as a file named .tga and once not) and as a file
// (read_texture_file, which sends PNG to libpng). Every input must be decoded or refused with a
// reason, never crash, never read out of bounds (AddressSanitizer), and a decoded image must have
// a consistent size within the texture limit.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "texture_file.hpp"

namespace {

// The limit is a parameter the decoders honour before decoding; a small one keeps each run fast
// (a header may claim 64 Mi pixels) without leaving any code path out.
constexpr std::int64_t kFuzzMaxPixels = std::int64_t{1} << 20;

// One in-memory file for the whole run: /proc/self/fd/N names it without touching the disk.
struct MemoryFile {
  int fd = ::memfd_create("fuzz.texture", 0);
  std::string path = "/proc/self/fd/" + std::to_string(fd);
};

void check(bool ok, const pfx::app::DisplayImage& image, const std::string& problem) {
  if (!ok) {
    if (problem.empty()) __builtin_trap();
    return;
  }
  if (!image.is_consistent() || image.width < 1 || image.height < 1) __builtin_trap();
  if (std::int64_t{image.width} * image.height > kFuzzMaxPixels) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (bool tga : {false, true}) {
    pfx::app::DisplayImage image;
    std::string problem;
    check(pfx::app::decode_texture_bytes(data, size, tga, &image, &problem, kFuzzMaxPixels), image, problem);
  }
  static MemoryFile file;
  if (file.fd < 0) __builtin_trap();
  if (::ftruncate(file.fd, 0) != 0 || ::pwrite(file.fd, data, size, 0) != static_cast<ssize_t>(size)) __builtin_trap();
  pfx::app::DisplayImage image;
  std::string problem;
  check(pfx::app::read_texture_file(file.path, &image, &problem, kFuzzMaxPixels), image, problem);
  return 0;
}
