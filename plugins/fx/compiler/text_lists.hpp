// Small text helpers the compiler's stages share: FX names of states and semantics compare
// without case, and messages list alternatives separated by commas.
#pragma once

#include <cctype>
#include <string>
#include <vector>

namespace pfx::fx {

inline bool same_ignoring_case(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

inline std::string joined(const std::vector<std::string>& parts) {
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? ", " : "") + parts[i];
  return text;
}

}  // namespace pfx::fx
