// Writes the seed corpus of the EXR fuzz target (tests/fuzz/corpus/exr): small valid files that
// reach every branch of read_exr (half, float, uint, Z, Y, offset windows, tiles and mipmaps,
// several compressions, two parts, lone channels, layers, luminance/chroma with subsampled chroma). Build it against OpenEXR and run it in that folder:
//   c++ -std=c++17 make_exr_seeds.cpp $(pkg-config --cflags --libs OpenEXR) -o make_exr_seeds
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfRgbaFile.h>
#include <ImfTiledOutputFile.h>
#include <ImfTileDescription.h>

#include <string>
#include <vector>

using namespace Imf;
using Imath::Box2i;
using Imath::V2i;

namespace {

std::vector<float> ramp(int n, float scale) {
  std::vector<float> v(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<size_t>(i)] = scale * static_cast<float>(i % 17) - 1.0f;
  return v;
}

// A scanline file with the given channels (all of one pixel type), windows and compression.
void scanline(const std::string& name, const std::vector<std::string>& channels, PixelType type, Box2i display,
              Box2i data, Compression compression) {
  Header header(display, data);
  header.compression() = compression;
  const int w = data.max.x - data.min.x + 1, h = data.max.y - data.min.y + 1;
  std::vector<std::vector<float>> floats;
  std::vector<std::vector<unsigned>> uints;
  std::vector<std::vector<half>> halves;
  FrameBuffer fb;
  for (const std::string& c : channels) {
    header.channels().insert(c, Channel(type));
    floats.push_back(ramp(w * h, 0.7f));
    uints.push_back(std::vector<unsigned>(static_cast<size_t>(w * h), 7u));
    halves.push_back(std::vector<half>(floats.back().begin(), floats.back().end()));
  }
  for (size_t i = 0; i < channels.size(); ++i) {
    // The frame buffer's type matches the file's: OutputFile converts nothing.
    char* base = type == UINT   ? reinterpret_cast<char*>(uints[i].data())
                 : type == HALF ? reinterpret_cast<char*>(halves[i].data())
                                : reinterpret_cast<char*>(floats[i].data());
    const size_t xs = type == UINT ? sizeof(unsigned) : type == HALF ? sizeof(half) : sizeof(float);
    fb.insert(channels[i], Slice::Make(type, base, data, xs, xs * static_cast<size_t>(w)));
  }
  OutputFile file(name.c_str(), header);
  file.setFrameBuffer(fb);
  file.writePixels(h);
}

void tiled(const std::string& name) {
  const Box2i window(V2i(0, 0), V2i(8, 6));
  Header header(window, window);
  header.channels().insert("R", Channel(HALF));
  header.channels().insert("G", Channel(HALF));
  header.channels().insert("B", Channel(HALF));
  header.setTileDescription(TileDescription(4, 4, MIPMAP_LEVELS, ROUND_DOWN));
  header.compression() = ZIP_COMPRESSION;
  TiledOutputFile file(name.c_str(), header);
  for (int level = 0; level < file.numLevels(); ++level) {
    const int w = file.levelWidth(level), h = file.levelHeight(level);
    const std::vector<float> f = ramp(w * h, 0.5f);
    std::vector<half> v(f.begin(), f.end());
    FrameBuffer fb;
    const Box2i lw = file.dataWindowForLevel(level);
    for (const char* c : {"R", "G", "B"}) fb.insert(c, Slice::Make(HALF, v.data(), lw, sizeof(half), sizeof(half) * w));
    file.setFrameBuffer(fb);
    file.writeTiles(0, file.numXTiles(level) - 1, 0, file.numYTiles(level) - 1, level);
  }
}

void two_parts(const std::string& name) {
  const Box2i window(V2i(0, 0), V2i(2, 1));
  std::vector<Header> headers(2, Header(window, window));
  for (int p = 0; p < 2; ++p) {
    headers[p].setName(p == 0 ? "beauty" : "depth");
    headers[p].setType(SCANLINEIMAGE);
    for (const char* c : p == 0 ? std::vector<const char*>{"R", "G", "B"} : std::vector<const char*>{"Z"})
      headers[p].channels().insert(c, Channel(FLOAT));
  }
  MultiPartOutputFile file(name.c_str(), headers.data(), 2);
  for (int p = 0; p < 2; ++p) {
    std::vector<float> v = ramp(6, 1.5f);
    FrameBuffer fb;
    for (const char* c : p == 0 ? std::vector<const char*>{"R", "G", "B"} : std::vector<const char*>{"Z"})
      fb.insert(c, Slice::Make(FLOAT, v.data(), window, sizeof(float), sizeof(float) * 3));
    OutputPart part(file, p);
    part.setFrameBuffer(fb);
    part.writePixels(2);
  }
}

// OpenEXR's own luminance/chroma layout: Y full size, RY and BY every second pixel and row.
void luminance_chroma(const std::string& name) {
  const int w = 6, h = 4;
  std::vector<Rgba> pixels;
  for (int i = 0; i < w * h; ++i) pixels.emplace_back(0.1f * i, 0.5f, 1.0f - 0.04f * i, 1.0f);
  RgbaOutputFile file(name.c_str(), w, h, WRITE_YCA);
  file.setFrameBuffer(pixels.data(), 1, w);
  file.writePixels(h);
}

}  // namespace

int main() {
  const Box2i small(V2i(0, 0), V2i(3, 2));
  scanline("rgba_half_zip.exr", {"R", "G", "B", "A"}, HALF, small, small, ZIP_COMPRESSION);
  scanline("rgbz_float_none.exr", {"R", "G", "B", "Z"}, FLOAT, small, small, NO_COMPRESSION);
  scanline("rgb_uint_rle.exr", {"R", "G", "B"}, UINT, small, small, RLE_COMPRESSION);
  scanline("y_half_piz.exr", {"Y"}, HALF, small, small, PIZ_COMPRESSION);
  // The data window sticks out of the display window on two sides and misses it on the others.
  scanline("offset_windows.exr", {"R", "G", "B"}, HALF, Box2i(V2i(0, 0), V2i(5, 4)), Box2i(V2i(-2, 1), V2i(3, 6)),
           ZIPS_COMPRESSION);
  scanline("tall_b44.exr", {"R", "G", "B"}, HALF, Box2i(V2i(0, 0), V2i(1, 40)), Box2i(V2i(0, 0), V2i(1, 40)),
           B44_COMPRESSION);
  scanline("z_only_float.exr", {"Z"}, FLOAT, small, small, ZIP_COMPRESSION);
  scanline("r_only_half.exr", {"R"}, HALF, small, small, NO_COMPRESSION);
  scanline("g_only_uint.exr", {"G"}, UINT, small, small, RLE_COMPRESSION);
  scanline("layers.exr", {"diffuse.R", "diffuse.G", "diffuse.B", "N.X", "N.Y", "N.Z", "depth.Z", "specular.R"}, HALF,
           small, small, PIZ_COMPRESSION);
  luminance_chroma("yca_subsampled.exr");
  tiled("tiled_mipmap.exr");
  two_parts("two_parts.exr");
  return 0;
}
