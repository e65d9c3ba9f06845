#pragma once
// What a name in a slang shader's uniform block, push constants or samplers stands for, as
// libretro's slang format defines them: the built-in values (MVP, OutputSize, FrameCount...), the
// sizes and textures of the frame, the passes and the lookup textures (Original, Source,
// OriginalHistoryN, PassOutputN, PassFeedbackN, UserN, each with its `...Size`; a pass's alias and
// `<alias>Feedback`; a lookup texture's id), and the preset's parameters by their ids. Indexed
// sizes put the number after "Size" (`PassOutputSize2`). A name that is none of these is an error,
// as in RetroArch: the runtime would have nothing to give it.
#include <optional>
#include <string>
#include <vector>

namespace pfx::libretro {

enum class SemanticKind {
  // Values
  kMvp,                // mat4
  kOutputSize,         // vec4 (w, h, 1/w, 1/h), as every size
  kFinalViewportSize,  // vec4
  kFrameCount,         // uint, after the pass's frame_count_mod
  kFrameDirection,     // int: 1, or -1 while rewinding
  kFrameTimeDelta,     // uint, microseconds
  kOriginalFps,        // float
  kOriginalAspect,     // float
  kOriginalAspectRotated,
  kRotation,             // uint, quarter turns
  kTotalSubFrames,       // uint
  kCurrentSubFrame,      // uint
  // RetroArch's HDR pipeline, which pfx does not have: its values for an SDR display.
  kHdrMode,         // uint: 0 off, 1 HDR10, 2 scRGB
  kBrightnessNits,  // float: paper white
  kScanlines,       // float: the HDR pipeline's own scanlines on (1) or off
  kSubpixelLayout,  // uint: those scanlines' subpixel order
  kExpandGamut,     // uint: colour boost, 0 none
  kInverseTonemap,  // float: on (1) or off
  kHdr10,           // float: HDR10 conversion on (1) or off
  kParameter,            // float; index into the preset's parameters
  kOriginalSize,         // vec4; the frame's
  kSourceSize,           // vec4; the pass's input
  kOriginalHistorySize,  // vec4; index frames back
  kPassOutputSize,       // vec4; index: the pass
  kPassFeedbackSize,     // vec4
  kUserSize,             // vec4; index: the lookup texture
  // Textures
  kOriginal,
  kSource,
  kOriginalHistory,  // index frames back (0 is Original)
  kPassOutput,       // this frame's output of pass `index`
  kPassFeedback,     // the last frame's output of pass `index`
  kUser,             // lookup texture `index`
};

enum class SemanticType { kFloat, kInt, kUint, kVec4, kMat4, kTexture };

struct Semantic {
  SemanticKind kind = SemanticKind::kMvp;
  int index = 0;
};

// What the names of one pass may refer to.
struct SemanticContext {
  int pass = 0;                         // the pass whose shader is read
  std::vector<std::string> aliases;     // per pass: its alias (or `#pragma name`), "" for none
  std::vector<std::string> textures;    // lookup texture ids, in the preset's order
  std::vector<std::string> parameters;  // parameter ids
};

// The semantic of uniform or sampler `name` of the pass, or nothing with the reason in *error.
// `texture` says whether the name is a sampler's.
std::optional<Semantic> find_semantic(const std::string& name, bool texture, const SemanticContext& context,
                                      std::string* error);

// The type the format gives the semantic's value.
SemanticType semantic_type(SemanticKind kind);
const char* semantic_type_name(SemanticType type);

}  // namespace pfx::libretro
