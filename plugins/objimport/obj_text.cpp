#include "obj_text.hpp"

#include <cstdio>

namespace pfx_obj {

namespace {

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

bool equals_lower(std::string_view text, std::string_view word) {
  if (text.size() != word.size()) return false;
  for (size_t i = 0; i < text.size(); ++i)
    if (lower(text[i]) != word[i]) return false;
  return true;
}

}  // namespace

std::string LineCursor::rest_of_line() {
  std::string text;
  while (!is_line_end(*p)) {
    if (!continuation(p)) text += *p++;
    else ++p, consume_line_end(), text += ' ';
  }
  const size_t first = text.find_first_not_of(" \t\f\v"), last = text.find_last_not_of(" \t\f\v");
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

bool parse_double(std::string_view token, double* out) {
  double value;
  if (token.empty() || parse_number(token.data(), &value) != token.data() + token.size()) return false;
  *out = value;
  return true;
}

bool parse_float(std::string_view token, float* out) {
  double value;
  if (!parse_double(token, &value)) return false;
  *out = static_cast<float>(value);
  return true;
}

bool is_non_finite_word(std::string_view token) {
  if (!token.empty() && (token[0] == '+' || token[0] == '-')) token.remove_prefix(1);
  return equals_lower(token, "nan") || equals_lower(token, "inf") || equals_lower(token, "infinity") ||
         (token.size() > 3 && equals_lower(token.substr(0, 4), "nan("));
}

std::string printable(std::string_view token) {
  std::string text;
  for (size_t i = 0; i < token.size() && i < 40; ++i) {
    unsigned char c = static_cast<unsigned char>(token[i]);
    if (c < 0x20 || c >= 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      text += hex;
    } else {
      text += static_cast<char>(c);
    }
  }
  if (token.size() > 40) text += "...";
  return text;
}

}  // namespace pfx_obj
