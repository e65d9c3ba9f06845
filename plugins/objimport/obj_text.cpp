#include "obj_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace pfx_obj {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

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

const char* parse_number_prefix(const char* p, const char* end, double* out) {
  bool negative = false;
  if (p < end && (*p == '+' || *p == '-')) negative = *p++ == '-';
  const char* number_start = p;
  uint64_t mantissa = 0;
  int significant = 0;     // digits accumulated in mantissa (at most 19 fit in 64 bits)
  int exponent = 0;        // decimal exponent to apply to mantissa
  bool truncated = false;  // a digit did not fit: only the exact slow path may round
  bool any_digit = false;
  while (p < end && *p == '0') { ++p; any_digit = true; }  // leading zeros are not significant
  for (; p < end && is_digit(*p); ++p) {
    any_digit = true;
    if (significant < 19) { mantissa = mantissa * 10 + static_cast<uint64_t>(*p - '0'); ++significant; }
    else { ++exponent; truncated = true; }
  }
  if (p < end && *p == '.') {
    ++p;
    if (significant == 0)
      while (p < end && *p == '0') { ++p; --exponent; any_digit = true; }
    for (; p < end && is_digit(*p); ++p) {
      any_digit = true;
      if (significant < 19) { mantissa = mantissa * 10 + static_cast<uint64_t>(*p - '0'); ++significant; --exponent; }
      else truncated = true;
    }
  }
  if (!any_digit) return nullptr;
  if (p < end && (*p == 'e' || *p == 'E')) {
    ++p;
    bool exponent_negative = false;
    if (p < end && (*p == '+' || *p == '-')) exponent_negative = *p++ == '-';
    if (p >= end || !is_digit(*p)) return nullptr;
    int written = 0;
    for (; p < end && is_digit(*p); ++p)
      if (written < 100000) written = written * 10 + (*p - '0');
    exponent += exponent_negative ? -written : written;
  }
  double value;
  if (mantissa == 0) {
    value = 0.0;
  } else if (!truncated && mantissa < (uint64_t{1} << 53) && exponent >= -22 && exponent <= 22) {
    value = static_cast<double>(mantissa);
    value = exponent < 0 ? value / kExactPowersOf10[-exponent] : value * kExactPowersOf10[exponent];
  } else {
    // Rare: long mantissas or large exponents. from_chars is exact and locale-independent; it
    // takes no '+', which was stepped over above.
    auto result = std::from_chars(number_start, p, value);
    if (result.ec == std::errc::result_out_of_range) value = (exponent > 0) ? HUGE_VAL : 0.0;
    else if (result.ec != std::errc() || result.ptr != p) return nullptr;
  }
  *out = negative ? -value : value;
  return p;
}

bool parse_double(std::string_view token, double* out) {
  double value;
  const char* end = token.data() + token.size();
  if (parse_number_prefix(token.data(), end, &value) != end) return false;
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

bool parse_integer(std::string_view token, int64_t* out) {
  const char* p = token.data();
  const char* end = p + token.size();
  bool negative = false;
  if (p < end && (*p == '+' || *p == '-')) negative = *p++ == '-';
  if (p >= end || end - p > 18) return false;
  int64_t value = 0;
  for (; p < end; ++p) {
    if (!is_digit(*p)) return false;
    value = value * 10 + (*p - '0');
  }
  *out = negative ? -value : value;
  return true;
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
