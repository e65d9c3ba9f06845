#include "texture_file.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <new>
#include <vector>

#include <stb/stb_image.h>

#include "jpeg_decode.hpp"
#include "png_io.hpp"

namespace pfx::app {
namespace {

// stb_image (TGA and BMP) pads a file that ends early with zeros and returns a picture; reading through these
// callbacks lets us see that it asked for bytes the file does not have, and call the file
// truncated instead of showing the made-up rest.
struct ByteStream {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t position = 0;
  bool ran_out = false;
};

int read_bytes(void* user, char* into, int wanted) {
  auto* s = static_cast<ByteStream*>(user);
  const std::size_t left = s->size - s->position;
  const std::size_t n = std::min(left, static_cast<std::size_t>(wanted > 0 ? wanted : 0));
  // stb refills its buffer 128 bytes at a time, and a short refill is how every file ends; a
  // short read of any other length is a block (a TGA row) the file cuts off, and a read at the end
  // means the decoder still wanted data.
  if ((n == 0 && wanted > 0) || (n < static_cast<std::size_t>(wanted) && wanted != 128)) s->ran_out = true;
  if (n) std::memcpy(into, s->data + s->position, n);
  s->position += n;
  return static_cast<int>(n);
}

void skip_bytes(void* user, int n) {
  auto* s = static_cast<ByteStream*>(user);
  // Negative skips are stb's rewinds; past the end is where a truncated BMP's rows would be.
  if (n < 0) {
    const std::size_t back = static_cast<std::size_t>(-static_cast<long long>(n));
    s->position = back > s->position ? 0 : s->position - back;
  } else {
    s->position = std::min(s->size, s->position + static_cast<std::size_t>(n));
  }
}

int at_end(void* user) {
  auto* s = static_cast<ByteStream*>(user);
  return s->position >= s->size;
}

bool has_prefix(const std::uint8_t* data, std::size_t size, const char* prefix, std::size_t length) {
  return size >= length && std::memcmp(data, prefix, length) == 0;
}

bool ends_with_tga(const std::string& path) {
  if (path.size() < 4) return false;
  std::string tail = path.substr(path.size() - 4);
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".tga";
}

}  // namespace

bool decode_texture_bytes(const std::uint8_t* data, std::size_t size, bool tga, DisplayImage* out,
                          std::string* problem, std::int64_t max_pixels) {
  const bool jpeg = has_prefix(data, size, "\xFF\xD8\xFF", 3);
  const bool bmp = has_prefix(data, size, "BM", 2);
  if (jpeg) return decode_jpeg(data, size, max_pixels, out, problem);
  if (!bmp && !tga) {
    *problem = "not a PNG, JPEG, TGA or BMP file";
    return false;
  }
  if (size > static_cast<std::size_t>(INT32_MAX)) {
    *problem = "file too large";
    return false;
  }
  const stbi_io_callbacks callbacks{read_bytes, skip_bytes, at_end};
  int width = 0, height = 0, channels = 0;
  ByteStream probe{data, size};
  if (!stbi_info_from_callbacks(&callbacks, &probe, &width, &height, &channels)) {
    *problem = std::string("damaged ") + (bmp ? "BMP" : "TGA") + " file (" + stbi_failure_reason() + ")";
    return false;
  }
  if (width <= 0 || height <= 0 || width > max_pixels / height) {
    *problem = "image " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the limit of " +
               std::to_string(max_pixels) + " pixels";
    return false;
  }
  // Grey + alpha and RGBA keep their alpha (a map_d or a cut-out); everything else is RGB.
  const int wanted = (channels == 2 || channels == 4) ? 4 : 3;
  ByteStream stream{data, size};
  int w = 0, h = 0, file_channels = 0;
  stbi_uc* pixels = stbi_load_from_callbacks(&callbacks, &stream, &w, &h, &file_channels, wanted);
  if (!pixels) {
    *problem = std::string("damaged ") + (bmp ? "BMP" : "TGA") + " file (" + stbi_failure_reason() + ")";
    return false;
  }
  if (stream.ran_out || w != width || h != height) {
    stbi_image_free(pixels);
    *problem = std::string("truncated ") + (bmp ? "BMP" : "TGA") + " file (it ends before its pixels do)";
    return false;
  }
  DisplayImage image;
  image.width = w;
  image.height = h;
  image.channels = wanted;
  try {
    image.pixels.assign(pixels, pixels + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * wanted);
  } catch (const std::bad_alloc&) {
    stbi_image_free(pixels);
    *problem = "out of memory";
    return false;
  }
  stbi_image_free(pixels);
  *out = std::move(image);
  return true;
}

bool read_texture_file(const std::string& path, DisplayImage* out, std::string* problem, std::int64_t max_pixels) {
  auto fail = [&](const std::string& why) {
    *problem = path + ": " + why;
    return false;
  };
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return fail(errno == ENOENT ? std::string("no such file") : std::string("cannot access: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) return fail("is a folder, not a texture file");

  std::ifstream file(path, std::ios::binary);
  std::uint8_t signature[8] = {};
  file.read(reinterpret_cast<char*>(signature), sizeof signature);
  if (!file && file.gcount() == 0 && st.st_size > 0) return fail("cannot be read");
  if (has_prefix(signature, static_cast<std::size_t>(file.gcount()), "\x89PNG\r\n\x1A\n", 8))
    return read_png(path, out, problem, max_pixels);

  // A JPEG of 64 Mi pixels is well under 1 GiB; anything larger is not a texture we would use.
  if (st.st_size > (std::int64_t{1} << 30)) return fail("file too large for a texture");
  std::vector<std::uint8_t> bytes;
  try {
    bytes.resize(static_cast<std::size_t>(st.st_size));
  } catch (const std::bad_alloc&) {
    return fail("out of memory");
  }
  file.clear();
  file.seekg(0);
  file.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<std::size_t>(file.gcount()) != bytes.size()) return fail("cannot be read");
  std::string why;
  if (!decode_texture_bytes(bytes.data(), bytes.size(), ends_with_tga(path), out, &why, max_pixels)) return fail(why);
  return true;
}

}  // namespace pfx::app
