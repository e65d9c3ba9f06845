// Reading OBJ and MTL text: blanks, line ends, tokens and numbers. Three line-end conventions are accepted (LF, CRLF, bare CR), and a backslash
// right before a line end joins the next physical line to this one (the OBJ line continuation).
#pragma once

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
  void skip_blanks() {
    for (;;) {
      if (is_blank(*p)) ++p;
      else if (continuation(p)) ++p, consume_line_end();
      else return;
    }
  }
  // Past the end of the statement: a comment and continued lines included.
  void skip_statement() {
    for (;;) {
      if (is_line_end(*p)) return consume_line_end();
      if (continuation(p)) ++p, consume_line_end();
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
  std::string rest_of_line();
};

// 10^0 .. 10^22 are exact in a double: a mantissa below 2^53 times or divided by one of them is
// rounded once, correctly (Clinger's fast path).
inline constexpr double kExactPowersOf10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                              1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Parses a decimal number: [+-] digits [. digits] [(e|E) [+-] digits], or [+-] . digits ...
// Accepts ".5", "1.", "+1", "1e-5", "-0". Returns false for anything else (including "nan",
// "inf", hex, a second '.', trailing letters), leaving *out alone. Rounds to double, then float.
bool parse_float(std::string_view token, float* out);
// Reads the longest number at p (before end) into *out and returns where it stopped, or nullptr
// when no number starts there. The caller checks what follows.
const char* parse_number_prefix(const char* p, const char* end, double* out);
// As parse_float, but keeps the double.
bool parse_double(std::string_view token, double* out);
// True when the token spells nan or inf/infinity in any case, with an optional sign.
bool is_non_finite_word(std::string_view token);

// Parses [+-] digits into an int64, rejecting empty, signs alone and more than 18 digits.
bool parse_integer(std::string_view token, int64_t* out);

// A token shown in a message: at most 40 bytes, control and non-ASCII bytes as \xNN.
std::string printable(std::string_view token);

}  // namespace pfx_obj
