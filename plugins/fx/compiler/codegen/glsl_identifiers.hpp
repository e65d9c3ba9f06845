#pragma once
// FX names made into GLSL identifiers. Every user name gets a prefix naming its kind (G_ global,
// F_ function, S_ struct, l_ local, m_ member), so no FX name can collide with a GLSL keyword or
// built-in ("input", "sample", "texture", "main") or with the generated code's own names.
#include <string>

namespace pfx::fx {

// "A::b" -> "A_ns_b"; characters GLSL does not take in a name become '_'; "__" becomes "_1" (GLSL
// reserves identifiers with two underscores in a row).
inline std::string glsl_safe(const std::string& name) {
  std::string out;
  for (std::size_t i = 0; i < name.size(); ++i) {
    char c = name[i];
    if (c == ':' && i + 1 < name.size() && name[i + 1] == ':') {
      if (!out.empty()) out += "_ns_";
      ++i;
      continue;
    }
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    char next = ok ? c : '_';
    if (next == '_' && !out.empty() && out.back() == '_') out += '1';
    else out += next;
  }
  return out;
}

}  // namespace pfx::fx
