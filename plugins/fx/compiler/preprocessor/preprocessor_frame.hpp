#pragma once
// One file being read: the preprocessor keeps a stack of these, the innermost #include on top.
#include <memory>
#include <optional>
#include <string>

#include "preprocessor.hpp"

namespace pfx::fx {

struct Preprocessor::Frame {
  std::string path;
  std::string text;  // the Lexer views it: never modified after the Lexer is made
  std::unique_ptr<Lexer> lexer;
  std::optional<Token> lookahead;  // the first token of the line after a directive
  std::size_t conditional_base = 0;
  long line_offset = 0;
};

}  // namespace pfx::fx
