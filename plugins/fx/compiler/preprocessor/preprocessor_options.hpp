#pragma once
// What the caller tells the preprocessor: where includes are looked up, extra definitions, and the
// values of the macros ReShade predefines (REFERENCE.md, "Macros").
#include <string>
#include <utility>
#include <vector>

namespace pfx::fx {

struct PreprocessorOptions {
  std::vector<std::string> include_folders;                  // searched after the including file's folder
  std::vector<std::pair<std::string, std::string>> defines;  // name, replacement text (as after #define NAME)

  int buffer_width = 1920;
  int buffer_height = 1080;
  int buffer_color_bit_depth = 8;
  int buffer_color_space = 1;  // 1 = sRGB
  // MAJOR * 10000 + MINOR * 100 + REVISION. 6.3.0: newer than every version test in the public
  // collections (the newest checked is "<= 50902").
  int reshade_version = 60300;
  // ReShade encodes OpenGL as 0x10000 | major << 12 | minor << 8 (REFERENCE.md: 0x14300 for 4.3);
  // pfx renders with OpenGL 4.5.
  int renderer = 0x14500;
  int vendor = 0;
  int device = 0;
  unsigned application = 0;  // ReShade: a hash of the executable's name; no meaning outside a game
  bool performance_mode = false;
};

}  // namespace pfx::fx
