// Reading OBJ and MTL text: blanks, line ends, tokens and numbers, over a byte range that is never
// read past its end. Three line-end conventions are accepted (LF, CRLF, bare CR), and a backslash
// right before a line end joins the next physical line to this one (the OBJ line continuation).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace pfx_obj {

inline bool is_line_end(char c) { return c == '\n' || c == '\r'; }
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

// A read position in [p, end) that counts the physical line ends it steps over.
struct Cursor {
  const char* p;
  const char* end;
  uint64_t line_ends = 0;  // line ends consumed so far (continuations included)

  bool at_end() const { return p >= end; }
  // A backslash followed by a line end (LF, CRLF or CR): the next line continues this one.
  bool at_continuation() const { return p < end && *p == '\\' && p + 1 < end && is_line_end(p[1]); }
  // Steps over one line end (CRLF counts once).
  void consume_line_end() {
    if (*p == '\r' && p + 1 < end && p[1] == '\n') ++p;
    ++p;
    ++line_ends;
  }
  // Skips blanks and continuations.
  void skip_blanks() {
    while (p < end) {
      if (is_blank(*p)) ++p;
      else if (at_continuation()) { ++p; consume_line_end(); }
      else break;
    }
  }
  // True at the end of the logical line: a line end, the end of the text, or a '#' comment.
  bool at_statement_end() const { return p >= end || is_line_end(*p) || *p == '#'; }
  // True where a token stops: a blank, a line end, a continuation, or the end.
  bool at_token_end() const { return p >= end || is_blank(*p) || is_line_end(*p) || at_continuation(); }
  // Moves past the end of the logical line (comments and continued lines included).
  void skip_statement() {
    while (p < end) {
      if (at_continuation()) { ++p; consume_line_end(); continue; }
      if (is_line_end(*p)) { consume_line_end(); return; }
      ++p;
    }
  }
  // The next token (may be empty at a statement end). Does not skip blanks before it.
  std::string_view token() {
    const char* start = p;
    while (!at_token_end()) ++p;
    return std::string_view(start, static_cast<size_t>(p - start));
  }
  // The rest of the logical line up to a line end (not a '#': names may contain it), blanks
  // trimmed at both ends and continuations turned into one space.
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
