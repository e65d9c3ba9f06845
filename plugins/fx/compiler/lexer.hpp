#pragma once
// Splits source text into tokens with their file:line:column. Backslash-newline continuations are
// removed on the fly, so a location is still the one in the file as written.
#include <string_view>

#include "diagnostics.hpp"
#include "token.hpp"

namespace pfx::fx {

class Lexer {
 public:
  Lexer(std::string_view source, std::uint32_t file, Diagnostics& diagnostics);

  Token next();
  // Lines told by #line shift the numbering of what follows.
  void set_line_offset(long offset) { line_offset_ = offset; }
  long physical_line() const { return line_; }
  void set_file(std::uint32_t file) { file_ = file; }
  // Inside skipped #if groups an unterminated string is not an error (the text may be prose).
  void set_quiet(bool quiet) { quiet_ = quiet; }

 private:
  char peek(std::size_t ahead = 0);
  char take();
  void skip_continuations();
  // Returns false on an unterminated block comment (reported).
  bool skip_space_and_comments(bool& saw_space, bool& saw_newline);
  void lex_number(Token& token);
  void lex_string(Token& token);
  void lex_punct(Token& token);

  std::string_view source_;
  std::size_t position_ = 0;
  long line_ = 1;
  long column_ = 1;
  long line_offset_ = 0;
  std::uint32_t file_;
  bool at_line_start_ = true;
  bool quiet_ = false;
  Diagnostics& diagnostics_;
};

// All tokens of a text (for macro pasting and tests); the kEnd token is not included.
TokenList lex_all(std::string_view source, std::uint32_t file, Diagnostics& diagnostics);

}  // namespace pfx::fx
