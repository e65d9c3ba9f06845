#include "swizzle.hpp"

#include <cctype>

namespace pfx::fx {
namespace {

bool vector_swizzle(const std::string& text, int size, std::vector<int>& components, std::string& error) {
  static const std::string sets[] = {"xyzw", "rgba"};
  int set_used = -1;
  for (char c : text) {
    int found = -1, set = -1;
    for (int s = 0; s < 2 && found < 0; ++s)
      if (sets[s].find(c) != std::string::npos) found = static_cast<int>(sets[s].find(c)), set = s;
    if (found < 0) return error = "'" + text + "' is not a swizzle", false;
    if (set_used >= 0 && set != set_used) return error = "swizzle '" + text + "' mixes xyzw and rgba", false;
    set_used = set;
    if (found >= size) return error = "swizzle '" + text + "' reaches past a " + std::to_string(size) + "-component value", false;
    components.push_back(found);
  }
  return true;
}

bool matrix_swizzle(const std::string& text, const Type& type, std::vector<int>& components, std::string& error) {
  // "_m01" counts from 0, "_12" from 1; groups may be chained: "_m00_m11".
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] != '_') return error = "'" + text + "' is not a matrix swizzle", false;
    bool zero_based = i + 1 < text.size() && text[i + 1] == 'm';
    std::size_t digits = i + (zero_based ? 2 : 1);
    if (digits + 2 > text.size() || !std::isdigit(static_cast<unsigned char>(text[digits])) ||
        !std::isdigit(static_cast<unsigned char>(text[digits + 1])))
      return error = "'" + text + "' is not a matrix swizzle", false;
    int row = text[digits] - '0' - (zero_based ? 0 : 1);
    int column = text[digits + 1] - '0' - (zero_based ? 0 : 1);
    if (row < 0 || column < 0 || row >= type.rows || column >= type.columns)
      return error = "'" + text + "' is outside a " + std::to_string(type.rows) + "x" + std::to_string(type.columns) + " matrix", false;
    components.push_back(row * 4 + column);
    i = digits + 2;
  }
  return true;
}

}  // namespace

bool parse_swizzle(const std::string& text, const Type& type, std::vector<int>& components, std::string& error) {
  components.clear();
  if (text.empty() || text.size() > 16) return error = "'" + text + "' is not a swizzle", false;
  bool ok = type.is_matrix() ? matrix_swizzle(text, type, components, error)
                             : vector_swizzle(text, type.is_vector() ? type.rows : 1, components, error);
  if (ok && components.size() > 4) return error = "swizzle '" + text + "' has more than 4 components", false;
  return ok;
}

}  // namespace pfx::fx
