// Whether an image file holds every byte its own structure says it has, found without decoding
// its pixels: what tells an output that was written whole from one cut short (a copy that
// stopped midway, a disk that filled). pfx-render writes its outputs under a temporary name and
// renames them when complete, so a file it wrote is whole whenever it exists; this check is for
// files something else put there, and costs a few small reads per file.
//   - a name ending in .png: the PNG signature first and the IEND chunk last.
//   - any other name, OpenEXR: the header reads, and in every scanline part every chunk's leader is readable and
//     its data ends inside the file. A tiled or deep part is decoded in full instead (slow, but
//     pfx-render never writes one).
// A file that is not what its name says, or cannot be opened: false.
#pragma once

#include <string>

namespace pfx::app {

bool image_file_is_whole(const std::string& path);

}  // namespace pfx::app
