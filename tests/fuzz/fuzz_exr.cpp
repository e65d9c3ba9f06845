// libFuzzer target for the EXR input path: read_exr on any bytes, as colour (--input) and as
// depth (--depth). Every input must be read or
// refused with a message that starts with the file's name, never crash, never read out of bounds
// (AddressSanitizer), never allocate past libFuzzer's limit, and a successful read must give an
// image of a consistent size within the limits asked for.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "exr_io.hpp"

namespace {

// One in-memory file for the whole run: read_exr takes a path, and /proc/self/fd/N names it
// without touching the disk.
struct MemoryFile {
  int fd = ::memfd_create("fuzz.exr", 0);
  std::string path = "/proc/self/fd/" + std::to_string(fd);
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static MemoryFile file;
  if (file.fd < 0) __builtin_trap();
  if (::ftruncate(file.fd, 0) != 0 || ::pwrite(file.fd, data, size, 0) != static_cast<ssize_t>(size)) __builtin_trap();

  pfx::app::ExrLimits limits;
  limits.max_dimension = 4096;
  limits.max_pixels = int64_t{1} << 20;
  for (auto role : {pfx::app::ExrRequest::Role::Color, pfx::app::ExrRequest::Role::Depth}) {
    pfx::app::ExrRequest request;
    request.role = role;
    request.limits = limits;
    pfx::app::Image image;
    std::string error, used;
    if (pfx::app::read_exr(file.path, &image, &error, request, &used)) {
      const bool depth_only = role == pfx::app::ExrRequest::Role::Depth;
      if (depth_only ? image.depth.size() != image.pixel_count() || !image.rgba.empty() : !image.is_consistent())
        __builtin_trap();
      if (image.width < 1 || image.height < 1 || used.empty()) __builtin_trap();
      if (image.width > limits.max_dimension || image.height > limits.max_dimension) __builtin_trap();
      if (int64_t{image.width} * image.height > limits.max_pixels) __builtin_trap();
    } else if (error.rfind(file.path + ": ", 0) != 0) {
      __builtin_trap();  // a refusal must name the file
    }
  }
  return 0;
}
