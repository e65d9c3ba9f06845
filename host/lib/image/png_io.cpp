#include "png_io.hpp"

#include <cerrno>
#include <cstring>
#include <exception>
#include <new>

#include <png.h>
#include <sys/stat.h>

#include "atomic_file.hpp"

namespace pfx::app {

bool write_png(const std::string& path, const DisplayImage& img, std::string* error) {
  if (img.width <= 0 || img.height <= 0 || !img.is_consistent()) {
    if (error) {
      *error = "cannot write " + path + ": the image is empty or its pixel data does not match " +
               std::to_string(img.width) + "x" + std::to_string(img.height) + "x" +
               std::to_string(img.channels);
    }
    return false;
  }
  return write_atomically(
      path,
      [&](const std::string& temp, std::string* reason) {
        png_image png;
        std::memset(&png, 0, sizeof png);
        png.version = PNG_IMAGE_VERSION;
        png.width = static_cast<png_uint_32>(img.width);
        png.height = static_cast<png_uint_32>(img.height);
        // Non-linear 8-bit formats are written with an sRGB chunk by libpng.
        png.format = img.channels == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
        const png_int_32 stride = static_cast<png_int_32>(img.width) * img.channels;
        if (!png_image_write_to_file(&png, temp.c_str(), 0, img.pixels.data(), stride, nullptr)) {
          *reason = std::string("libpng: ") + png.message;
          png_image_free(&png);
          return false;
        }
        return true;
      },
      error);
}

bool read_png(const std::string& path, DisplayImage* out, std::string* error,
              std::int64_t max_pixels) {
  auto fail = [&](const std::string& why) {
    if (error) *error = path + ": " + why;
    return false;
  };
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    return fail(errno == ENOENT ? std::string("no such file")
                                : std::string("cannot access: ") + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) return fail("is a folder, not a PNG file");

  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    const std::string why = std::string("not a readable PNG file (libpng: ") + png.message + ")";
    png_image_free(&png);
    return fail(why);
  }
  const std::int64_t w = png.width, h = png.height;
  if (w <= 0 || h <= 0 || w > max_pixels / h) {
    png_image_free(&png);
    return fail("image " + std::to_string(w) + "x" + std::to_string(h) +
                " exceeds the limit of " + std::to_string(max_pixels) + " pixels");
  }
  const bool alpha = (png.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  png.format = alpha ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;

  DisplayImage img;
  img.width = static_cast<int>(w);
  img.height = static_cast<int>(h);
  img.channels = alpha ? 4 : 3;
  try {
    img.pixels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * img.channels);
  } catch (const std::bad_alloc&) {
    png_image_free(&png);
    return fail("out of memory");
  }
  const png_int_32 stride = static_cast<png_int_32>(w) * img.channels;
  if (!png_image_finish_read(&png, nullptr, img.pixels.data(), stride, nullptr)) {
    const std::string why = std::string("damaged PNG file (libpng: ") + png.message + ")";
    png_image_free(&png);
    return fail(why);
  }
  *out = std::move(img);
  return true;
}

}  // namespace pfx::app
