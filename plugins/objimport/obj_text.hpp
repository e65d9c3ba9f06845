// Reading OBJ and MTL text: blanks, line ends, tokens and numbers. Three line-end conventions are
// accepted (LF, CRLF, bare CR), and a backslash right before a line end joins the next physical line
// to this one (the OBJ line continuation).
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace pfx_obj {

inline bool is_line_end(char c) { return c == '\n' || c == '\r'; }
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

// A read position in text that ends with a line end which does not continue its line, with one
// more readable byte after it unless that line end is the last byte of a file: every scan stops at
// a line end, so none checks for the end of the text. It counts the physical line ends it steps
// over; a backslash right before a line end joins the next line to this one.
struct LineCursor {
  const char* p;
  const char* end;
  uint64_t line_ends = 0;

  static bool continuation(const char* q) { return q[0] == '\\' && is_line_end(q[1]); }
  static bool token_end(const char* q) { return is_blank(*q) || is_line_end(*q) || continuation(q); }
  bool at_statement_end() const { return is_line_end(*p) || *p == '#'; }  // a line end or a comment
  void consume_line_end() {  // CRLF counts once
    if (*p == '\r' && p + 1 < end && p[1] == '\n') ++p;
    ++p;
    ++line_ends;
  }
  void consume_continuation() { ++p; consume_line_end(); }  // the backslash and its line end
  void skip_blanks() {
    for (;;) {
      if (is_blank(*p)) ++p;
      else if (continuation(p)) consume_continuation();
      else return;
    }
  }
  // Past the end of the statement: a comment and continued lines included.
  void skip_statement() {
    for (;;) {
      if (is_line_end(*p)) return consume_line_end();
      if (continuation(p)) consume_continuation();
      else ++p;
    }
  }
  std::string_view token() {  // may be empty; blanks before it are not skipped
    const char* start = p;
    while (!token_end(p)) ++p;
    return {start, static_cast<size_t>(p - start)};
  }
  // The rest of the line (a '#' included: names may hold one), blanks trimmed at both ends, each
  // continuation one space.
  std::string rest_of_line() {
    std::string text;
    while (!is_line_end(*p)) {
      const bool joined = continuation(p);
      if (joined) consume_continuation();
      text += joined ? ' ' : *p++;
    }
    const size_t first = text.find_first_not_of(" \t\f\v"), last = text.find_last_not_of(" \t\f\v");
    return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  }
};

// 10^0 .. 10^22 are exact in a double: a mantissa below 2^53 times or divided by one of them is
// rounded once, correctly (Clinger's fast path).
inline constexpr double kExactPowersOf10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                              1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Whether c is a decimal digit, *value its value.
inline bool digit(char c, uint32_t* value) {
  *value = static_cast<uint32_t>(static_cast<unsigned char>(c)) - '0';
  return *value < 10;
}

// [start, end) read by std::from_chars (exact, locale-independent). Out of a double's range it is
// inf or 0: `place` (digits + exponent, less leading zeros) is the first digit's power of ten + 1.
[[gnu::cold, gnu::noinline]] inline bool parse_exactly(const char* start, const char* end, long place, double* value) {
  const auto result = std::from_chars(start, end, *value);
  if (result.ec != std::errc::result_out_of_range) return result.ec == std::errc() && result.ptr == end;
  for (const char* q = start; *q == '0' || *q == '.'; ++q) place -= *q == '0';  // leading zeros
  *value = place - 1 > 0 ? HUGE_VAL : 0.0;
  return true;
}

// Reads the decimal number at p — [+-] digits [. digits] [(e|E) [+-] digits], with a digit on at
// least one side of the point — into *out (rounded once, to double) and returns where it ends, or
// null when none starts there; the caller checks what follows. The text must end with a byte that
// is not part of a number (a line end, a blank, a NUL). Up to 19 digits with a small exponent take
// Clinger's fast path; the rest, parse_exactly.
[[gnu::always_inline]] inline const char* parse_number(const char* p, double* out) {
  const bool negative = *p == '-';
  if (*p == '-' || *p == '+') ++p;
  const char* const start = p;  // from_chars takes no sign
  uint64_t mantissa = 0;        // wraps past 19 digits, when it is not used
  uint32_t d;
  for (; digit(*p, &d); ++p) mantissa = mantissa * 10 + d;
  const char* const point = p;
  if (*p == '.')
    for (++p; digit(*p, &d); ++p) mantissa = mantissa * 10 + d;
  const long digits = (p - start) - (*point == '.');
  if (digits == 0) return nullptr;
  long exponent = *point == '.' ? point + 1 - p : 0;  // the value is mantissa * 10^exponent
  if (*p == 'e' || *p == 'E') {
    const bool below = p[1] == '-';
    p += p[1] == '-' || p[1] == '+' ? 2 : 1;
    if (!digit(*p, &d)) return nullptr;
    long written = 0;
    for (; digit(*p, &d); ++p) written = std::min(written * 10 + d, 100000L);
    exponent += below ? -written : written;
  }
  double value;
  if (digits < 20 && mantissa < (uint64_t{1} << 53) && exponent >= -22 && exponent <= 22) {
    value = exponent < 0 ? static_cast<double>(mantissa) / kExactPowersOf10[-exponent]
                         : static_cast<double>(mantissa) * kExactPowersOf10[exponent];
  } else if (!parse_exactly(start, p, digits + exponent, &value)) {
    return nullptr;
  }
  *out = negative ? -value : value;
  return p;
}

// A whole token as a number (as parse_number, so the byte after it is read); false for anything
// else (nan, inf, hex, a second '.', trailing letters), leaving *out alone.
inline bool parse_double(std::string_view token, double* out) {
  double value;
  if (token.empty() || parse_number(token.data(), &value) != token.data() + token.size()) return false;
  *out = value;
  return true;
}
// As parse_double, then rounded to float.
inline bool parse_float(std::string_view token, float* out) {
  double value;
  if (!parse_double(token, &value)) return false;
  *out = static_cast<float>(value);
  return true;
}

// True when the token spells nan, nan(...), inf or infinity in any case, with an optional sign.
inline bool is_non_finite_word(std::string_view token) {
  if (!token.empty() && (token[0] == '+' || token[0] == '-')) token.remove_prefix(1);
  std::string lower(token.substr(0, 9));
  for (char& c : lower) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower == "nan" || lower == "inf" || lower == "infinity" || (token.size() > 3 && lower.substr(0, 4) == "nan(");
}

// A token shown in a message: at most 40 bytes, control and non-ASCII bytes as \xNN.
inline std::string printable(std::string_view token) {
  std::string text;
  for (size_t i = 0; i < token.size() && i < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) text += static_cast<char>(c);
    else text += std::string("\\x") + "0123456789abcdef"[c >> 4] + "0123456789abcdef"[c & 15];
  }
  return token.size() > 40 ? text + "..." : text;
}

}  // namespace pfx_obj
