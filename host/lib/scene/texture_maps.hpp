// Texture files as a scene's maps: the decoded file (texture_file.hpp) turned into the linear
// values the G-buffer samples, by what the map means.
#pragma once

#include <string>

#include "image.hpp"
#include "scene.hpp"

namespace pfx::app {

enum class MapKind {
  color,   // map_Kd, map_Ke: sRGB codes decoded to linear RGB; A as stored
  alpha,   // map_d: A is the file's alpha, or its first channel when it has no alpha
  normal,  // norm: a tangent-space normal map, RGB kept as stored
  bump,    // bump / map_Bump: a grey height map becomes a normal map; a coloured one is taken
           // for a normal map, as many models ship them under this name
};

// The image as a texture of that kind, rows flipped to bottom first.
Texture make_map(const DisplayImage& image, MapKind kind);

// Reads and converts; false with *problem ("PATH: REASON") when the file cannot be read.
bool load_map(const std::string& path, MapKind kind, Texture* out, std::string* problem);

}  // namespace pfx::app
