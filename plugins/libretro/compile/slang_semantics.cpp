#include "slang_semantics.hpp"

#include <cctype>

namespace pfx::libretro {
namespace {

// RetroArch keeps 128 frames of history at most.
constexpr int kMaxHistory = 128;

struct Named {
  const char* name;
  SemanticKind kind;
};

constexpr Named kValues[] = {
    {"MVP", SemanticKind::kMvp},
    {"OutputSize", SemanticKind::kOutputSize},
    {"FinalViewportSize", SemanticKind::kFinalViewportSize},
    {"FrameCount", SemanticKind::kFrameCount},
    {"FrameDirection", SemanticKind::kFrameDirection},
    {"FrameTimeDelta", SemanticKind::kFrameTimeDelta},
    {"OriginalFPS", SemanticKind::kOriginalFps},
    {"OriginalAspect", SemanticKind::kOriginalAspect},
    {"OriginalAspectRotated", SemanticKind::kOriginalAspectRotated},
    {"Rotation", SemanticKind::kRotation},
    {"TotalSubFrames", SemanticKind::kTotalSubFrames},
    {"CurrentSubFrame", SemanticKind::kCurrentSubFrame},
    {"HDRMode", SemanticKind::kHdrMode},
    {"BrightnessNits", SemanticKind::kBrightnessNits},
    {"Scanlines", SemanticKind::kScanlines},
    {"SubpixelLayout", SemanticKind::kSubpixelLayout},
    {"ExpandGamut", SemanticKind::kExpandGamut},
    {"InverseTonemap", SemanticKind::kInverseTonemap},
    {"HDR10", SemanticKind::kHdr10},
    {"OriginalSize", SemanticKind::kOriginalSize},
    {"SourceSize", SemanticKind::kSourceSize},
};

// Names with a number after them; the texture's, then its size's.
struct Indexed {
  const char* texture;
  SemanticKind texture_kind;
  const char* size;
  SemanticKind size_kind;
};

constexpr Indexed kIndexed[] = {
    {"OriginalHistory", SemanticKind::kOriginalHistory, "OriginalHistorySize", SemanticKind::kOriginalHistorySize},
    {"PassOutput", SemanticKind::kPassOutput, "PassOutputSize", SemanticKind::kPassOutputSize},
    {"PassFeedback", SemanticKind::kPassFeedback, "PassFeedbackSize", SemanticKind::kPassFeedbackSize},
    {"User", SemanticKind::kUser, "UserSize", SemanticKind::kUserSize},
};

// The number `name` ends with after `prefix`, when the rest is all digits.
std::optional<int> number_after(const std::string& name, const std::string& prefix) {
  if (name.size() <= prefix.size() || name.size() > prefix.size() + 6 || name.compare(0, prefix.size(), prefix) != 0)
    return std::nullopt;
  int number = 0;
  for (std::size_t i = prefix.size(); i < name.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return std::nullopt;
    number = number * 10 + (name[i] - '0');
  }
  return number;
}

// The names the preset makes: parameters, pass aliases and their feedback, lookup textures.
std::optional<Semantic> preset_name(const std::string& name, const SemanticContext& context) {
  for (std::size_t i = 0; i < context.parameters.size(); ++i)
    if (name == context.parameters[i]) return Semantic{SemanticKind::kParameter, static_cast<int>(i)};
  for (std::size_t i = 0; i < context.aliases.size(); ++i) {
    const std::string& alias = context.aliases[i];
    if (alias.empty()) continue;
    const int pass = static_cast<int>(i);
    if (name == alias) return Semantic{SemanticKind::kPassOutput, pass};
    if (name == alias + "Size") return Semantic{SemanticKind::kPassOutputSize, pass};
    if (name == alias + "Feedback") return Semantic{SemanticKind::kPassFeedback, pass};
    if (name == alias + "FeedbackSize") return Semantic{SemanticKind::kPassFeedbackSize, pass};
  }
  for (std::size_t i = 0; i < context.textures.size(); ++i) {
    if (name == context.textures[i]) return Semantic{SemanticKind::kUser, static_cast<int>(i)};
    if (name == context.textures[i] + "Size") return Semantic{SemanticKind::kUserSize, static_cast<int>(i)};
  }
  return std::nullopt;
}

std::optional<Semantic> built_in(const std::string& name) {
  if (name == "Original") return Semantic{SemanticKind::kOriginal, 0};
  if (name == "Source") return Semantic{SemanticKind::kSource, 0};
  for (const Named& value : kValues)
    if (name == value.name) return Semantic{value.kind, 0};
  // The size names first: "PassOutputSize2" also starts with "PassOutput".
  for (const Indexed& indexed : kIndexed)
    if (const auto n = number_after(name, indexed.size)) return Semantic{indexed.size_kind, *n};
  for (const Indexed& indexed : kIndexed)
    if (const auto n = number_after(name, indexed.texture)) return Semantic{indexed.texture_kind, *n};
  return std::nullopt;
}

// "" when `semantic` may be read by the pass, else why not.
std::string check_reach(const std::string& name, const Semantic& semantic, const SemanticContext& context) {
  const int passes = static_cast<int>(context.aliases.size());
  switch (semantic.kind) {
    case SemanticKind::kPassOutput:
    case SemanticKind::kPassOutputSize:
      if (semantic.index >= context.pass)
        return "'" + name + "' reads pass " + std::to_string(semantic.index) + ", which has not run when pass " +
               std::to_string(context.pass) + " runs (PassFeedback" + std::to_string(semantic.index) +
               " is its last frame's output)";
      return "";
    case SemanticKind::kPassFeedback:
    case SemanticKind::kPassFeedbackSize:
      return semantic.index < passes ? ""
                                     : "'" + name + "' names pass " + std::to_string(semantic.index) +
                                           " of a preset of " + std::to_string(passes) + " passes";
    case SemanticKind::kUser:
    case SemanticKind::kUserSize:
      return semantic.index < static_cast<int>(context.textures.size())
                 ? ""
                 : "'" + name + "' names lookup texture " + std::to_string(semantic.index) + " of " +
                       std::to_string(context.textures.size());
    case SemanticKind::kOriginalHistory:
    case SemanticKind::kOriginalHistorySize:
      return semantic.index < kMaxHistory
                 ? ""
                 : "'" + name + "' reaches back more than " + std::to_string(kMaxHistory) + " frames";
    default:
      return "";
  }
}

}  // namespace

std::optional<Semantic> find_semantic(const std::string& name, bool texture, const SemanticContext& context,
                                      std::string* error) {
  std::optional<Semantic> semantic = preset_name(name, context);
  if (!semantic) semantic = built_in(name);
  if (!semantic)
    return *error = "'" + name +
                    "' is not a name the slang format gives a value (a built-in, a parameter, a pass's alias or a "
                    "lookup texture)",
           std::nullopt;
  if ((semantic_type(semantic->kind) == SemanticType::kTexture) != texture)
    return *error = "'" + name + (texture ? "' is a value, not a texture" : "' is a texture, not a value"),
           std::nullopt;
  const std::string why = check_reach(name, *semantic, context);
  if (!why.empty()) return *error = why, std::nullopt;
  return semantic;
}

SemanticType semantic_type(SemanticKind kind) {
  switch (kind) {
    case SemanticKind::kMvp:
      return SemanticType::kMat4;
    case SemanticKind::kFrameCount:
    case SemanticKind::kFrameTimeDelta:
    case SemanticKind::kRotation:
    case SemanticKind::kTotalSubFrames:
    case SemanticKind::kCurrentSubFrame:
    case SemanticKind::kHdrMode:
    case SemanticKind::kSubpixelLayout:
    case SemanticKind::kExpandGamut:
      return SemanticType::kUint;
    case SemanticKind::kFrameDirection:
      return SemanticType::kInt;
    case SemanticKind::kOriginalFps:
    case SemanticKind::kOriginalAspect:
    case SemanticKind::kOriginalAspectRotated:
    case SemanticKind::kBrightnessNits:
    case SemanticKind::kScanlines:
    case SemanticKind::kInverseTonemap:
    case SemanticKind::kHdr10:
    case SemanticKind::kParameter:
      return SemanticType::kFloat;
    case SemanticKind::kOriginal:
    case SemanticKind::kSource:
    case SemanticKind::kOriginalHistory:
    case SemanticKind::kPassOutput:
    case SemanticKind::kPassFeedback:
    case SemanticKind::kUser:
      return SemanticType::kTexture;
    default:
      return SemanticType::kVec4;  // the sizes
  }
}

const char* semantic_type_name(SemanticType type) {
  switch (type) {
    case SemanticType::kFloat:
      return "float";
    case SemanticType::kInt:
      return "int";
    case SemanticType::kUint:
      return "uint";
    case SemanticType::kVec4:
      return "vec4";
    case SemanticType::kMat4:
      return "mat4";
    case SemanticType::kTexture:
      return "sampler2D";
  }
  return "?";
}

}  // namespace pfx::libretro
