#include <exception>
#include <fstream>
#include <new>
#include <vector>

#include <Imath/half.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#include "atomic_file.hpp"
#include "exr_io.hpp"

namespace pfx::app {
namespace {

bool write_exr_file(const std::string& temp_path, const Image& img, ExrPixelType type,
                    std::string* reason) {
  const Imf::PixelType colour_type = type == ExrPixelType::Half ? Imf::HALF : Imf::FLOAT;
  Imf::Header header(img.width, img.height);
  for (const char* name : {"R", "G", "B", "A"}) header.channels().insert(name, Imf::Channel(colour_type));
  // Depth in half would lose centimetres beyond a few metres; it always goes out as float.
  if (img.has_depth()) header.channels().insert("Z", Imf::Channel(Imf::FLOAT));

  // OpenEXR writes only the pixel type the file declares, so half data is converted here, with
  // Imath's round-to-nearest (the same conversion readers of the file would assume).
  std::vector<half> halves;
  char* rgba = nullptr;
  std::size_t xs = 0;
  if (type == ExrPixelType::Half) {
    halves.resize(img.rgba.size());
    for (std::size_t i = 0; i < img.rgba.size(); ++i) halves[i] = half(img.rgba[i]);
    rgba = reinterpret_cast<char*>(halves.data());
    xs = 4 * sizeof(half);
  } else {
    // Slices take non-const pointers for both directions; writing only reads them.
    rgba = reinterpret_cast<char*>(const_cast<float*>(img.rgba.data()));
    xs = 4 * sizeof(float);
  }
  const std::size_t ys = xs * static_cast<std::size_t>(img.width);
  const std::size_t cs = xs / 4;
  Imf::FrameBuffer fb;
  fb.insert("R", Imf::Slice(colour_type, rgba + 0 * cs, xs, ys));
  fb.insert("G", Imf::Slice(colour_type, rgba + 1 * cs, xs, ys));
  fb.insert("B", Imf::Slice(colour_type, rgba + 2 * cs, xs, ys));
  fb.insert("A", Imf::Slice(colour_type, rgba + 3 * cs, xs, ys));
  if (img.has_depth()) {
    char* depth = reinterpret_cast<char*>(const_cast<float*>(img.depth.data()));
    fb.insert("Z", Imf::Slice(Imf::FLOAT, depth, sizeof(float),
                              sizeof(float) * static_cast<std::size_t>(img.width)));
  }

  // Our own stream, because OutputFile writes its offset table in its destructor and swallows
  // errors there; checking the stream afterwards catches a full disk at that last step.
  std::ofstream os(temp_path, std::ios::binary | std::ios::trunc);
  if (!os) {
    *reason = "cannot create the temporary file " + temp_path;
    return false;
  }
  {
    Imf::StdOFStream stream(os, temp_path.c_str());
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(fb);
    file.writePixels(img.height);
  }
  os.close();
  if (!os) {
    *reason = "writing the file failed (disk full?)";
    return false;
  }
  return true;
}

}  // namespace

bool write_exr(const std::string& path, const Image& img, ExrPixelType type, std::string* error) {
  if (img.width <= 0 || img.height <= 0 || !img.is_consistent()) {
    if (error) {
      *error = "cannot write " + path + ": the image is empty or its pixel data does not match " +
               std::to_string(img.width) + "x" + std::to_string(img.height);
    }
    return false;
  }
  return write_atomically(
      path,
      [&](const std::string& temp, std::string* reason) {
        try {
          return write_exr_file(temp, img, type, reason);
        } catch (const std::bad_alloc&) {
          *reason = "out of memory";
        } catch (const std::exception& e) {
          *reason = e.what();
        }
        return false;
      },
      error);
}

}  // namespace pfx::app
