#pragma once
// What a preset's chain needs from frame to frame, worked out once its passes are compiled (no
// GL): each pass's size for a frame, its framebuffer format, whether it draws straight into the
// host's output, whether its output of the last frame is read (feedback: two textures) or read
// with mipmaps, and how many frames of the original picture are kept (OriginalHistoryN). The rules
// are RetroArch's glcore and Vulkan drivers':
//   - a pass without a scale type renders at its source's size; the last one at the viewport's,
//     straight into the output;
//   - a last pass with a scale type renders into a texture of its own, and a blit stretches it over
//     the output (RetroArch appends the same stock pass); pfx leaves the blit out where it would
//     copy texel for texel (the viewport's size, not sRGB);
//   - sizes are rounded half away from zero (roundf) and kept within 1..16384 (RetroArch keeps no
//     bound; a zero-sized or larger framebuffer cannot be made in GL);
//   - only a pass with a scale type takes srgb_framebufferN (R8G8B8A8_SRGB, winning) or
//     float_framebufferN (R16G16B16A16_SFLOAT) over its `#pragma format`; R8G8B8A8_UNORM otherwise.
// pfx also gives the last pass a texture of its own when a pass reads its feedback (RetroArch
// would refuse such a preset).
#include <string>
#include <vector>

#include "preset.hpp"
#include "slang_reflection.hpp"

namespace pfx::libretro {

struct PixelSize {
  int width = 1, height = 1;
  bool operator==(const PixelSize& o) const { return width == o.width && height == o.height; }
  bool operator!=(const PixelSize& o) const { return !(*this == o); }
};

constexpr int kMaxTextureSide = 16384;

struct PassPlan {
  std::string format = "R8G8B8A8_UNORM";  // the framebuffer's, a `#pragma format` name
  bool to_output = false;                 // draws straight into the host's output
  bool feedback = false;   // PassFeedback (or <alias>Feedback) of it is read: two textures, swapped each frame
  bool mipmapped = false;  // the next pass has mipmap_input: a full mip chain, made after the pass runs
};

struct ChainPlan {
  std::vector<PassPlan> passes;
  int history = 0;                  // OriginalHistory frames read beyond this one (the largest N)
  bool original_mipmapped = false;  // pass 0 has mipmap_input: the original picture gets mips
  bool finish = false;              // the last pass renders into its own texture; a blit follows
};

// The plan of a compiled chain: `formats` holds each pass's `#pragma format` ("" for none),
// `passes` its reflection.
ChainPlan plan_chain(const Preset& preset, const std::vector<std::string>& formats,
                     const std::vector<PassInterface>& passes);

// Each pass's output size for a picture of `original` (the content, OriginalSize) shown in
// `viewport` (the host's frame, FinalViewportSize). The last pass of a chain that draws straight
// into the output is at the viewport's size whatever its scale.
std::vector<PixelSize> pass_sizes(const Preset& preset, const ChainPlan& plan, PixelSize original, PixelSize viewport);

// A format with integer texels (sampled only as integers, never filtered).
bool is_integer_format(const std::string& format);

}  // namespace pfx::libretro
