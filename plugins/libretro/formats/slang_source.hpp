#pragma once
// A libretro slang shader (.slang): Vulkan GLSL 4.50 in one file for both stages, read as
// RetroArch reads it before compiling. The first line is `#version`; `#include "file"` at the
// start of a line splices the file in (relative to the file that includes it, with no include
// guard; `#pragma include_optional` skips a missing one); `#pragma stage vertex|fragment` sends the
// lines that follow to that stage (lines before the first go to both); `#pragma name`,
// `#pragma format` and `#pragma parameter ID "Label" initial minimum maximum [step]` describe the
// pass and leave the code. Each stage's code carries `#line N "file"` directives
// (GL_GOOGLE_cpp_style_line_directive), so the compiler's messages name the file and line written.
#include <string>
#include <vector>

#include "preset_file.hpp"

namespace pfx::libretro {

struct SlangParameter {
  std::string id, label;
  double initial = 0, minimum = 0, maximum = 0, step = 0;  // step: 0.1 of the range when not written
  TextPlace place;
};

struct SlangSource {
  std::string path;
  std::string vertex, fragment;  // each stage's code
  std::string name;              // `#pragma name`: what later passes may sample this pass's output by
  std::string format;            // `#pragma format`: a Vulkan format name without VK_FORMAT_; "" unset
  std::vector<SlangParameter> parameters;
  std::vector<std::string> files;  // the shader and every file it includes, once each
};

// Include depth, files spliced in, and the most code one shader may expand to (includes without
// guards can grow without end).
constexpr int kMaxSlangIncludeDepth = 32;
constexpr int kMaxSlangIncludes = 4096;
constexpr std::size_t kMaxSlangSourceBytes = 16u << 20;

// False with "file:line: why" in *error.
bool read_slang(const std::string& path, const TextReader& read, SlangSource* out, std::string* error);

// The text after `#pragma parameter`: `ID "Label" initial minimum maximum [step]`, read as
// RetroArch reads it (with sscanf): the numbers one after the other, each as long as it reads as one
// ("0.0.001" is 0.0 then .001), what follows the last ignored (collections write comments there).
// Returns "" or why not. Both shader forms write parameters so.
std::string parse_parameter(const std::string& text, SlangParameter* out);

// The formats `#pragma format` may name, as RetroArch lists them.
bool is_slang_format(const std::string& name);

}  // namespace pfx::libretro
