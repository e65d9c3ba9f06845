#pragma once
// A libretro shader preset (.slangp, .glslp) as RetroArch reads one: the passes with their
// sampling, scale and framebuffer settings, the lookup textures, and the values a preset gives
// parameters. A preset built on another (`#reference "file"`, a "simple preset") takes its passes
// and textures from the root (the file the chain of first references ends at) and may change only
// parameter values and the files of the root's textures, later files winning: the loaded file over
// its second reference over its first over that one's own references. Paths are resolved relative
// to the file that names them. What RetroArch refuses (a missing pass, an unknown scale type) is an
// error naming the file and line; what it ignores (an unknown wrap mode, a boolean that is not one)
// is a warning and the default applies.
#include <optional>
#include <string>
#include <vector>

#include "preset_file.hpp"

namespace pfx::libretro {

enum class PresetFormat { kSlang, kGlsl };  // .slangp (Vulkan GLSL shaders) or .glslp (GLSL)
enum class ScaleType { kSource, kViewport, kAbsolute };
enum class WrapMode { kClampToBorder, kClampToEdge, kRepeat, kMirroredRepeat };

// One axis of a pass's output size: the source's size (the previous pass's, or the frame's for the
// first pass) or the viewport's times `factor`, or `pixels`.
struct AxisScale {
  ScaleType type = ScaleType::kSource;
  double factor = 1.0;
  int pixels = 0;
};

struct PresetPass {
  std::string shader;                 // the shader file, resolved
  TextPlace place;                    // where `shaderN` is
  std::optional<bool> filter_linear;  // how the pass samples its input; unset: the host's default
  WrapMode wrap = WrapMode::kClampToBorder;
  bool mipmap_input = false;  // mips made for the pass's input
  std::string alias;          // the name later passes sample the output by
  bool float_framebuffer = false, srgb_framebuffer = false;
  // Whether the preset gives a scale type: without one a pass renders at its source's size, and
  // the last pass at the viewport's.
  bool scaled = false;
  AxisScale x, y;
  unsigned frame_count_mod = 0;  // FrameCount is taken modulo this; 0: not
};

struct LookupTexture {
  std::string id;    // the sampler's name in the shaders
  std::string path;  // the image file, resolved
  std::optional<bool> linear;
  WrapMode wrap = WrapMode::kClampToBorder;
  bool mipmap = false;
};

struct Preset {
  std::string path;  // the file loaded
  std::string root;  // the file the passes come from (path when it references nothing)
  PresetFormat format = PresetFormat::kSlang;
  std::vector<PresetPass> passes;
  std::vector<LookupTexture> textures;
  // `feedback_pass` (the GLSL form): the pass whose last-frame output GLSL shaders sample as
  // `FeedbackTexture`; -1 for none. Slang shaders name theirs (PassFeedbackN) instead.
  int feedback_pass = -1;
  std::vector<std::string> warnings;

  // The value the preset gives parameter `id` (a `#pragma parameter` of its shaders), if any: the
  // last file's that gives a finite number.
  std::optional<double> parameter_value(const std::string& id) const;

  // The files whose entries give parameter values, in the order they apply (later wins).
  std::vector<PresetFile> layers;
};

// RetroArch's limits: passes and lookup textures in one preset, references followed.
constexpr int kMaxPasses = 64;
constexpr int kMaxLookupTextures = 64;
constexpr int kMaxReferenceDepth = 16;
constexpr int kMaxReferencedFiles = 256;  // files reached through references, each time counted

// The preset at `path`, its files read with `read` (read_text_file for files on disk). False with
// "file:line: why" in *error.
bool read_preset(const std::string& path, const TextReader& read, Preset* out, std::string* error);

// "source", "viewport"...: the preset's words, for messages and listings.
const char* scale_type_name(ScaleType type);
const char* wrap_mode_name(WrapMode mode);

}  // namespace pfx::libretro
