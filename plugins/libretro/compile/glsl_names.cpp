#include "glsl_names.hpp"

#include <algorithm>
#include <cctype>

namespace pfx::libretro {
namespace {

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// The number `text` ends with after `prefix` ("Pass12", "Pass" -> 12), or -1.
int digits_after(const std::string& text, const std::string& prefix) {
  if (text.size() <= prefix.size() || text.size() > prefix.size() + 4 || text.compare(0, prefix.size(), prefix) != 0)
    return -1;
  int number = 0;
  for (std::size_t i = prefix.size(); i < text.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) return -1;
    number = number * 10 + (text[i] - '0');
  }
  return number;
}

constexpr int kHistoryNames = 7;  // Prev, Prev1..Prev6

// The picture a `<base>` names in pass `pass`: its texture's semantic (the size's follows).
std::optional<Semantic> picture(const std::string& base, const SemanticContext& context, int feedback_pass) {
  const int pass = context.pass;
  if (base == "Orig") return Semantic{SemanticKind::kOriginal, 0};
  if (base == "Feedback") {
    if (feedback_pass < 0) return std::nullopt;
    return Semantic{SemanticKind::kPassFeedback, feedback_pass};
  }
  if (base == "Prev") return Semantic{SemanticKind::kOriginalHistory, 1};
  if (const int n = digits_after(base, "PassPrev"); n >= 1) {
    if (n == pass + 1 && pass > 0) return Semantic{SemanticKind::kOriginal, 0};
    if (n <= pass) return Semantic{SemanticKind::kPassOutput, pass - n};
    return std::nullopt;
  }
  if (const int n = digits_after(base, "Prev"); n >= 1 && n < kHistoryNames)
    return Semantic{SemanticKind::kOriginalHistory, n + 1};
  if (const int n = digits_after(base, "Pass"); n >= 1 && n <= pass) return Semantic{SemanticKind::kPassOutput, n - 1};
  for (int i = 0; i < pass && i < static_cast<int>(context.aliases.size()); ++i)
    if (!context.aliases[static_cast<std::size_t>(i)].empty() && context.aliases[static_cast<std::size_t>(i)] == base)
      return Semantic{SemanticKind::kPassOutput, i};
  return std::nullopt;
}

SemanticKind size_of(SemanticKind texture) {
  switch (texture) {
    case SemanticKind::kOriginal:
      return SemanticKind::kOriginalSize;
    case SemanticKind::kOriginalHistory:
      return SemanticKind::kOriginalHistorySize;
    case SemanticKind::kPassOutput:
      return SemanticKind::kPassOutputSize;
    default:
      return SemanticKind::kPassFeedbackSize;
  }
}

int index_in(const std::vector<std::string>& names, const std::string& name) {
  const auto at = std::find(names.begin(), names.end(), name);
  return at == names.end() ? -1 : static_cast<int>(at - names.begin());
}

}  // namespace

std::optional<GlslName> find_glsl_name(const std::string& name, const SemanticContext& context, int feedback_pass) {
  if (name == "MVPMatrix") return GlslName{{SemanticKind::kMvp, 0}, false};
  if (name == "OutputSize") return GlslName{{SemanticKind::kOutputSize, 0}, false};
  if (name == "InputSize" || name == "TextureSize") return GlslName{{SemanticKind::kSourceSize, 0}, false};
  if (name == "FrameCount") return GlslName{{SemanticKind::kFrameCount, 0}, false};
  if (name == "FrameDirection") return GlslName{{SemanticKind::kFrameDirection, 0}, false};
  if (name == "Texture") return GlslName{{SemanticKind::kSource, 0}, true};
  if (const int k = index_in(context.textures, name); k >= 0) return GlslName{{SemanticKind::kUser, k}, true};
  if (const int k = index_in(context.parameters, name); k >= 0) return GlslName{{SemanticKind::kParameter, k}, false};
  for (const char* suffix : {"TextureSize", "InputSize"})
    if (ends_with(name, suffix))
      if (const auto texture = picture(name.substr(0, name.size() - std::string(suffix).size()), context,
                                       feedback_pass))
        return GlslName{{size_of(texture->kind), texture->index}, false};
  if (ends_with(name, "Texture"))
    if (const auto texture = picture(name.substr(0, name.size() - 7), context, feedback_pass))
      return GlslName{*texture, true};
  return std::nullopt;
}

}  // namespace pfx::libretro
