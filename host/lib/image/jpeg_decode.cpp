#include "jpeg_decode.hpp"

#include <csetjmp>
#include <cstdio>
#include <new>
#include <vector>

#include <jpeglib.h>
#include <jerror.h>

namespace pfx::app {
namespace {

// libjpeg reports fatal errors through error_exit, which must not return: it jumps back to run's
// setjmp.
struct ErrorManager {
  jpeg_error_mgr base;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
  bool truncated;
};

[[noreturn]] void on_error(j_common_ptr info) {
  auto* errors = reinterpret_cast<ErrorManager*>(info->err);
  (*info->err->format_message)(info, errors->message);
  std::longjmp(errors->jump, 1);
}

// Warnings (level -1) are data libjpeg could not use; the one that matters is the file ending
// early, after which libjpeg makes up the rest. Nothing is printed: the caller reports.
void on_message(j_common_ptr info, int level) {
  auto* errors = reinterpret_cast<ErrorManager*>(info->err);
  if (level < 0 && info->err->msg_code == JWRN_JPEG_EOF) errors->truncated = true;
}

// Everything the decode touches lives here, reached through one pointer, so a longjmp back to
// run's setjmp finds it as it was (no local is changed after the setjmp), and everything with a
// destructor outlives run.
struct JpegJob {
  const std::uint8_t* data;
  std::size_t size;
  std::int64_t max_pixels;
  jpeg_decompress_struct info;
  ErrorManager errors;
  std::vector<std::uint8_t> pixels;
  std::string problem;
  bool created = false;
  bool jumped = false;  // libjpeg gave up: errors.message says why
};

// Everything after the setjmp, in a function of its own: the one that calls setjmp then holds no
// C++ object at all (GCC rightly warns that a std::string temporary there could be clobbered).
__attribute__((noinline)) bool decode(JpegJob* job) {
  jpeg_decompress_struct& info = job->info;
  jpeg_create_decompress(&info);
  job->created = true;
  jpeg_mem_src(&info, job->data, static_cast<unsigned long>(job->size));
  jpeg_read_header(&info, TRUE);
  const std::int64_t w = info.image_width, h = info.image_height;
  if (w <= 0 || h <= 0 || w > job->max_pixels / h) {
    job->problem = "image " + std::to_string(w) + "x" + std::to_string(h) + " exceeds the limit of " +
                   std::to_string(job->max_pixels) + " pixels";
    return false;
  }
  info.out_color_space = JCS_RGB;
  jpeg_start_decompress(&info);
  const std::size_t stride = static_cast<std::size_t>(info.output_width) * 3;
  job->pixels.resize(stride * info.output_height);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = job->pixels.data() + stride * info.output_scanline;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  if (job->errors.truncated) {
    job->problem = "truncated JPEG file (it ends before its pixels do)";
    return false;
  }
  return true;
}

bool run(JpegJob* job) {
  job->info.err = jpeg_std_error(&job->errors.base);
  job->errors.base.error_exit = on_error;
  job->errors.base.emit_message = on_message;
  if (setjmp(job->errors.jump)) {
    job->jumped = true;
    return false;
  }
  return decode(job);
}

}  // namespace

bool decode_jpeg(const std::uint8_t* data, std::size_t size, std::int64_t max_pixels, DisplayImage* out,
                 std::string* problem) {
  JpegJob job{data, size, max_pixels, {}, {}, {}, {}, false, false};
  bool ok = false;
  try {
    ok = run(&job);
  } catch (const std::bad_alloc&) {
    job.problem = "out of memory";
  }
  if (job.jumped) job.problem = std::string("damaged JPEG file (libjpeg: ") + job.errors.message + ")";
  if (job.created) jpeg_destroy_decompress(&job.info);
  if (!ok) {
    *problem = job.problem;
    return false;
  }
  out->width = static_cast<int>(job.info.output_width);
  out->height = static_cast<int>(job.info.output_height);
  out->channels = 3;
  out->pixels = std::move(job.pixels);
  return true;
}

}  // namespace pfx::app
