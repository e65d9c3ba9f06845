// Writes EXR files with any channel names, pixel types, sampling, tiling and parts through
// OpenEXR's own API, so tests can hand the reader the layouts users have (a lone Z, layers,
// luminance/chroma...) and compare what it reads with the values written.
#pragma once

#include <string>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfTiledOutputFile.h>
#include <ImfTiledOutputPart.h>

namespace pfx_test {

struct ExrChannel {
  std::string name;
  // One value per sample, row by row: (width / x_sampling) x (height / y_sampling) of them.
  std::vector<float> values;
  Imf::PixelType type = Imf::FLOAT;
  int x_sampling = 1;
  int y_sampling = 1;
};

struct ExrPart {
  std::string name;  // needed when a file has several parts
  std::vector<ExrChannel> channels;
  bool tiled = false;
};

namespace detail {

// Each channel's samples in its own pixel type: OpenEXR converts nothing on output.
struct Buffers {
  std::vector<std::vector<float>> floats;
  std::vector<std::vector<half>> halves;
  std::vector<std::vector<unsigned>> uints;
};

inline Imf::FrameBuffer frame_buffer(const std::vector<ExrChannel>& channels, int width, Buffers* buffers) {
  Imf::FrameBuffer fb;
  for (const ExrChannel& c : channels) {
    buffers->floats.push_back(c.values);
    buffers->halves.emplace_back(c.values.begin(), c.values.end());
    buffers->uints.emplace_back();
    for (float v : c.values) buffers->uints.back().push_back(static_cast<unsigned>(v));
    char* base = c.type == Imf::UINT   ? reinterpret_cast<char*>(buffers->uints.back().data())
                 : c.type == Imf::HALF ? reinterpret_cast<char*>(buffers->halves.back().data())
                                       : reinterpret_cast<char*>(buffers->floats.back().data());
    const std::size_t size = c.type == Imf::HALF ? sizeof(half) : 4;
    fb.insert(c.name, Imf::Slice(c.type, base, size, size * static_cast<std::size_t>(width / c.x_sampling),
                                 c.x_sampling, c.y_sampling));
  }
  return fb;
}

inline Imf::Header header_for(const ExrPart& part, int width, int height, bool multi_part) {
  Imf::Header header(width, height);
  for (const ExrChannel& c : part.channels) {
    header.channels().insert(c.name, Imf::Channel(c.type, c.x_sampling, c.y_sampling));
  }
  if (part.tiled) header.setTileDescription(Imf::TileDescription(4, 4, Imf::ONE_LEVEL));
  if (multi_part) {
    header.setName(part.name);
    header.setType(part.tiled ? Imf::TILEDIMAGE : Imf::SCANLINEIMAGE);
  }
  return header;
}

}  // namespace detail

// One part per entry; a single entry makes a single-part file.
inline void write_exr_parts(const std::string& path, int width, int height, const std::vector<ExrPart>& parts) {
  const bool multi = parts.size() > 1;
  std::vector<Imf::Header> headers;
  for (const ExrPart& part : parts) headers.push_back(detail::header_for(part, width, height, multi));
  if (!multi) {
    detail::Buffers buffers;
    const Imf::FrameBuffer fb = detail::frame_buffer(parts[0].channels, width, &buffers);
    if (parts[0].tiled) {
      Imf::TiledOutputFile file(path.c_str(), headers[0]);
      file.setFrameBuffer(fb);
      file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
    } else {
      Imf::OutputFile file(path.c_str(), headers[0]);
      file.setFrameBuffer(fb);
      file.writePixels(height);
    }
    return;
  }
  Imf::MultiPartOutputFile file(path.c_str(), headers.data(), static_cast<int>(headers.size()));
  for (std::size_t p = 0; p < parts.size(); ++p) {
    detail::Buffers buffers;
    const Imf::FrameBuffer fb = detail::frame_buffer(parts[p].channels, width, &buffers);
    if (parts[p].tiled) {
      Imf::TiledOutputPart part(file, static_cast<int>(p));
      part.setFrameBuffer(fb);
      part.writeTiles(0, part.numXTiles() - 1, 0, part.numYTiles() - 1);
    } else {
      Imf::OutputPart part(file, static_cast<int>(p));
      part.setFrameBuffer(fb);
      part.writePixels(height);
    }
  }
}

inline void write_exr_channels(const std::string& path, int width, int height, const std::vector<ExrChannel>& channels,
                               bool tiled = false) {
  write_exr_parts(path, width, height, {ExrPart{"", channels, tiled}});
}

}  // namespace pfx_test
